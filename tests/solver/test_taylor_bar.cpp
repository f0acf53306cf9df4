// Taylor cylinder impact of 4340 steel (Rc 30) against a rigid wall with the
// Johnson-Cook set of Johnson & Cook 1983 (preset steel_4340_jc1983), compared
// with their cylinder-impact test: L0 = 25.4 mm, D0 = 7.62 mm, V = 208 m/s,
// final length L/L0 = 0.885, foot diameter 11.1 mm (Johnson & Cook 1983;
// re-evaluated by Johnson & Holmquist 1988, J. Appl. Phys. 64, 3901).
// Required: final length within 2 %, foot diameter within 5 %.
// Sources, mesh convergence and the other tests: docs/theory/explosive-and-steel.md §5.2
// and tests/solver/long_taylor_bar.cpp.
#include <gtest/gtest.h>

#include "common/verification.hpp"
#include "solver/taylor_bar.hpp"

using namespace camouflet;

TEST(TaylorBar, Steel4340At208MetresPerSecondAgainstJohnsonCook1983Test) {
  // 6 cells across the radius (0.64 mm); 12 cells change L by 0.08 % and the
  // foot by 0.06 % (long_taylor_bar.cpp). The rod has stopped by 60 us.
  const test::TaylorSpec spec{"steel_4340_jc1983", 3.81e-3, 25.4e-3, 208.0, 6, 80e-6, 60e-6};
  const test::TaylorResult r = test::run_taylor_bar(spec);
  test::verify(
      {"Taylor impact, 4340 steel (JC 1983 constants), 208 m/s, axisymmetric FEM 6 cells/radius: final "
       "length",
       "test L = 0.885 x 25.4 mm (Johnson & Cook 1983)", 0.885 * 25.4e-3, r.final_length, 0.02, true, "m"});
  test::verify(
      {"Taylor impact, 4340 steel (JC 1983 constants), 208 m/s, axisymmetric FEM 6 cells/radius: foot "
       "diameter",
       "test 11.1 mm (Johnson & Cook 1983)", 11.1e-3, r.foot_diameter, 0.05, true, "m"});
  // The temperature field: its peak rise against the Taylor-Quinney heat of the plastic work.
  test::verify({"Taylor impact, 4340 steel, 208 m/s: peak temperature rise of the field",
                "chi w_p / C_v of the same element's plastic work (Taylor-Quinney, chi = 0.9)",
                r.peak_temperature_from_work - r.room_temperature, r.peak_temperature - r.room_temperature, 0.02,
                true, "K"});
  EXPECT_GT(r.peak_temperature - r.room_temperature, 50.0) << "the foot must heat visibly";
  EXPECT_LT(r.kinetic_fraction, 0.02) << "the rod must have stopped (elastic ringing only)";
  EXPECT_LT(r.energy_error, 0.01);
}
