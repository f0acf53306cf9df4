// Long verification (label `long`): the coarse paper case
// (cases/wang2005/coarse.toml) run through the executable. Issue 8, "what it
// must show" 2: group-B peak stresses within a factor 1.5 of the TM 5-855-1
// band (Functions 1 and 2, f = 0.6; Wang et al. 2005 eqs. 38-39) over the
// gauges' Z range, the energy error below 2 %, and the run reaching its end.
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

TEST(Wang2005Coarse, GroupBWithinTm5Band) {
  const fs::path out = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "wang2005_coarse";
  fs::remove_all(out);
  const fs::path case_file = fs::path(CAMOUFLET_SOURCE_DIR) / "cases/wang2005/coarse.toml";
  const auto r = test::run_camouflet("run '" + case_file.string() + "' -o '" + out.string() + "' --quiet");
  ASSERT_EQ(r.status, 0) << r.output;

  std::ifstream csv(out / "group_B.csv");
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> names;
  for (std::stringstream hs(line); std::getline(hs, line, ',');) names.push_back(line);
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> row;
    std::stringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  ASSERT_FALSE(rows.empty());
  const auto col = [&](const std::string& n) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin());
  };
  const double w3 = std::cbrt(100.0), depth = 0.5, f = 0.6;
  for (int k = 1;; ++k) {
    const std::string g = "B" + std::to_string(k);
    if (col(g + ".stress_xx") >= names.size()) break;
    const double r0 = rows[0][col(g + ".position_x")], z0 = rows[0][col(g + ".position_y")];
    const double R = std::hypot(r0, z0 + depth), nr = r0 / R, nz = (z0 + depth) / R;
    double peak = 0.0;  // radial stress, compression positive, MPa
    for (const auto& row : rows) {
      const double s = row[col(g + ".stress_xx")] * nr * nr + row[col(g + ".stress_yy")] * nz * nz +
                       2.0 * row[col(g + ".stress_xy")] * nr * nz;
      peak = std::max(peak, -s / 1e6);
    }
    const double Z = R / w3;
    const double lower = f * 15.0 * std::pow(Z, -2.5) / 1.5, upper = f * 22.0 * std::pow(Z, -2.0) * 1.5;
    // Record as the distance (in log) outside the widened band: 0 inside.
    const double outside = peak < lower   ? std::log(lower / peak)
                           : peak > upper ? std::log(peak / upper)
                                          : 0.0;
    test::verify({"Wang 2005 coarse case: group-B peak stress at Z = " + std::to_string(Z).substr(0, 5) +
                      " (log distance outside the TM-5 band x1.5)",
                  "TM 5-855-1 Functions 1-2, f = 0.6", 0.0, outside, 1e-12, false, "-"});
  }
}

}  // namespace
}  // namespace camouflet
