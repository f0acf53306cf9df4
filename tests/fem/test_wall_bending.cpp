// Bending of a wall with one-point quads: a simply supported elastic
// strip, L/t = 10 (a 1 m span of the box's 100 mm wall), 2 and 4 cells through
// its thickness (the `coarse` and `default` cases), vibrating in its first
// bending mode; its period against the Timoshenko beam's under each hourglass
// form and coefficient (beam_vibration.hpp; docs/buried-structure.md,
// "Hourglass form in the structure").
//
// What one-point quads give: each cell layer's strain is that at its
// mid-line, so without hourglass stiffness a strip of n layers keeps
// (1 - 1/n^2) of the bending stiffness E'I (the rest is the quads' hourglass
// mode) and its period is 1/sqrt(1 - 1/n^2) times the beam's: +15.5 % for
// n = 2, +3.3 % for n = 4. The viscous form adds no stiffness, so it must
// match that prediction; the stiffness form gives part of the rest back in
// proportion to its coefficient (measured: n = 2 +12.1 % at 0.05, +9.5 % at
// 0.1; n = 4 +2.6 %, +2.1 %).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "beam_vibration.hpp"
#include "common/verification.hpp"

using namespace camouflet;

namespace {

test::StripVibration strip(int cells, HourglassForm form, double kappa) {
  test::StripSpec s;
  s.cells_through = cells;
  s.hourglass = {form, kappa};
  const test::StripVibration v = test::vibrate_strip(s);
  EXPECT_GE(v.crossings, 5) << "the strip must vibrate through a few periods";
  return v;
}

TEST(WallBending, ViscousFormKeepsOnlyTheLayersBendingStiffness) {
  for (int n : {2, 4})
    for (double kappa : {0.05, 0.1}) {
      const test::StripVibration v = strip(n, HourglassForm::viscous, kappa);
      const double expected = v.reference_period / std::sqrt(1.0 - 1.0 / (n * n));
      test::verify({fmt::format("Wall bending (L/t = 10, {} one-point quads through), viscous hourglass form "
                                "{}: first-mode period",
                                n, kappa),
                    "Timoshenko / sqrt(1 - 1/n^2) (layer-wise bending, no hourglass stiffness)",
                    1e3 * expected, 1e3 * v.period, 0.01, true, "ms"});
    }
}

TEST(WallBending, StiffnessFormPeriodAgainstTheBeam) {
  // Tolerances from the measured errors (see the header), tight enough that
  // the form's added stiffness must be there: at n = 2 the viscous form's
  // period is 15 % long.
  const struct {
    int n;
    double kappa, tolerance;
  } cases[] = {{2, 0.05, 0.13}, {2, 0.1, 0.10}, {4, 0.05, 0.03}, {4, 0.1, 0.025}};
  for (const auto& c : cases) {
    const test::StripVibration v = strip(c.n, HourglassForm::stiffness, c.kappa);
    test::verify(
        {fmt::format("Wall bending (L/t = 10, {} one-point quads through), stiffness hourglass form {}: "
                     "first-mode period",
                     c.n, c.kappa),
         "Timoshenko beam, simply supported (plane strain, shear coefficient 5/6)", 1e3 * v.reference_period,
         1e3 * v.period, c.tolerance, true, "ms"});
    // Stiffer than the layers alone: shorter than the viscous form's period.
    EXPECT_LT(v.period, v.reference_period / std::sqrt(1.0 - 1.0 / (c.n * c.n)) * 0.995);
  }
}

}  // namespace
