// `camouflet compare OUTDIR...` (scripts/compare_runs.py): the headline
// results of several runs side by side, checked on synthetic output folders
// whose peak stresses, TM-5 band positions and group ordering are known by
// construction, and its bad-input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "case/run_executable.hpp"
#include "common/verification.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

// A soil gauge CSV: gauge k at range ranges[k] from the charge centre (0, 0), along the 45° line down (group
// B) or along the ground (group A), under isotropic compression rising linearly to peaks[k] and back.
void write_group(const fs::path& path, char letter, const std::vector<double>& ranges,
                 const std::vector<double>& peaks) {
  std::ofstream o(path);
  o << "time_s";
  for (std::size_t k = 0; k < ranges.size(); ++k)
    for (const char* q : {"position_x", "position_y", "stress_xx", "stress_yy", "stress_xy"})
      o << ',' << letter << k + 1 << '.' << q;
  o << '\n';
  const double c = letter == 'B' ? std::sqrt(0.5) : 1.0;
  for (int step = 0; step <= 4; ++step) {
    const double shape = step <= 2 ? step / 2.0 : (4 - step) / 2.0;
    o << step * 1e-3;
    for (std::size_t k = 0; k < ranges.size(); ++k) {
      const double p = peaks[k] * 1e6 * shape;  // Pa, compression
      o << ',' << ranges[k] * c << ',' << -ranges[k] * (letter == 'B' ? c : 0.0) << ',' << -p << ',' << -p
        << ",0";
    }
    o << '\n';
  }
}

fs::path synthetic_run(const std::string& name, double b1_peak) {
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "compare" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  // 1 kg at the ground surface: Z = R.
  std::ofstream(dir / "case.toml") << "# generator: charge_mass_kg=1 burst_depth_m=0 standoff_m=2 "
                                      "box_length_m=1 box_height_m=0.5 wall_thickness_m=0.1 top_depth_m=0\n";
  std::ofstream(dir / "summary.json") << "{\"final_time_s\": 0.004, \"stop_reason\": \"end time reached\", "
                                         "\"cycles\": 1234, \"wall_seconds\": 5.5, "
                                         "\"energy_J\": {\"relative_error\": 0.012}}\n";
  // TM-5 band (f = 0.6) widened by 1.5: Z = 1: 6 .. 19.8 MPa; Z = 2: 1.061 .. 4.95 MPa.
  write_group(dir / "group_B.csv", 'B', {1.0, 2.0}, {b1_peak, 0.5});
  write_group(dir / "group_A.csv", 'A', {1.0, 2.0}, {5.0, 0.6});
  return dir;
}

// The CSV of `camouflet compare` as {quantity: [value per run]}.
std::map<std::string, std::vector<std::string>> read_table(const fs::path& csv) {
  std::map<std::string, std::vector<std::string>> out;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char ch : line) {
      if (ch == '"')
        quoted = !quoted;
      else if (ch == ',' && !quoted) {
        cells.push_back(cell);
        cell.clear();
      } else
        cell += ch;
    }
    cells.push_back(cell);
    out[cells[0]] = std::vector<std::string>(cells.begin() + 1, cells.end());
  }
  return out;
}

std::string row_starting(const std::map<std::string, std::vector<std::string>>& t, const std::string& prefix,
                         std::size_t run) {
  for (const auto& [q, v] : t)
    if (q.rfind(prefix, 0) == 0) return v.at(run);
  ADD_FAILURE() << "no row " << prefix;
  return "";
}

TEST(Compare, SideBySideHeadlinePeaksOfSyntheticRuns) {
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy'").status != 0)
    GTEST_SKIP() << "python3-numpy is not installed";
  const fs::path coarse = synthetic_run("coarse", 10.0), fine = synthetic_run("fine", 25.0);
  const fs::path csv = coarse.parent_path() / "table.csv";
  const auto r = test::run_camouflet("compare '" + coarse.string() + "' '" + fine.string() +
                                     "' --label coarse --label fine --csv '" + csv.string() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("| quantity | coarse | fine |"), std::string::npos) << r.output;
  // B2 (0.5 MPa at Z = 2) lies below the band's lower edge 1.061 MPa: shown with its ratio.
  EXPECT_NE(r.output.find("0.5 (0.47×)"), std::string::npos) << r.output;
  // fine's B1 (25 MPa at Z = 1) lies above the upper edge 19.8 MPa.
  EXPECT_NE(r.output.find("25 (1.26×)"), std::string::npos) << r.output;
  const auto t = read_table(csv);
  test::verify({"camouflet compare: peak radial stress of a synthetic gauge on the 45-degree line",
                "the prescribed isotropic compression (by construction)", 10.0,
                std::stod(row_starting(t, "B1 peak radial stress", 0)), 1e-9, false, "MPa"});
  EXPECT_DOUBLE_EQ(std::stod(row_starting(t, "B1 peak radial stress", 1)), 25.0);
  EXPECT_EQ(row_starting(t, "group B within", 0), "1 of 2");
  EXPECT_EQ(row_starting(t, "group B within", 1), "0 of 2");
  EXPECT_EQ(row_starting(t, "group A below group B", 0), "1 of 2");  // A1 < B1, A2 > B2
  EXPECT_EQ(row_starting(t, "cycles", 1), "1234");
  EXPECT_DOUBLE_EQ(std::stod(row_starting(t, "energy balance error", 0)), 1.2);
}

