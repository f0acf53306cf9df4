#include "output/history_resume.hpp"

#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "output/text_file.hpp"

namespace camouflet {

std::optional<double> cut_history_before(const std::filesystem::path& path, double restart_time) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos) return std::nullopt;
  std::size_t keep = header_end + 1;
  double last = -std::numeric_limits<double>::infinity();
  for (std::size_t line = keep; line < text.size();) {
    const std::size_t end = text.find('\n', line);
    if (end == std::string::npos) break;  // incomplete row
    const double time = std::strtod(text.c_str() + line, nullptr);
    if (!(time < restart_time)) break;  // rows are in time order
    last = time;
    keep = end + 1;
    line = end + 1;
  }
  if (keep != text.size()) write_file_atomically(path, std::string_view(text).substr(0, keep));
  return last;
}

}  // namespace camouflet
