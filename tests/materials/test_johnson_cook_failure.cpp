// Johnson-Cook failure at a material point (docs/theory/explosive-and-steel.md
// §5.1): uniaxial stress to failure through the material-point driver. In
// uniaxial stress the triaxiality is sigma* = +1/3 (tension) or -1/3
// (compression) at every step, so the plastic strain at which D reaches 1
// must be eps_f = [D1 + D2 exp(D3 sigma*)][1 + D4 ln rate*][1 + D5 T*] of
// Johnson & Cook 1985; after failure the point carries no stress.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/johnson_cook_failure.hpp"
#include "materials/material_driver.hpp"
#include "materials/registry.hpp"

using namespace camouflet;

namespace {

SourceLocation at(const std::string& key) {
  return SourceLocation{"test.toml", 1, 1, "damage." + key};
}

// 4340 steel: strength of Johnson & Cook 1983 (Table 1-2), fracture constants
// of Johnson & Cook 1985 (Table 2).
Parameters failure_block() {
  Parameters b(at(""));
  b.set_string("type", "johnson_cook", at("type"));
  b.set_number("d1", -0.80, at("d1"));
  b.set_number("d2", 2.10, at("d2"));
  b.set_number("d3", -0.50, at("d3"));
  b.set_number("d4", 0.002, at("d4"));
  b.set_number("d5", 0.61, at("d5"));
  b.set_number("melt_temperature", 1793.0, at("melt_temperature"));
  return b;
}

JohnsonCookFailureParameters failure_parameters() {
  JohnsonCookFailureParameters p;
  p.d1 = -0.80;
  p.d2 = 2.10;
  p.d3 = -0.50;
  p.d4 = 0.002;
  p.d5 = 0.61;
  p.melt_temperature = 1793.0;
  return p;
}

Material steel_4340() {
  Parameters eos;
  eos.set_string("type", "polynomial");
  eos.set_number("density", 7830.0);
  eos.set_number("a1", 159.0e9);
  Parameters s;
  s.set_string("type", "johnson_cook");
  s.set_number("shear_modulus", 77.5e9);
  s.set_number("yield_stress", 792.0e6);
  s.set_number("hardening_modulus", 510.0e6);
  s.set_number("hardening_exponent", 0.26);
  s.set_number("rate_coefficient", 0.014);
  s.set_number("thermal_exponent", 1.03);
  s.set_number("melt_temperature", 1793.0);
  s.set_number("specific_heat", 477.0);
  s.set_bool("isothermal", true);  // T* = 0: the thermal factor is checked by the formula test below
  Parameters d = failure_block();
  return Material("steel_4340", make_eos(eos), make_strength(s), make_damage(d));
}

struct Failure {
  double plastic_strain = -1.0;  // at D = 1 (midpoint of the step in which it is reached)
  double stress_after = 0.0;     // Pa, |axial stress| at the end of the path
  double damage_before = 0.0;    // damage one step before failure
};

Failure pull(double rate, double final_strain) {
  DriverSpec spec;
  spec.path = LoadPath::uniaxial_stress;
  spec.strain_rate = rate;
  spec.final_strain = final_strain;
  spec.steps = 4000;
  const auto rows = drive_material(steel_4340(), spec);
  Failure f;
  for (std::size_t k = 1; k < rows.size(); ++k)
    if (rows[k].damage >= 1.0) {
      f.plastic_strain = 0.5 * (rows[k - 1].plastic_strain + rows[k].plastic_strain);
      f.damage_before = rows[k - 1].damage;
      break;
    }
  f.stress_after = std::abs(rows.back().stress.xx);
  return f;
}

}  // namespace

TEST(JohnsonCookFailure, FailureStrainFormula) {
  const JohnsonCookFailureParameters p = failure_parameters();
  // Hand values: tension at the reference rate and room temperature.
  EXPECT_NEAR(johnson_cook_failure_strain(p, 1.0 / 3.0, 1.0, 300.0), -0.80 + 2.10 * std::exp(-0.5 / 3.0),
              1e-15);
  // Rate and temperature factors; rates below the reference give factor 1.
  const double t_half = 300.0 + 0.5 * (1793.0 - 300.0);
  EXPECT_NEAR(johnson_cook_failure_strain(p, 0.0, 1000.0, t_half),
              (-0.80 + 2.10) * (1.0 + 0.002 * std::log(1000.0)) * (1.0 + 0.61 * 0.5), 1e-14);
  EXPECT_DOUBLE_EQ(johnson_cook_failure_strain(p, 0.0, 1e-3, 300.0), -0.80 + 2.10);
  // Past sigma* = ln(0.8 / 2.1) / -0.5 = 1.93 the bare formula gives eps_f < 0:
  // 0 by default (immediate failure), else `minimum_failure_strain`.
  EXPECT_EQ(johnson_cook_failure_strain(p, 2.0, 1.0, 300.0), 0.0);
  JohnsonCookFailureParameters bounded = p;
  bounded.minimum_failure_strain = 0.2;
  EXPECT_DOUBLE_EQ(johnson_cook_failure_strain(bounded, 3.0, 1.0, 300.0), 0.2);
  EXPECT_DOUBLE_EQ(johnson_cook_failure_strain(bounded, 0.0, 1.0, 300.0), 1.3);
}

TEST(JohnsonCookFailure, UniaxialStressFailsAtTheFormulaStrain) {
  const JohnsonCookFailureParameters p = failure_parameters();
  struct Case {
    const char* name;
    double rate, triaxiality, final_strain;
  };
  for (const Case& c :
       {Case{"tension at 1 /s", 1.0, 1.0 / 3.0, 1.3}, Case{"tension at 1000 /s", 1000.0, 1.0 / 3.0, 1.3},
        Case{"compression at 1 /s", -1.0, -1.0 / 3.0, -2.0}}) {
    const double expected = johnson_cook_failure_strain(p, c.triaxiality, std::abs(c.rate), 300.0);
    const Failure f = pull(c.rate, c.final_strain);
    ASSERT_GT(f.plastic_strain, 0.0) << c.name << ": the point did not fail";
    test::verify({std::string("Johnson-Cook failure, 4340 steel, uniaxial stress ") + c.name +
                      ": plastic strain at D = 1",
                  "eps_f = [D1 + D2 exp(D3 sigma*)][1 + D4 ln rate*] (Johnson & Cook 1985), sigma* = " +
                      std::to_string(c.triaxiality),
                  expected, f.plastic_strain, 0.01, true, "-"});
    EXPECT_LT(f.damage_before, 1.0);
    // A failed point carries no deviator and no tension (in compression the
    // driver holds the lateral stress at 0, so the axial stress is -p = 0 too).
    EXPECT_LT(f.stress_after, 1e-6 * 792e6) << c.name;
  }
}

TEST(JohnsonCookFailure, BadInputNamesTheKey) {
  auto key_of = [](const char* key, double value) {
    Parameters b = failure_block();
    b.set_number(key, value, at(key));
    try {
      make_damage(b);
    } catch (const InputError& e) {
      return e.where().key;
    }
    return std::string("no error");
  };
  // D1 + D2 exp(D3/3) <= 0: no strain to failure in tension.
  EXPECT_EQ(key_of("d1", -2.0), "damage.d1");
  EXPECT_EQ(key_of("melt_temperature", 250.0), "damage.melt_temperature");
  EXPECT_EQ(key_of("reference_strain_rate", 0.0), "damage.reference_strain_rate");
  EXPECT_EQ(key_of("minimum_failure_strain", -0.1), "damage.minimum_failure_strain");
  EXPECT_EQ(key_of("d4", 0.01), "no error");
}
