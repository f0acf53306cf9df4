// Programmed burn: lighting times from several detonation points and the
// burn-fraction ramp that scales the JWL pressure (programmed_burn.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/verification.hpp"
#include "materials/jwl_eos.hpp"
#include "materials/programmed_burn.hpp"

using namespace camouflet;

namespace {

JwlEos tnt(double n_burn = 2.0) {
  JwlParameters p;
  p.density = 1630.0;
  p.c1 = 373.8e9;
  p.c2 = 3.747e9;
  p.r1 = 4.15;
  p.r2 = 0.9;
  p.omega = 0.35;
  p.e0 = 6.0e9;
  return JwlEos(p, 6930.0, n_burn);
}

}  // namespace

TEST(ProgrammedBurn, LightingTimeIsEarliestArrival) {
  const std::vector<DetonationPoint> points{{{0.0, 0.0, 0.0}, 0.0}, {{1.0, 0.0, 0.0}, 50e-6}};
  const double d = 6930.0;
  test::verify({"Programmed burn: lighting time from the nearer point", "|x - x1| / D", 0.3 / d,
                lighting_time({0.3, 0.0, 0.0}, points, d), 1e-14, true, "s"});
  // 0.9 m from the first point (129.9 us) but 0.1 m from the second, lit at 50 us: 64.4 us.
  test::verify({"Programmed burn: lighting time from a later point", "t2 + |x - x2| / D", 50e-6 + 0.1 / d,
                lighting_time({0.9, 0.0, 0.0}, points, d), 1e-14, true, "s"});
  EXPECT_EQ(lighting_time({0.0, 0.0, 0.0}, {}, d), std::numeric_limits<double>::infinity());
}

TEST(ProgrammedBurn, FractionRampsOverNBurnLengths) {
  const double d = 6930.0, L = 0.01, tl = 1e-5;
  EXPECT_EQ(burn_fraction(0.9 * tl, tl, d, 2.0, L), 0.0);
  // Half-way through the ramp: the front has run n_burn L / 2.
  test::verify({"Programmed burn: fraction half-way through the ramp", "F = (t - t_l) D / (n_burn L)", 0.5,
                burn_fraction(tl + 0.5 * 2.0 * L / d, tl, d, 2.0, L), 1e-12, true, ""});
  EXPECT_EQ(burn_fraction(tl + 3.0 * L / d, tl, d, 2.0, L), 1.0);
  EXPECT_EQ(burn_fraction(1.0, std::numeric_limits<double>::infinity(), d, 2.0, L), 0.0);
}

TEST(ProgrammedBurn, JwlPressureScalesWithBurnFraction) {
  const JwlEos eos = tnt();
  MaterialPoints pts;
  eos.register_state(pts);
  pts.resize(3);
  const double L = 0.01;
  std::vector<std::array<double, 3>> x{{0.0, 0.0, 0.0}, {0.1, 0.0, 0.0}, {0.2, 0.0, 0.0}};
  for (std::size_t i = 0; i < 3; ++i) {
    pts.density[i] = 1630.0;
    pts.specific_energy[i] = eos.reference_specific_energy();
    pts.characteristic_length[i] = L;
  }
  eos.place(pts, x, {DetonationPoint{{0.0, 0.0, 0.0}, 0.0}});
  const double* lit = pts.history.column(pts.history.slot("lighting_time"));
  EXPECT_NEAR(lit[1], 0.1 / 6930.0, 1e-15);
  // At t: point 0 fully burnt, point 1 a quarter through its ramp, point 2 unlit.
  const double t = 0.1 / 6930.0 + 0.25 * 2.0 * L / 6930.0;
  eos.evaluate(pts, MaterialContext{1e-7, t}, false);
  const double full = eos.products_pressure(1630.0, eos.reference_specific_energy());
  EXPECT_NEAR(pts.pressure[0], full, 1e-9 * full);
  test::verify({"Programmed burn: JWL pressure a quarter through the ramp", "F p_JWL with F = 0.25",
                0.25 * full, pts.pressure[1], 1e-9, true, "Pa"});
  EXPECT_EQ(pts.pressure[2], 0.0);  // unburnt explosive carries no pressure
  EXPECT_GT(pts.sound_speed[2], 0.0);
  // The predictor (commit = false) leaves the stored fraction alone; commit stores it.
  const double* burnt = pts.history.column(pts.history.slot("burn_fraction"));
  EXPECT_EQ(burnt[1], 0.0);
  eos.evaluate(pts, MaterialContext{1e-7, t}, true);
  EXPECT_NEAR(burnt[1], 0.25, 1e-12);
  // Burnt stays burnt, even if asked at an earlier time.
  eos.evaluate(pts, MaterialContext{1e-7, 0.0}, false);
  EXPECT_NEAR(pts.pressure[1], 0.25 * full, 1e-9 * full);
}
