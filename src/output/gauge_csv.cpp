#include "output/gauge_csv.hpp"

#include <fmt/format.h>

namespace camouflet {

GaugeCsv::GaugeCsv(const std::filesystem::path& path, const std::vector<std::string>& gauge_names,
                   const std::vector<std::string>& quantities)
    : file_(path) {
  std::string header = "time_s";
  for (const auto& g : gauge_names)
    for (const auto& q : quantities) header += fmt::format(",{}.{}", g, q);
  header += '\n';
  file_.write(header);
  file_.flush();
}

GaugeCsv::GaugeCsv(const std::filesystem::path& path) : file_(path, TextFile::Mode::append) {}

void GaugeCsv::write_row(double time, const std::vector<double>& values) {
  line_.clear();
  // 17 significant digits: the row reproduces the double exactly (restart checks compare bit for bit).
  fmt::format_to(std::back_inserter(line_), "{:.17g}", time);
  for (double v : values) fmt::format_to(std::back_inserter(line_), ",{:.17g}", v);
  line_ += '\n';
  file_.write(line_);
  file_.flush();
}

}  // namespace camouflet
