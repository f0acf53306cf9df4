// Taylor cylinder impact, longer runs (label `long`): mesh convergence of the
// quick test (tests/solver/test_taylor_bar.cpp) and the OFHC copper test of
// Johnson & Cook 1983 at 190 m/s (L0 = 25.4 mm, D0 = 7.62 mm: L/L0 = 0.638,
// foot diameter 1.78 D0; also used by Zerilli & Armstrong 1987, J. Appl.
// Phys. 61, 1816). With the JC 1983 copper constants the computed rod is 7 %
// longer than the test and its foot 7 % wider on every mesh tried (6 and 10
// cells/radius agree within 0.1 % on length): a model-versus-test
// difference, not a discretisation error, so the copper tolerance (8 %) is a
// regression guard on that documented difference, not an accuracy claim.
// docs/theory/explosive-and-steel.md §5.2.
#include <gtest/gtest.h>

#include "common/verification.hpp"
#include "solver/taylor_bar.hpp"

using namespace camouflet;

TEST(TaylorBarLong, Steel4340At208MetresPerSecondFineMesh) {
  const test::TaylorSpec spec{"steel_4340_jc1983", 3.81e-3, 25.4e-3, 208.0, 12, 80e-6, 60e-6};
  const test::TaylorResult r = test::run_taylor_bar(spec);
  test::verify(
      {"Taylor impact, 4340 steel (JC 1983 constants), 208 m/s, axisymmetric FEM 12 cells/radius: final "
       "length",
       "test L = 0.885 x 25.4 mm (Johnson & Cook 1983)", 0.885 * 25.4e-3, r.final_length, 0.02, true, "m"});
  test::verify(
      {"Taylor impact, 4340 steel (JC 1983 constants), 208 m/s, axisymmetric FEM 12 cells/radius: foot "
       "diameter",
       "test 11.1 mm (Johnson & Cook 1983)", 11.1e-3, r.foot_diameter, 0.05, true, "m"});
  EXPECT_LT(r.energy_error, 0.01);
}

TEST(TaylorBarLong, OfhcCopperAt190MetresPerSecond) {
  const test::TaylorSpec spec{"copper_ofhc_jc1983", 3.81e-3, 25.4e-3, 190.0, 10, 120e-6, 90e-6};
  const test::TaylorResult r = test::run_taylor_bar(spec);
  test::verify(
      {"Taylor impact, OFHC copper (JC 1983 constants), 190 m/s, axisymmetric FEM 10 cells/radius: final "
       "length (model-test difference of the JC copper set, see docs)",
       "test L = 0.638 x 25.4 mm (Johnson & Cook 1983)", 0.638 * 25.4e-3, r.final_length, 0.08, true, "m"});
  test::verify(
      {"Taylor impact, OFHC copper (JC 1983 constants), 190 m/s, axisymmetric FEM 10 cells/radius: foot "
       "diameter (model-test difference of the JC copper set, see docs)",
       "test 1.78 x 7.62 mm (Johnson & Cook 1983)", 1.78 * 7.62e-3, r.foot_diameter, 0.08, true, "m"});
  test::verify({"Taylor impact, OFHC copper, 190 m/s: peak temperature rise of the field",
                "chi w_p / C_v of the same element's plastic work (Taylor-Quinney, chi = 0.9)",
                r.peak_temperature_from_work - r.room_temperature, r.peak_temperature - r.room_temperature, 0.02,
                true, "K"});
  EXPECT_LT(r.energy_error, 0.01);
}
