// Robustness of the RHT + P-alpha concrete: random admissible strain
// increments on a batch, and bad parameters refused with the key named.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "common/verification.hpp"
#include "concrete_fixture.hpp"

using namespace camouflet;
using camouflet::test::verify;

namespace {

bool finite(const SymTensor& s) {
  return std::isfinite(s.xx) && std::isfinite(s.yy) && std::isfinite(s.zz) && std::isfinite(s.xy) &&
         std::isfinite(s.yz) && std::isfinite(s.zx);
}

// The key an InputError names when the concrete is built with one override.
std::string refused_key(const std::string& block, const std::string& key, double value) {
  Parameters eos, strength;
  (block == "eos" ? eos : strength).set_number(key, value, SourceLocation{"case.toml", 7, 3, key});
  try {
    test::concrete_35mpa(eos, strength);
  } catch (const InputError& e) {
    return e.where().key;
  }
  return "<accepted>";
}

}  // namespace

TEST(ConcreteRobustness, RandomStrainIncrementsNeverBreakTheUpdate) {
  const auto concrete = test::concrete_35mpa();
  constexpr std::size_t points = 400, steps = 25;  // 10,000 increments; > 256 points: the threaded loops
  MaterialPoints pts;
  concrete->setup(pts, points);
  const std::size_t alpha_slot = pts.history.slot("plastic_distension");
  std::mt19937_64 rng(20051);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> log_dt(-7.0, -3.0), log_size(-6.0, -2.5);
  std::vector<double> alpha_before(points);
  int bad = 0;
  double time = 0.0;
  for (std::size_t k = 0; k < steps; ++k) {
    const double dt = std::pow(10.0, log_dt(rng));
    for (std::size_t i = 0; i < points; ++i) {
      const double size = std::pow(10.0, log_size(rng));
      SymTensor de{unit(rng), unit(rng), unit(rng), unit(rng), unit(rng), unit(rng)};
      de *= size;
      // Admissible: keep the density between 0.8 rho_0 and a 6 GPa compaction.
      const double rho_new = pts.density[i] * std::exp(-de.trace());
      if (rho_new < 0.8 * 2314.0 || rho_new > 3100.0) de -= SymTensor::isotropic(2.0 * de.trace() / 3.0);
      pts.density_previous[i] = pts.density[i];
      pts.density[i] *= std::exp(-de.trace());
      pts.strain_rate[i] = de * (1.0 / dt);
      pts.spin[i] = Spin{0.3 * unit(rng) * size / dt, 0.0, 0.0};
      alpha_before[i] = pts.history.column(alpha_slot)[i];
    }
    time += dt;
    ASSERT_NO_THROW(concrete->update(pts, MaterialContext{dt, time})) << "step " << k;
    for (std::size_t i = 0; i < points; ++i) {
      const bool ok = std::isfinite(pts.pressure[i]) && finite(pts.deviator[i]) &&
                      std::isfinite(pts.specific_energy[i]) && std::isfinite(pts.sound_speed[i]) &&
                      pts.sound_speed[i] > 0.0 && pts.damage[i] >= 0.0 && pts.damage[i] <= 1.0 &&
                      pts.history.column(alpha_slot)[i] <= alpha_before[i] &&
                      pts.history.column(alpha_slot)[i] >= 1.0;
      if (!ok) ++bad;
    }
  }
  verify({"RHT + P-alpha: 10,000 random admissible strain increments",
          "no NaN, damage in [0,1], alpha_p non-increasing", 0.0, static_cast<double>(bad), 0.0, false,
          "bad states"});
}

TEST(ConcreteRobustness, BadParametersNameTheirKey) {
  EXPECT_EQ(refused_key("eos", "solid_density", 2000.0), "solid_density");
  EXPECT_EQ(refused_key("eos", "compaction_pressure", 1e6), "compaction_pressure");
  EXPECT_EQ(refused_key("eos", "porous_sound_speed", 5000.0), "porous_sound_speed");
  EXPECT_EQ(refused_key("eos", "a1", -1.0), "a1");
  EXPECT_EQ(refused_key("strength", "tensile_strength", 50e6), "tensile_strength");
  EXPECT_EQ(refused_key("strength", "tensile_meridian_ratio", 1.5), "tensile_meridian_ratio");
  EXPECT_EQ(refused_key("strength", "residual_shear_modulus", 20e9), "residual_shear_modulus");
  EXPECT_EQ(refused_key("strength", "compresive_strength", 30e6), "compresive_strength");  // misspelt
  EXPECT_EQ(refused_key("strength", "shear_modulus", 0.0), "shear_modulus");
}
