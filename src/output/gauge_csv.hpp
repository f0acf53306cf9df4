#pragma once
// One CSV per gauge group: `time_s`, then one column per gauge and quantity
// named `<gauge>.<quantity>`. Flushed after every row, so a killed run keeps
// every complete row written so far (output is never lost).
#include <filesystem>
#include <string>
#include <vector>

#include "output/text_file.hpp"

namespace camouflet {

class GaugeCsv {
 public:
  GaugeCsv(const std::filesystem::path& path, const std::vector<std::string>& gauge_names,
           const std::vector<std::string>& quantities);
  // Reopens a complete CSV (header and whole rows) to append rows: restarts.
  explicit GaugeCsv(const std::filesystem::path& path);
  // values[g * quantities + q]
  void write_row(double time, const std::vector<double>& values);
  void close() { file_.close(); }

 private:
  TextFile file_;
  std::string line_;
};

}  // namespace camouflet
