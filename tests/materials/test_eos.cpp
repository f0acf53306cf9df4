// Each EOS of the family against its closed form, and its sound speed against
// the isentropic derivative c^2 = dp/drho along de = p / rho^2 drho.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "common/verification.hpp"
#include "materials/material_driver.hpp"
#include "materials/registry.hpp"

using namespace camouflet;

namespace {

Parameters block(const std::string& type, std::initializer_list<std::pair<const char*, double>> values) {
  Parameters b(SourceLocation{"test.toml", 1, 1, "eos"});
  b.set_string("type", type, SourceLocation{"test.toml", 2, 1, "eos.type"});
  int line = 3;
  for (const auto& [k, v] : values)
    b.set_number(k, v, SourceLocation{"test.toml", line++, 1, std::string("eos.") + k});
  return b;
}

// Pressure and sound speed of a one-point batch at (rho, e).
struct State {
  double pressure, sound_speed;
};
State evaluate(const EquationOfState& eos, double rho, double e, double time = 1.0) {
  MaterialPoints pts;
  eos.register_state(pts);
  pts.resize(1);
  pts.density[0] = rho;
  pts.specific_energy[0] = e;
  pts.characteristic_length[0] = 1e-3;
  if (pts.history.contains("lighting_time")) pts.history.column(pts.history.slot("lighting_time"))[0] = 0.0;
  eos.evaluate(pts, MaterialContext{0.0, time}, false);
  return {pts.pressure[0], pts.sound_speed[0]};
}

// c^2 by central differences along the isentrope (the second-order term of
// e(rho) cancels in the symmetric difference).
double isentropic_c2(const EquationOfState& eos, double rho, double e) {
  const double h = 1e-5 * rho;
  const double p = evaluate(eos, rho, e).pressure;
  const double de = p / (rho * rho) * h;
  return (evaluate(eos, rho + h, e + de).pressure - evaluate(eos, rho - h, e - de).pressure) / (2.0 * h);
}

void check_sound_speed(const std::string& name, const EquationOfState& eos, double rho, double e) {
  const double c = evaluate(eos, rho, e).sound_speed;
  test::verify({name + ": sound speed at rho = " + std::to_string(rho),
                "sqrt(dp/drho at constant entropy), numerical", std::sqrt(isentropic_c2(eos, rho, e)), c,
                1e-6, true, "m/s"});
}

}  // namespace

TEST(ShockEos, ReproducesItsHugoniot) {
  const double rho0 = 8930.0, c0 = 3940.0, s = 1.49;  // copper (Meyers 1994, Table 4.1)
  Parameters b = block("shock", {{"density", rho0}, {"c0", c0}, {"s", s}, {"gamma0", 2.0}});
  auto eos = make_eos(b);
  double worst = 0.0;
  for (double mu : {0.01, 0.05, 0.1, 0.2, 0.3, 0.5}) {
    const double p_h = rho0 * c0 * c0 * mu * (1.0 + mu) / std::pow(1.0 - (s - 1.0) * mu, 2);
    const double eta = mu / (1.0 + mu);
    const double e_h = p_h * eta / (2.0 * rho0);  // Rankine-Hugoniot energy from rest
    worst = std::max(worst, std::abs(evaluate(*eos, rho0 * (1.0 + mu), e_h).pressure - p_h) / p_h);
  }
  test::verify({"Shock EOS on its own Hugoniot (mu = 0.01..0.5)", "p_H = rho0 c0^2 mu (1+mu) / (1-(s-1)mu)^2",
                0.0, worst, 1e-9, false, "relative"});
  // Off the Hugoniot: p - p_H = Gamma0 rho0 (e - e_H).
  const double mu = 0.2, p_h = rho0 * c0 * c0 * mu * (1.0 + mu) / std::pow(1.0 - (s - 1.0) * mu, 2);
  const double e_h = p_h * mu / (1.0 + mu) / (2.0 * rho0);
  test::verify({"Shock EOS off the Hugoniot", "p_H + Gamma0 rho0 (e - e_H)", p_h + 2.0 * rho0 * 1.0e5,
                evaluate(*eos, rho0 * 1.2, e_h + 1.0e5).pressure, 1e-12, true, "Pa"});
  check_sound_speed("Shock EOS", *eos, rho0 * 1.2, e_h + 1.0e5);
  check_sound_speed("Shock EOS (tension)", *eos, rho0 * 0.97, 1.0e4);
  EXPECT_NEAR(evaluate(*eos, rho0, 0.0).sound_speed, c0, 1e-9 * c0);
  EXPECT_THROW(evaluate(*eos, rho0 * s / (s - 1.0) * 1.01, 0.0), NumericalError);
}

