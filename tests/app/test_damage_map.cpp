// The damage map of `camouflet report` (scripts/run_metrics.py box_section,
// front_wall_halves; scripts/damage_map.py) on synthetic box sections, r-z and
// 3-D (cases in tests/app/damage_map_cases.py): the front wall's damage is its
// depth over the height, so its lower half has mean 0.75 and its upper half
// 0.25 by construction; the other members carry 0.9, every node is lifted by
// 30 mm (the split must use reference positions) and in 3-D the cell layer off
// the symmetry plane carries 1 (the section must leave it out).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "case/run_executable.hpp"
#include "common/verification.hpp"

namespace {

namespace fs = std::filesystem;

struct Case {
  double expected = 0.0, computed = 0.0;
};

std::map<std::string, Case> run_cases(const fs::path& dir) {
  const std::string script = std::string(CAMOUFLET_SOURCE_DIR) + "/tests/app/damage_map_cases.py";
  const auto r = camouflet::test::run_camouflet_raw("/usr/bin/python3 '" + script + "' '" + dir.string() + "'");
  EXPECT_EQ(r.status, 0) << r.output;
  std::map<std::string, Case> out;
  // Line by line: a library warning on stderr (matplotlib's cache folder) is not a case.
  std::istringstream in(r.output);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string name, rest;
    Case c;
    if (fields >> name >> c.expected >> c.computed && !(fields >> rest)) out[name] = c;
  }
  return out;
}

TEST(DamageMap, FrontWallLowerAndUpperHalvesOfASyntheticSection) {
  if (camouflet::test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy, matplotlib'").status != 0)
    GTEST_SKIP() << "python3-numpy or python3-matplotlib is not installed (scripts/setup.sh installs them)";
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "damage_map";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto cases = run_cases(dir);
  ASSERT_EQ(cases.size(), 12u);
  using camouflet::test::verify;
  for (const std::string geometry : {"rz", "3d"}) {
    const std::string where = geometry == "rz" ? "r-z section" : "3-D, symmetry-plane section";
    const auto& lower = cases.at(geometry + "_front_wall_lower_mean");
    verify({"Box damage map, " + where + ": front wall's lower-half mean",
            "D = depth / height by construction: 0.75", lower.expected, lower.computed, 1e-9, false, "-"});
    const auto& upper = cases.at(geometry + "_front_wall_upper_mean");
    verify({"Box damage map, " + where + ": front wall's upper-half mean",
            "D = depth / height by construction: 0.25", upper.expected, upper.computed, 1e-9, false, "-"});
    const auto& whole = cases.at(geometry + "_front_wall_mean");
    EXPECT_NEAR(whole.computed, whole.expected, 1e-9) << geometry;
    const auto& count = cases.at(geometry + "_section_elements");
    EXPECT_EQ(count.computed, count.expected) << geometry << ": elements in the section";
    EXPECT_DOUBLE_EQ(cases.at(geometry + "_section_time_s").computed, 0.07) << geometry;
    EXPECT_EQ(cases.at(geometry + "_caption_names_time").computed, 1.0) << geometry;
    EXPECT_TRUE(fs::exists(dir / geometry / "fig14_damage.png")) << geometry;
  }
}

}  // namespace
