// The wall-bending study behind docs/buried-structure.md, "Hourglass form in
// the structure" (long label): the simply supported strip of
// test_wall_bending.cpp (L/t = 10) with 1, 2, 4 and 8 one-point quads through
// its thickness, under the viscous form and the stiffness form at
// coefficients 0.05 to 0.5; prints the period over the Timoshenko beam's.
// Checked: the mesh converges to the beam (8 cells, stiffness 0.1, within
// 1 %), and one cell through the thickness under the viscous form has no
// bending stiffness at all (the strip does not swing back within 3 periods).
// The same strip of hexes (one cell wide between two symmetry planes: the
// `coarse3d` walls are one hex thick) is printed too: the 3-D stiffness form
// scales differently (k = kappa rho c^2 l / 4).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "beam_vibration.hpp"
#include "common/verification.hpp"

using namespace camouflet;

namespace {

template <int D>
void study(const std::string& element) {
  struct Row {
    HourglassForm form;
    double kappa;
  };
  const Row rows[] = {{HourglassForm::viscous, 0.1},   {HourglassForm::stiffness, 0.05},
                      {HourglassForm::stiffness, 0.1}, {HourglassForm::stiffness, 0.2},
                      {HourglassForm::stiffness, 0.3}, {HourglassForm::stiffness, 0.5}};
  std::printf(
      "%s\n| form | coefficient | 1 cell | 2 cells | 4 cells | 8 cells |\n|---|---|---|---|---|---|\n",
      element.c_str());
  for (const Row& row : rows) {
    std::string line =
        fmt::format("| {} | {} |", row.form == HourglassForm::viscous ? "viscous" : "stiffness", row.kappa);
    for (int n : {1, 2, 4, 8}) {
      test::StripSpec s;
      s.cells_through = n;
      s.hourglass = {row.form, row.kappa};
      const test::StripVibration v = test::vibrate_strip<D>(s);
      const bool swings = v.crossings >= 3;
      line += swings ? fmt::format(" {:.4f} |", v.period / v.reference_period)
                     : std::string(" no swing in 3 periods |");
      if (n == 1 && row.form == HourglassForm::viscous) {
        test::record_check(
            "Wall bending (L/t = 10), 1 one-point " + element + " through, viscous hourglass form",
            "no bending stiffness (one layer: all bending is hourglass mode)",
            swings ? fmt::format("swings, period ratio {:.3f}", v.period / v.reference_period)
                   : "does not swing back in 3 beam periods",
            !swings);
        EXPECT_FALSE(swings);
      }
      if (n == 8 && row.form == HourglassForm::stiffness && row.kappa == 0.1)
        test::verify({"Wall bending (L/t = 10, 8 one-point " + element +
                          "s through), stiffness hourglass form 0.1: first-mode period",
                      "Timoshenko beam, simply supported (plane strain, shear coefficient 5/6)",
                      1e3 * v.reference_period, 1e3 * v.period, 0.01, true, "ms"});
    }
    std::printf("%s\n", line.c_str());
  }
}

TEST(WallBendingStudy, PeriodOverTheBeamsByCellsFormAndCoefficient) {
  study<2>("quad");
}

TEST(WallBendingStudy, HexStripPeriodOverTheBeams) {
  study<3>("hex");
}

}  // namespace