// Three runs whose B1 peak follows f(h) = 20 - 8 h^2 MPa with h = 1, 1/2, 1/4 (12, 18, 19.5 MPa, exact
// in the gauge CSVs' six digits): the observed order is 2 and the Richardson estimate 20 MPa; a quantity that
// goes up and down is named so, not given an order.
TEST(Compare, RefinementGivesTheObservedOrderAndTheRichardsonEstimate) {
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy'").status != 0)
    GTEST_SKIP() << "python3-numpy is not installed";
  std::vector<fs::path> runs;
  for (const double h : {1.0, 0.5, 0.25}) runs.push_back(synthetic_run("h" + std::to_string(h), 20.0 - 8.0 * h * h));
  // An oscillating energy error: 1.2 %, 0.6 %, 0.9 %.
  std::ofstream(runs[1] / "summary.json") << "{\"final_time_s\": 0.004, \"stop_reason\": \"end time reached\", "
                                             "\"cycles\": 2468, \"wall_seconds\": 11, "
                                             "\"energy_J\": {\"relative_error\": 0.006}}\n";
  std::ofstream(runs[2] / "summary.json") << "{\"final_time_s\": 0.004, \"stop_reason\": \"end time reached\", "
                                             "\"cycles\": 4936, \"wall_seconds\": 22, "
                                             "\"energy_J\": {\"relative_error\": 0.009}}\n";
  const fs::path csv = runs[0].parent_path() / "convergence.csv";
  const auto r = test::run_camouflet("compare '" + runs[0].string() + "' '" + runs[1].string() + "' '" +
                                     runs[2].string() + "' --refinement 2 --csv '" + csv.string() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("observed order | Richardson estimate |"), std::string::npos) << r.output;
  const auto t = read_table(csv);
  const auto& b1 = [&] {
    for (const auto& [q, v] : t)
      if (q.rfind("B1 peak radial stress", 0) == 0) return v;
    return std::vector<std::string>{};
  }();
  ASSERT_EQ(b1.size(), 5u);
  test::verify({"camouflet compare --refinement: observed order of a quantity f = 20 - 8 h^2",
                "the exponent of the synthetic runs (by construction)", 2.0, std::stod(b1[3]), 1e-9, false, "-"});
  test::verify({"camouflet compare --refinement: Richardson estimate of f = 20 - 8 h^2 MPa",
                "f(0) of the synthetic runs (by construction)", 20.0, std::stod(b1[4]), 1e-9, false, "MPa"});
  EXPECT_EQ(row_starting(t, "energy balance error", 3), "oscillates");
  const auto two = test::run_camouflet("compare '" + runs[0].string() + "' '" + runs[1].string() + "' --refinement 2");
  EXPECT_EQ(two.status, 2) << two.output;
  EXPECT_NE(two.output.find("--refinement: needs three output folders"), std::string::npos) << two.output;
}

TEST(Compare, BadInputNamesTheFolderOrOption) {
  const fs::path coarse = synthetic_run("bad_input", 10.0);
  const auto missing = test::run_camouflet("compare '" + coarse.string() + "' /nonexistent/run");
  EXPECT_EQ(missing.status, 2) << missing.output;
  EXPECT_NE(missing.output.find("/nonexistent/run: no summary.json"), std::string::npos) << missing.output;
  const auto labels = test::run_camouflet("compare '" + coarse.string() + "' --label a --label b");
  EXPECT_EQ(labels.status, 2) << labels.output;
  EXPECT_NE(labels.output.find("--label: 2 labels for 1 output folders"), std::string::npos) << labels.output;
}

}  // namespace
}  // namespace camouflet