TEST(PolynomialEos, ClosedFormInCompressionAndTension) {
  // Concrete, Wang et al. 2005 Table 3 (A1 = T1 = 35.27 GPa ...) with Autodyn's B0 = B1 = 1.22.
  const double rho0 = 2750.0, a1 = 35.27e9, a2 = 39.58e9, a3 = 9.04e9, b0 = 1.22, b1 = 1.22;
  Parameters b =
      block("polynomial",
            {{"density", rho0}, {"a1", a1}, {"a2", a2}, {"a3", a3}, {"b0", b0}, {"b1", b1}, {"t2", -5e9}});
  auto eos = make_eos(b);
  const double e = 2.0e5, mu = 0.08;
  test::verify({"Polynomial EOS, compression", "A1 mu + A2 mu^2 + A3 mu^3 + (B0 + B1 mu) rho0 e",
                a1 * mu + a2 * mu * mu + a3 * mu * mu * mu + (b0 + b1 * mu) * rho0 * e,
                evaluate(*eos, rho0 * (1.0 + mu), e).pressure, 1e-12, true, "Pa"});
  test::verify({"Polynomial EOS, tension", "T1 mu + T2 mu^2 + B0 rho0 e (T1 = A1)",
                a1 * -0.02 + -5e9 * 0.0004 + b0 * rho0 * e, evaluate(*eos, rho0 * 0.98, e).pressure, 1e-12,
                true, "Pa"});
  check_sound_speed("Polynomial EOS", *eos, rho0 * 1.08, e);
  check_sound_speed("Polynomial EOS (tension)", *eos, rho0 * 0.98, e);
}

TEST(IdealGasEos, FollowsItsIsentropeThroughTheDriver) {
  // Hydrostatic compression through Material::update (energy equation with
  // p dv): the gas must follow p / rho^gamma = const.
  const double gamma = 1.4, rho0 = 1.2, e0 = 2.0e5;
  Parameters b = block("ideal_gas", {{"density", rho0}, {"gamma", gamma}, {"specific_energy", e0}});
  auto eos = make_eos(b);
  const Material gas("air", eos);
  DriverSpec spec;
  spec.path = LoadPath::hydrostatic;
  spec.strain_rate = -1.0;
  spec.final_strain = -0.2;
  spec.steps = 400;
  const auto rows = drive_material(gas, spec);
  const DriverRow& last = rows.back();
  const double p0 = (gamma - 1.0) * rho0 * e0;
  test::verify({"Ideal gas, hydrostatic compression to rho/rho0 = e^0.6", "isentrope p0 (rho/rho0)^gamma",
                p0 * std::pow(last.density / rho0, gamma), last.pressure, 1e-5, true, "Pa"});
  check_sound_speed("Ideal gas", *eos, 2.0, 3.0e5);
}

TEST(JwlEos, FullyBurntPressureAndSoundSpeed) {
  Parameters b = block("jwl", {{"density", 1630.0},
                               {"c1", 373.8e9},
                               {"c2", 3.747e9},
                               {"r1", 4.15},
                               {"r2", 0.9},
                               {"omega", 0.35},
                               {"e0", 6.0e9}});
  auto eos = make_eos(b);
  // Long after lighting (t = 1 s) the burn fraction is 1: the JWL form itself.
  for (double v : {0.75, 1.0, 3.0}) {
    const double rho = 1630.0 / v, e = 3.0e6;
    const double expected = 373.8e9 * (1.0 - 0.35 / (4.15 * v)) * std::exp(-4.15 * v) +
                            3.747e9 * (1.0 - 0.35 / (0.9 * v)) * std::exp(-0.9 * v) + 0.35 * 1630.0 * e / v;
    test::verify({"JWL pressure at V = " + std::to_string(v), "Wang 2005 eq. 37 with E = rho0 e", expected,
                  evaluate(*eos, rho, e).pressure, 1e-12, true, "Pa"});
    check_sound_speed("JWL at V = " + std::to_string(v), *eos, rho, e);
  }
}

TEST(EosInput, BadValuesNameTheKey) {
  auto key_of = [](Parameters b) {
    try {
      make_eos(b);
    } catch (const InputError& e) {
      return e.where().key;
    }
    return std::string("no error");
  };
  EXPECT_EQ(key_of(block("ideal_gas", {{"density", 1.2}, {"gamma", 1.0}})), "eos.gamma");
  EXPECT_EQ(key_of(block("shock", {{"density", 8930.0}, {"c0", 3940.0}, {"s", -1.0}, {"gamma0", 2.0}})),
            "eos.s");
  EXPECT_EQ(key_of(block("polynomial", {{"density", 2750.0}, {"a1", 1e9}, {"a4", 1e9}})), "eos.a4");
  EXPECT_EQ(key_of(block("jwl", {{"density", 1630.0},
                                 {"c1", 373.8e9},
                                 {"c2", 3.747e9},
                                 {"r1", 4.15},
                                 {"r2", 0.9},
                                 {"omega", 0.35},
                                 {"e0", 6.0e9},
                                 {"burn_width_factor", 0.0}})),
            "eos.burn_width_factor");
}
