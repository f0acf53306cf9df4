// Velocity gradient of a linear field, with and without the kernel-gradient
// correction; conservation properties of the sums (unit tests).
#include <gtest/gtest.h>

#include <random>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

// A graded, jittered 2-D set in a box; velocities v = A x + b.
Model graded_gas_block() {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  ParticleFillSpec spec = test::box_fill({0, 0, 0}, {1, 1, 0}, 0.02);
  spec.graded = true;
  spec.grading_point = {0.3, 0.4, 0};
  spec.grading_ratio = 1.08;
  spec.max_spacing = 0.06;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1.0, 1.4, 1.0), spec);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (std::size_t i = 0; i < model.particles.count(); ++i)
    for (int d = 0; d < 2; ++d)
      model.particles.coordinates[2 * i + d] += jitter(rng) * model.particles.spacing[i];
  return model;
}

double worst_strain_rate_error(bool correction, bool interior_only) {
  Model model = graded_gas_block();
  SphOptions options;
  options.kernel_correction = correction;
  SphSystem<2> sph(model, options);
  const double a[2][2] = {{0.3, -0.7}, {1.1, -0.2}};
  auto& p = sph.particles();
  for (std::size_t i = 0; i < sph.size(); ++i)
    for (int r = 0; r < 2; ++r)
      p.velocity[i][r] = 0.05 + a[r][0] * p.position[i][0] + a[r][1] * p.position[i][1];
  sph.update_state(1e-9, 1e-9);
  double worst = 0.0;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    const auto& x = p.position[i];
    const double margin = 3.0 * p.smoothing_length[i];
    if (interior_only && (x[0] < margin || x[0] > 1 - margin || x[1] < margin || x[1] > 1 - margin)) continue;
    const auto& d = p.strain_rate[i];
    worst = std::max({worst, std::abs(d.xx - a[0][0]), std::abs(d.yy - a[1][1]),
                      std::abs(d.xy - 0.5 * (a[0][1] + a[1][0])),
                      std::abs(p.spin[i].xy - 0.5 * (a[0][1] - a[1][0]))});
  }
  return worst;
}

}  // namespace

TEST(SphKinematics, CorrectedGradientIsExactForLinearField) {
  // With the correction every particle, boundary ones included, gets the exact gradient.
  test::verify({"SPH velocity gradient with kernel-gradient correction, graded jittered set: worst error",
                "exact for a linear velocity field (Randles & Libersky 1996)", 0.0,
                worst_strain_rate_error(true, false), 1e-9, false, "1/s"});
  // Without it the interior is close but not exact; at the free boundary it is wrong (so the test can fail).
  const double plain_interior = worst_strain_rate_error(false, true);
  EXPECT_LT(plain_interior, 0.2);
  EXPECT_GT(worst_strain_rate_error(false, false), 0.1);
}

TEST(SphKinematics, PairForcesConserveMomentumOnGradedParticles) {
  // Random velocities and a gas under pressure: the symmetric pair form with
  // h_ij = (h_i + h_j)/2 keeps the total momentum rate at round-off.
  Model model = graded_gas_block();
  SphSystem<2> sph(model, SphOptions{});
  auto& p = sph.particles();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < sph.size(); ++i) p.velocity[i] = Vec<2>{{u(rng), u(rng)}};
  sph.update_state(1e-4, 1e-4);
  sph.compute_accelerations();
  Vec<2> rate{};
  double scale = 0.0;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    rate += p.acceleration[i] * p.mass[i];
    scale += p.mass[i] * norm(p.acceleration[i]);
  }
  EXPECT_LT(norm(rate), 1e-12 * scale);
}

TEST(SphKinematics, ThreeDimensionalCorrectedGradientAndConservation) {
  // A jittered 3-D gas cube: the corrected velocity gradient is exact for a
  // linear field, and the pair forces conserve momentum.
  Model model;
  model.run.mode = GeometryMode::three_d;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1.0, 1.4, 1.0),
                     test::box_fill({0, 0, 0}, {1, 1, 1}, 0.1));
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  for (auto& c : model.particles.coordinates) c += jitter(rng);
  SphOptions options;
  options.kernel_correction = true;
  SphSystem<3> sph(model, options);
  auto& p = sph.particles();
  const double a[3][3] = {{0.3, -0.7, 0.2}, {1.1, -0.2, 0.4}, {-0.5, 0.6, 0.1}};
  for (std::size_t i = 0; i < sph.size(); ++i)
    for (int r = 0; r < 3; ++r)
      p.velocity[i][r] = a[r][0] * p.position[i][0] + a[r][1] * p.position[i][1] + a[r][2] * p.position[i][2];
  sph.update_state(1e-9, 1e-9);
  double worst = 0.0;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    const auto& x = p.position[i];
    if (x[0] < 0.25 || x[0] > 0.75 || x[1] < 0.25 || x[1] > 0.75 || x[2] < 0.25 || x[2] > 0.75) continue;
    const auto& d = p.strain_rate[i];
    worst = std::max({worst, std::abs(d.xx - a[0][0]), std::abs(d.yy - a[1][1]), std::abs(d.zz - a[2][2]),
                      std::abs(d.xy - 0.5 * (a[0][1] + a[1][0])), std::abs(d.yz - 0.5 * (a[1][2] + a[2][1])),
                      std::abs(d.zx - 0.5 * (a[2][0] + a[0][2])),
                      std::abs(p.spin[i].xy - 0.5 * (a[0][1] - a[1][0]))});
  }
  test::verify(
      {"SPH velocity gradient with kernel-gradient correction, 3-D jittered cube (inner half; corner "
       "particles fall back to B = I): worst error",
       "exact for a linear velocity field (Randles & Libersky 1996)", 0.0, worst, 1e-9, false, "1/s"});
  sph.compute_accelerations();
  Vec<3> rate{};
  double scale = 0.0;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    rate += p.acceleration[i] * p.mass[i];
    scale += p.mass[i] * norm(p.acceleration[i]);
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(norm(rate), 1e-12 * scale);
}
