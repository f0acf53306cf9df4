// `camouflet run` of the main-job example (cases/examples/elastic_column.toml)
// through the executable: the output folder is complete, and the gauge on the
// column records the plane P-wave stress sigma_yy = -rho c_p v of the pulse.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/verification.hpp"
#include "run_executable.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(EndToEnd, ElasticColumnExample) {
  const fs::path out = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "elastic_column";
  fs::remove_all(out);
  const fs::path case_file = fs::path(CAMOUFLET_SOURCE_DIR) / "cases/examples/elastic_column.toml";
  const auto r =
      test::run_camouflet("run '" + case_file.string() + "' -o '" + out.string() + "' --threads 1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("results in"), std::string::npos) << r.output;

  for (const char* f : {"case.toml", "summary.json", "axis.csv", "fields.pvd", "fields_0000.vtu"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_EQ(slurp(out / "case.toml"), slurp(case_file));
  const std::string summary = slurp(out / "summary.json");
  EXPECT_NE(summary.find("\"stop_reason\": \"end time reached\""), std::string::npos)
      << summary.substr(0, 600);
  EXPECT_NE(summary.find("\"axis\""), std::string::npos);

  // Snapshots at 0, 2, 4 ... 12 ms.
  const std::string pvd = slurp(out / "fields.pvd");
  EXPECT_EQ(std::count(pvd.begin(), pvd.end(), '\n') - 5, 7) << pvd;

  // Peak compressive stress at the middle gauge (y = 5 m), where the front has sharpened.
  std::ifstream csv(out / "axis.csv");
  std::string header, line;
  std::getline(csv, header);
  std::vector<std::string> names;
  for (std::stringstream hs(header); std::getline(hs, line, ',');) names.push_back(line);
  const auto column = std::find(names.begin(), names.end(), "p3.stress_yy") - names.begin();
  ASSERT_LT(static_cast<std::size_t>(column), names.size()) << header;
  double peak = 0.0;
  int rows = 0;
  while (std::getline(csv, line)) {
    std::stringstream ls(line);
    std::string cell;
    for (long c = 0; c <= column; ++c) std::getline(ls, cell, ',');
    peak = std::min(peak, std::stod(cell));
    ++rows;
  }
  EXPECT_GT(rows, 200);  // every 50 us (or every cycle when dt is longer) over 12 ms
  const double rho = 2000.0, k = 6.6667e8, g = 4.0e8, v = 1.0;
  const double c_p = std::sqrt((k + 4.0 * g / 3.0) / rho);
  // The peak includes the overshoot behind the front: 2 % at y = 5 m on this 0.05 m mesh.
  test::verify({"Example elastic column: peak gauge stress at y = 5 m", "-rho c_p v (plane P-wave)",
                -rho * c_p * v, peak, 0.03, true, "Pa"});
}

}  // namespace
}  // namespace camouflet

namespace camouflet {
namespace {

TEST(EndToEnd, CheckPrintsSummaryAndExitsZero) {
  const auto case_file = std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "cases/examples/elastic_column.toml";
  const auto r = test::run_camouflet("check '" + case_file.string() + "'");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(": OK"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2211 nodes, 2000 elements"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("soil (linear, elastic, 2000 kg/m^3)"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace camouflet

namespace camouflet {
namespace {

// Exit code 1: a run stopped by a numerical check (here the energy-balance
// limit, set absurdly tight) still leaves its summary, marked failed.
TEST(EndToEnd, NumericalFailureExitsOne) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output";
  fs::create_directories(dir);
  std::string text = slurp(fs::path(CAMOUFLET_SOURCE_DIR) / "cases/examples/elastic_column.toml");
  text.replace(text.find("cfl = 0.6"), 9, "cfl = 0.6\nenergy_error_limit = 1e-300");
  const fs::path case_file = dir / "energy_limit.toml";
  std::ofstream(case_file) << text;
  const fs::path out = dir / "energy_limit";
  fs::remove_all(out);
  const auto r =
      test::run_camouflet("run --quiet --threads 1 '" + case_file.string() + "' -o '" + out.string() + "'");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(r.output.rfind("error: numerical failure: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("energy"), std::string::npos) << r.output;
  EXPECT_NE(slurp(out / "summary.json").find("\"failed\": true"), std::string::npos);
}

// Exit code 3: an output folder that cannot be created.
TEST(EndToEnd, UnwritableOutputExitsThree) {
  const auto case_file = std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "cases/examples/elastic_column.toml";
  const auto r =
      test::run_camouflet("run --quiet '" + case_file.string() + "' -o /proc/camouflet-no-such-dir/x");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_EQ(r.output.rfind("error: I/O failure: ", 0), 0u) << r.output;
}

}  // namespace
}  // namespace camouflet

namespace camouflet {
namespace {

// Exit code 130: an interrupted run ends at once, keeping complete CSV rows.
TEST(EndToEnd, InterruptExits130WithCompleteRows) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output";
  fs::create_directories(dir);
  std::string text = slurp(fs::path(CAMOUFLET_SOURCE_DIR) / "cases/examples/elastic_column.toml");
  text.replace(text.find("end_time = 0.012"), 16, "end_time = 100.0");  // far longer than the test waits
  const fs::path case_file = dir / "interrupted.toml";
  std::ofstream(case_file) << text;
  const fs::path out = dir / "interrupted";
  fs::remove_all(out);
  const auto r = test::run_camouflet_raw("timeout --preserve-status -s INT 2 '" +
                                         std::string(CAMOUFLET_EXECUTABLE) + "' run --quiet --threads 1 '" +
                                         case_file.string() + "' -o '" + out.string() + "'");
  EXPECT_EQ(r.status, 130) << r.output;
  EXPECT_NE(r.output.find("interrupted"), std::string::npos) << r.output;
  std::ifstream csv(out / "axis.csv");
  std::string header, line;
  std::getline(csv, header);
  const auto columns = std::count(header.begin(), header.end(), ',');
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << "row " << rows;
  }
  EXPECT_GT(rows, 1);
}

}  // namespace
}  // namespace camouflet
