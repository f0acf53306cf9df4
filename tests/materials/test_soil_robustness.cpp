// Three-phase soil under random strain increments, and refusal of bad
// parameters with an InputError naming the key.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/verification.hpp"
#include "core/error.hpp"
#include "soil_test_support.hpp"

namespace camouflet::test {
namespace {

TEST(ThreePhaseSoilRobustness, TenThousandRandomIncrements) {
  PointDriver point(soil_material(soil_eos_block(), soil_strength_block(), soil_damage_block()));
  const double rho0 = point.pts.density[0];
  std::mt19937_64 rng(20051);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> coin(0.0, 1.0);
  const double dt = 1e-5;
  int bad = 0, solve_failures = 0, compressed = 0, cutoff = 0, unloading = 0;
  double max_pressure = 0.0;
  for (int s = 0; s < 10000; ++s) {
    // Mostly moderate increments; 5 % large volumetric jumps (up to +-25 % per step).
    const bool jump = coin(rng) < 0.05;
    double vol = (jump ? 0.25 : 0.01) * unit(rng);
    // Keep V/V0 within [0.55, 1.6]: from ~70 GPa compression to wide open tension
    // (the step multiplies V by exp(vol)).
    const double v = rho0 / point.pts.density[0];
    if (std::log(v) + vol < std::log(0.55) || std::log(v) + vol > std::log(1.6)) vol = -vol;
    SymTensor rate{unit(rng), unit(rng), unit(rng), unit(rng), unit(rng), unit(rng)};
    rate = deviator(rate) * (0.02 / dt);  // shear increments up to ~2 %
    rate += SymTensor::isotropic(vol / (3.0 * dt));
    try {
      point.step(rate, dt);
    } catch (const NumericalError&) {
      ++solve_failures;
      break;
    }
    const auto& p = point.pts;
    if (!std::isfinite(p.pressure[0]) || !std::isfinite(p.sound_speed[0]) || !(p.density[0] > 0.0) ||
        !(p.sound_speed[0] > 0.0) || !std::isfinite(j2(p.deviator[0])) ||
        !std::isfinite(p.specific_energy[0]) || p.damage[0] < 0.0 || p.damage[0] > 1.0)
      ++bad;
    if (p.pressure[0] < -0.2e6 / 0.75 - 1e-6) ++bad;  // never below the cut-off
    if (point.history("soil_eos_branch") == 2.0) ++cutoff;
    if (point.history("soil_eos_branch") == 1.0) ++unloading;
    if (p.pressure[0] > 1e9) ++compressed;
    max_pressure = std::max(max_pressure, p.pressure[0]);
  }
  record_check("Three-phase soil: 10,000 random strain increments (incl. +-25 % volumetric jumps)",
               "no NaN, no negative density, no failed solve, p >= cut-off",
               fmt::format("{} bad states, {} failed solves; {} steps above 1 GPa (max {:.3g} Pa), {} "
                           "unloading, {} at the cut-off",
                           bad, solve_failures, compressed, max_pressure, unloading, cutoff),
               bad == 0 && solve_failures == 0);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(solve_failures, 0);
  EXPECT_GT(compressed, 0);  // the walk did reach the high-pressure range
  EXPECT_GT(cutoff, 0);      // and the tension cut-off
  EXPECT_GT(unloading, 0);
}

// A stiff skeleton (f K_p = 3.8 GPa, the seismic-velocity calibration of the
// theory section) locks a skeleton stress above the water's spinodal tension
// K_w/k_w = 321 MPa: on unloading the pore water would be driven to -321 MPa
// while the mean stress is still compressive. The water cavitates at zero
// absolute pressure instead, so the point reaches the tension cut-off (this
// path threw NumericalError before).
TEST(ThreePhaseSoilRobustness, StiffSkeletonUnloadsToTheCutOff) {
  Parameters block = soil_eos_block();
  block.set_number("friction_modulus", 6.76e9);
  const auto eos = soil_eos(block);
  const double rho0 = eos->reference_density();
  Material m("soil", eos);
  MaterialPoints pts;
  m.setup(pts, 1);
  for (double v = 1.0; v > 0.77; v -= 0.005) {  // load to ~6.5 GPa
    pts.density[0] = rho0 / v;
    eos->evaluate(pts, MaterialContext{}, true);
  }
  const double p_max = pts.pressure[0];
  EXPECT_GT(p_max, 5e9);
  for (double v = 0.77; v < 5.0; v += 0.01) {
    pts.density[0] = rho0 / v;
    ASSERT_NO_THROW(eos->evaluate(pts, MaterialContext{}, true)) << "v = " << v;
  }
  verify({"Three-phase soil, stiff skeleton: unloading from 6.5 GPa to v = 5", "tension cut-off -p_t",
          -0.2e6 / 0.75, pts.pressure[0], 1e-9, true, "Pa"});
  EXPECT_TRUE(std::isfinite(pts.sound_speed[0]) && pts.sound_speed[0] > 0.0);
}

// Each bad block must throw an InputError that names the offending key.
void expect_refused(Parameters block, const std::string& key) {
  try {
    soil_eos(std::move(block));
    ADD_FAILURE() << "accepted bad value of " << key;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(ThreePhaseSoilRobustness, BadParametersNameTheKey) {
  {
    Parameters b = soil_eos_block();
    b.set_number("air_fraction", 0.05);  // sum 1.01
    expect_refused(b, "air_fraction");
  }
  {
    Parameters b = soil_eos_block();
    b.set_number("friction_modulus", -165e6);
    expect_refused(b, "friction_modulus");
  }
  {
    Parameters b = soil_eos_block();
    b.set_number("bond_modulus", -1.0);
    expect_refused(b, "bond_modulus");
  }
  {
    Parameters b = soil_eos_block();
    b.set_number("water_exponent", 0.0);
    expect_refused(b, "water_exponent");
  }
  {
    Parameters b = soil_eos_block();
    b.set_number("solid_sound_speed", -4500.0);
    expect_refused(b, "solid_sound_speed");
  }
  {
    Parameters b = soil_eos_block();
    b.set_number("porosity", 0.42);  // both ways of giving the fractions
    expect_refused(b, "porosity");
  }
  {
    Parameters b;
    b.set_string("type", "three_phase_soil");
    b.set_number("friction_coefficient", 0.56);
    b.set_number("friction_modulus", 165e6);
    b.set_number("bond_modulus", 20e6);
    b.set_number("porosity", 0.42);
    expect_refused(b, "saturation");
  }
  {
    Parameters s = soil_strength_block();
    s.set_number("shear_modulus", -55e6);
    EXPECT_THROW(
        {
          try {
            make_soil_drucker_prager(s);
          } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("shear_modulus"), std::string::npos);
            throw;
          }
        },
        InputError);
  }
  {
    Parameters d = soil_damage_block();
    d.set_number("strain_coefficient", 0.0);
    EXPECT_THROW(make_soil_bond_damage(d), InputError);
  }
}

// Porosity and saturation (or dry density) give the same soil as the fractions.
TEST(ThreePhaseSoilRobustness, PorosityAndSaturationDeriveTheFractions) {
  Parameters b;
  b.set_string("type", "three_phase_soil");
  b.set_number("friction_coefficient", 0.56);
  b.set_number("friction_modulus", 165e6);
  b.set_number("bond_modulus", 20e6);
  b.set_number("grain_density", 2650.0);
  b.set_number("dry_density", 1537.0);  // porosity 0.42 (Table 1: ~1530)
  b.set_number("saturation", 0.38 / 0.42);
  const auto eos = soil_eos(b);
  verify({"Three-phase soil from dry density and saturation: reference density",
          "same soil from fractions 0.58/0.38/0.04", 1917.048, eos->reference_density(), 1e-9, true,
          "kg/m^3"});
  EXPECT_NEAR(eos->constants().air.fraction, 0.04, 1e-12);
}

}  // namespace
}  // namespace camouflet::test
