// Johnson-Cook steel at a material point: uniaxial stress
// at constant strain rate through the material-point driver, against the
// closed-form yield curve (isothermal) and the closed-form adiabatic
// softening (an accurate integration of dT/deps_p = chi Y / (rho C_v)).
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/material_driver.hpp"
#include "materials/registry.hpp"

using namespace camouflet;

namespace {

Parameters steel_block(bool isothermal) {
  Parameters b(SourceLocation{"test.toml", 1, 1, "strength"});
  int line = 2;
  auto set = [&](const char* k, double v) {
    b.set_number(k, v, SourceLocation{"test.toml", line++, 1, std::string("strength.") + k});
  };
  b.set_string("type", "johnson_cook", SourceLocation{"test.toml", line++, 1, "strength.type"});
  // Wang et al. 2005, Table 4 (steel 1006).
  set("shear_modulus", 81.8e9);
  set("yield_stress", 350.0e6);
  set("hardening_modulus", 275.0e6);
  set("hardening_exponent", 0.36);
  set("rate_coefficient", 0.022);
  set("thermal_exponent", 1.0);
  set("room_temperature", 300.0);
  set("melt_temperature", 1811.0);
  set("specific_heat", 452.0);
  b.set_bool("isothermal", isothermal, SourceLocation{"test.toml", line++, 1, "strength.isothermal"});
  return b;
}

Material steel(bool isothermal) {
  Parameters eos(SourceLocation{"test.toml", 20, 1, "eos"});
  eos.set_string("type", "polynomial");
  eos.set_number("density", 7896.0);
  eos.set_number("a1", 200.0e9);
  Parameters strength = steel_block(isothermal);
  return Material("steel", make_eos(eos), make_strength(strength));
}

std::vector<DriverRow> compress(const Material& m, double rate) {
  DriverSpec spec;
  spec.path = LoadPath::uniaxial_stress;
  spec.strain_rate = -rate;
  spec.final_strain = -0.3;
  spec.steps = 1500;
  return drive_material(m, spec);
}

JohnsonCookParameters table4() {
  JohnsonCookParameters p;
  p.shear_modulus = 81.8e9;
  p.yield_stress = 350.0e6;
  p.hardening_modulus = 275.0e6;
  p.hardening_exponent = 0.36;
  p.rate_coefficient = 0.022;
  p.thermal_exponent = 1.0;
  p.melt_temperature = 1811.0;
  p.specific_heat = 452.0;
  return p;
}

}  // namespace

TEST(JohnsonCook, IsothermalUniaxialStressFollowsYieldCurve) {
  const Material m = steel(true);
  const JohnsonCookParameters p = table4();
  for (double rate : {1.0, 1000.0}) {
    const auto rows = compress(m, rate);
    double worst = 0.0, worst_at = 0.0;
    for (const DriverRow& r : rows) {
      // At 1 /s the rate factor is 1 from the first plastic step on; at
      // 1000 /s the plastic rate reaches the total rate only past the
      // elastic-plastic transition.
      if (r.plastic_strain <= (rate > 1.0 ? 0.005 : 0.0)) continue;
      const double y = johnson_cook_yield(p, r.plastic_strain, rate, 300.0);
      const double err = std::abs(-r.stress.xx - y) / y;
      if (err > worst) {
        worst = err;
        worst_at = r.plastic_strain;
      }
    }
    test::verify({"Johnson-Cook steel 1006, isothermal uniaxial stress at " + std::to_string(rate) +
                      " /s: max error over the plastic range up to eps_p = 0.3 (worst at eps_p = " +
                      std::to_string(worst_at) + ")",
                  "closed form [Y0 + B eps^n][1 + C ln rate*]", 0.0, worst, 0.01, false, "relative"});
    // The lateral stress stays free and the elastic part has slope E.
    EXPECT_LT(std::abs(rows.back().stress.yy), 1e-6 * std::abs(rows.back().stress.xx));
    EXPECT_GT(rows.back().plastic_strain, 0.29);
  }
  // The elastic part has slope E = 9 K G / (3 K + G) (to 1e-4: p = K mu is
  // linear in rho, not in the driver's logarithmic strain).
  const auto rows = compress(m, 1.0);
  const double young = 9.0 * 200e9 * 81.8e9 / (3.0 * 200e9 + 81.8e9);
  test::verify({"Johnson-Cook steel 1006, uniaxial stress: elastic slope",
                "E = 9KG/(3K+G), K = 200 GPa, G = 81.8 GPa", young, rows[1].stress.xx / rows[1].axial_strain,
                1e-4, true, "Pa"});
}

