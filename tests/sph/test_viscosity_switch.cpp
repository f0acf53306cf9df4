// The time-dependent artificial viscosity (SphOptions::viscosity_switch; Morris
// & Monaghan 1997, J. Comput. Phys. 136, 41-50): away from compression alpha
// decays to alpha_min with the e-folding time tau = h / (l c); under a steady
// compression -div v it relaxes to the balance of decay and source,
// (alpha_min / tau + S alpha_max) / (1 / tau + S). The elastic-wave benefit is
// measured by the join tests (tests/coupling/test_join.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

struct Block {
  Model model;
  SphOptions options;
};

Block elastic_block() {
  Block b;
  b.model.run.mode = GeometryMode::plane_strain;
  test::add_sph_part(b.model, "solid", test::elastic_solid("solid", 2000.0, 2e9, 1.5e9),
                     test::box_fill({0, 0, 0}, {0.2, 0.2, 0}, 0.01));
  b.options.viscosity_switch = true;
  b.options.viscosity_alpha = 1.0;
  b.options.viscosity_alpha_min = 0.1;
  b.options.viscosity_switch_decay = 0.2;
  return b;
}

// The particle nearest the block's centre.
std::size_t centre_particle(const SphSystem<2>& sph) {
  std::size_t best = 0;
  double best_d = 1e300;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    const auto& x = sph.particles().position[i];
    const double d = std::hypot(x[0] - 0.1, x[1] - 0.1);
    if (d < best_d) best_d = d, best = i;
  }
  return best;
}

}  // namespace

TEST(SphViscositySwitch, DecaysToTheFloorWithTimeConstantTau) {
  Block b = elastic_block();
  SphSystem<2> sph(b.model, b.options);
  auto& p = sph.particles();
  sph.update_state(1e-12, 1e-12);  // wave speeds and smoothing lengths of the material state
  const std::size_t i = centre_particle(sph);
  for (std::size_t k = 0; k < sph.size(); ++k) p.viscosity_alpha[k] = 1.0;  // as after a shock
  const double tau = p.smoothing_length[i] / (0.2 * p.wave_speed[i]);
  // Two steps of tau / 2 at rest: alpha - alpha_min falls by e^-1.
  sph.update_state(0.5 * tau, 0.5 * tau);
  sph.update_state(0.5 * tau, tau);
  test::verify({"SPH viscosity switch at rest: alpha after one decay time tau = h / (0.2 c)",
                "alpha_min + (1 - alpha_min) / e (Morris & Monaghan 1997)", 0.1 + 0.9 * std::exp(-1.0),
                p.viscosity_alpha[i], 1e-6, true, "-"});
  EXPECT_GT(p.viscosity_alpha[i], 0.1);
}

TEST(SphViscositySwitch, RisesUnderCompressionToTheSourceBalance) {
  Block b = elastic_block();
  SphSystem<2> sph(b.model, b.options);
  auto& p = sph.particles();
  sph.update_state(1e-12, 1e-12);
  const std::size_t i = centre_particle(sph);
  // Uniform compression v = -g (x - 0.1): -div v = g (interior particles, to the lattice normalisation).
  const double g = 200.0;  // 1/s
  for (std::size_t k = 0; k < sph.size(); ++k) p.velocity[k] = Vec<2>{{-g * (p.position[k][0] - 0.1), 0.0}};
  const double tau = p.smoothing_length[i] / (0.2 * p.wave_speed[i]);
  const double dt = 2e-6;  // s, a small strain (4e-4)
  sph.update_state(dt, dt);
  const double source = -p.strain_rate[i].trace();
  const double a = 0.1 / tau + source * 1.0, rate = 1.0 / tau + source;
  const double expected = a / rate + (0.1 - a / rate) * std::exp(-rate * dt);
  test::verify({"SPH viscosity switch under uniform compression g = 200/s: alpha after one step",
                "exact solution of d alpha/dt = -(alpha - 0.1)/tau + S (1 - alpha)", expected,
                p.viscosity_alpha[i], 1e-6, true, "-"});
  EXPECT_NEAR(source, g, 0.03 * g);  // the switch sees the compression
  EXPECT_GT(p.viscosity_alpha[i], 0.1 + 1e-4);
}
