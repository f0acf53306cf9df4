// Chapman-Jouguet state of the seed paper's TNT and the
// refusal of a JWL set without one.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "materials/cj_state.hpp"
#include "materials/jwl_eos.hpp"
#include "materials/registry.hpp"

using namespace camouflet;

namespace {

JwlParameters tnt() {
  // Wang et al. 2005, Table 5.
  JwlParameters p;
  p.density = 1630.0;
  p.c1 = 373.8e9;
  p.c2 = 3.747e9;
  p.r1 = 4.15;
  p.r2 = 0.9;
  p.omega = 0.35;
  p.e0 = 6.0e9;
  return p;
}

Parameters jwl_block(double c2) {
  Parameters b(SourceLocation{"case.toml", 10, 1, "materials.tnt.eos"});
  auto at = [](const std::string& k, int line) {
    return SourceLocation{"case.toml", line, 1, "materials.tnt.eos." + k};
  };
  b.set_string("type", "jwl", at("type", 11));
  b.set_number("density", 1630.0, at("density", 12));
  b.set_number("c1", 373.8e9, at("c1", 13));
  b.set_number("c2", c2, at("c2", 14));
  b.set_number("r1", 4.15, at("r1", 15));
  b.set_number("r2", 0.9, at("r2", 16));
  b.set_number("omega", 0.35, at("omega", 17));
  b.set_number("e0", 6.0e9, at("e0", 18));
  return b;
}

}  // namespace

TEST(CjState, TntOfWang2005) {
  const CjState cj = chapman_jouguet_state(tnt());
  test::verify({"CJ state of TNT (JWL, Wang 2005 Table 5): detonation velocity", "Table 5: D = 6930 m/s",
                6930.0, cj.detonation_velocity, 0.005, true, "m/s"});
  test::verify({"CJ state of TNT (JWL, Wang 2005 Table 5): CJ pressure", "physics.md: P_CJ = 21.0 GPa",
                21.0e9, cj.pressure, 0.01, true, "Pa"});
  // Jump conditions: rho0 D^2 (1 - V) = p and u = D (1 - V).
  EXPECT_NEAR(1630.0 * cj.detonation_velocity * cj.detonation_velocity * (1.0 - cj.relative_volume),
              cj.pressure, 1e-9 * cj.pressure);
  EXPECT_NEAR(cj.density, 1630.0 / cj.relative_volume, 1e-9);
}

TEST(CjState, SoundSpeedAtCjIsDMinusU) {
  // At the CJ point the Rayleigh line, the Hugoniot and the isentrope are
  // tangent, so the products' sound speed equals D - u_CJ (Fickett & Davis
  // 1979, ch. 2): an independent check of the tangency and of the JWL sound speed.
  const JwlParameters p = tnt();
  const JwlEos eos(p, 0.0, 2.0);
  const CjState& cj = eos.cj_state();
  const double e_cj = p.e0 / p.density + 0.5 * cj.pressure * (1.0 / p.density - 1.0 / cj.density);  // J/kg
  EXPECT_NEAR(eos.products_pressure(cj.density, e_cj), cj.pressure, 1e-6 * cj.pressure);
  const double c = std::sqrt(eos.products_sound_speed_squared(cj.density, e_cj));
  test::verify({"CJ state of TNT: sonic condition", "c_CJ = D - u_CJ (CJ theory)",
                cj.detonation_velocity - cj.particle_velocity, c, 1e-4, true, "m/s"});
  EXPECT_DOUBLE_EQ(eos.detonation_velocity(), cj.detonation_velocity);  // no D given: the CJ one
}

TEST(CjState, FactoryUsesGivenVelocityAndKeepsCj) {
  Parameters b = jwl_block(3.747e9);
  b.set_number("detonation_velocity", 6930.0,
               SourceLocation{"case.toml", 19, 1, "materials.tnt.eos.detonation_velocity"});
  auto eos = make_eos(b);
  const auto* jwl = dynamic_cast<const JwlEos*>(eos.get());
  ASSERT_NE(jwl, nullptr);
  EXPECT_DOUBLE_EQ(jwl->detonation_velocity(), 6930.0);
  EXPECT_NEAR(jwl->reference_specific_energy(), 6.0e9 / 1630.0, 1e-6);  // J/kg from J/m^3
}

TEST(CjState, NoCjStateNamesTheKey) {
  // A strongly negative C2 makes the product Hugoniot pressure negative near
  // V = 1: no Rayleigh line from (rho0, 0) can touch it.
  Parameters b = jwl_block(-60.0e9);
  try {
    make_eos(b);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "materials.tnt.eos.c2");
    EXPECT_EQ(e.where().line, 14);
    EXPECT_NE(std::string(e.what()).find("Chapman-Jouguet"), std::string::npos) << e.what();
  }
  JwlParameters p = tnt();
  p.e0 = -1.0e9;
  p.c1 = 0.0;
  p.c2 = 0.0;
  try {
    chapman_jouguet_state(p);
    FAIL() << "expected CjStateError";
  } catch (const CjStateError& e) {
    EXPECT_EQ(e.key(), "e0");
  }
}