TEST(JohnsonCook, AdiabaticSofteningAsPredicted) {
  // Closed-form prediction: at constant plastic rate, T(eps_p) solves
  // dT/deps = chi Y(eps, rate, T) / (rho C_v), integrated here by RK4 in
  // small steps; the flow stress is Y(eps, rate, T(eps)).
  const JohnsonCookParameters p = table4();
  const double rate = 1000.0, rho = 7896.0;
  auto dT = [&](double eps, double T) {
    return p.taylor_quinney * johnson_cook_yield(p, eps, rate, T) / (rho * p.specific_heat);
  };
  const auto rows = compress(steel(false), rate);
  const DriverRow& last = rows.back();
  double T = 300.0, eps = 0.0;
  const int n = 20000;
  const double h = last.plastic_strain / n;
  for (int k = 0; k < n; ++k, eps += h) {
    const double k1 = dT(eps, T), k2 = dT(eps + 0.5 * h, T + 0.5 * h * k1);
    const double k3 = dT(eps + 0.5 * h, T + 0.5 * h * k2), k4 = dT(eps + h, T + h * k3);
    T += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  test::verify({"Johnson-Cook steel 1006, adiabatic 1000 /s: temperature at eps_p = 0.3",
                "integral of chi Y deps / (rho C_v)", T, last.temperature, 0.01, true, "K"});
  const double y_adiabatic = johnson_cook_yield(p, last.plastic_strain, rate, T);
  test::verify({"Johnson-Cook steel 1006, adiabatic 1000 /s: flow stress at eps_p = 0.3",
                "Y(eps, rate, T_adiabatic(eps)) (closed form)", y_adiabatic, -last.stress.xx, 0.01, true,
                "Pa"});
  // The softening itself (isothermal minus adiabatic) is predicted within 2 %.
  const double y_iso = johnson_cook_yield(p, last.plastic_strain, rate, 300.0);
  const auto iso = compress(steel(true), rate);
  test::verify({"Johnson-Cook steel 1006, adiabatic 1000 /s: thermal softening at eps_p = 0.3",
                "Y_isothermal - Y_adiabatic (closed form)", y_iso - y_adiabatic,
                last.stress.xx - iso.back().stress.xx, 0.02, true, "Pa"});
}

TEST(JohnsonCook, BadInputNamesTheKey) {
  auto key_of = [](const char* key, double value) {
    Parameters b = steel_block(false);
    b.set_number(key, value, SourceLocation{"test.toml", 99, 1, std::string("strength.") + key});
    try {
      make_strength(b);
    } catch (const InputError& e) {
      return e.where().key;
    }
    return std::string("no error");
  };
  EXPECT_EQ(key_of("hardening_exponent", 0.0), "strength.hardening_exponent");
  EXPECT_EQ(key_of("hardening_exponent", -0.3), "strength.hardening_exponent");
  EXPECT_EQ(key_of("melt_temperature", 300.0), "strength.melt_temperature");
  EXPECT_EQ(key_of("melt_temperature", 250.0), "strength.melt_temperature");
  EXPECT_EQ(key_of("taylor_quinney", 1.5), "strength.taylor_quinney");
}
