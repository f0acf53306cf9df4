// Gravity as a body force: a free block (no boundary) falls by g t^2 / 2 and
// the energy balance closes with gravity's work booked (the potential energy
// given up); in plane strain, r-z, 3-D, and for SPH particles.
#include <gtest/gtest.h>

#include <cmath>

#include "../sph/sph_test_models.hpp"
#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr double g = 9.81;        // m/s^2
constexpr double end_time = 0.05;  // s

struct FallResult {
  double time = 0.0;            // s
  double mean_drop = 0.0;       // m, mass-weighted mean displacement along gravity
  double worst_spread = 0.0;    // m, largest difference of a node's drop from the mean
  double energy_error = 0.0;    // the solver's relative energy error at the end
  double gravity_work = 0.0;    // J
  double kinetic = 0.0;         // J
};

template <int D>
FallResult fall(Model model) {
  test::use_threads(1);
  const int down = D - 1;  // gravity along -y in 2-D (r-z: -z), -z in 3-D
  model.run.gravity = {};
  model.run.gravity[static_cast<std::size_t>(down)] = -g;
  model.run.end_time = end_time;
  Solver<D> solver(model);
  // No landing step on the end time: the particles' centred kinetic energy assumes steady steps.
  while (solver.time() < end_time) solver.step();
  FallResult r;
  r.time = solver.time();
  double mass = 0.0;
  std::vector<double> drops;
  for (std::size_t n = 0; n < solver.node_count(); ++n) {
    const double d = -solver.displacement()[n * D + static_cast<std::size_t>(down)];
    r.mean_drop += solver.node_mass()[n] * d;
    mass += solver.node_mass()[n];
    drops.push_back(d);
  }
  if (const auto* sph = solver.particles()) {
    const auto& p = sph->particles();
    for (std::size_t k = 0; k < p.real; ++k) {
      const double d = -p.displacement[k][down];
      r.mean_drop += p.mass[k] * d;
      mass += p.mass[k];
      drops.push_back(d);
    }
  }
  r.mean_drop /= mass;
  for (double d : drops) r.worst_spread = std::max(r.worst_spread, std::abs(d - r.mean_drop));
  r.energy_error = solver.energy().relative_error;
  r.gravity_work = solver.energy_split().gravity;
  r.kinetic = solver.energy().kinetic;
  return r;
}

void check(const FallResult& r, const std::string& label) {
  const double expected = 0.5 * g * r.time * r.time;
  // The central difference integrates a constant acceleration exactly, also with varying steps.
  test::verify({label + ": drop after about 50 ms", "g t^2 / 2 (analytic)", expected, r.mean_drop, 1e-9, true, "m"});
  EXPECT_LT(r.worst_spread, 1e-9 * expected) << "a free block falls as a rigid body";
  // Gravity's work is the potential energy given up, m g h, and becomes kinetic energy.
  EXPECT_GT(r.gravity_work, 0.0);
  test::verify({label + ": energy balance with gravity's work", "closed (exact)", 0.0, r.energy_error, 1e-5,
                false, "relative"});
  EXPECT_NEAR(r.kinetic, r.gravity_work, 1e-5 * r.gravity_work);
}

}  // namespace

TEST(Gravity, FreeFallPlaneStrain) {
  Model model = test::block_model(GeometryMode::plane_strain, {{"block", 0, {0, 0, 0}, {1, 0.5, 0}, {4, 2, 1}}},
                                  test::ElasticConstants{});
  check(fall<2>(model), "Free fall of an elastic block, plane strain");
}

TEST(Gravity, FreeFallAxisymmetric) {
  // A ring r in [1, 2] m: a uniform fall along z strains nothing, whatever the ring weights.
  Model model = test::block_model(GeometryMode::axisymmetric, {{"ring", 0, {1, 0, 0}, {1, 0.5, 0}, {4, 2, 1}}},
                                  test::ElasticConstants{});
  check(fall<2>(model), "Free fall of an elastic ring, r-z");
}

TEST(Gravity, FreeFall3d) {
  Model model = test::block_model(GeometryMode::three_d, {{"block", 0, {0, 0, 0}, {1, 0.5, 0.5}, {2, 2, 2}}},
                                  test::ElasticConstants{});
  check(fall<3>(model), "Free fall of an elastic block, 3-D");
}

TEST(Gravity, FreeFallParticlesPlaneStrain) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  test::add_sph_part(model, "block", test::elastic_solid("solid", 2000.0, 2.0e9, 1.5e9),
                     test::box_fill({0, 0, 0}, {0.4, 0.2, 0}, 0.05));
  check(fall<2>(model), "Free fall of an SPH block, plane strain");
}
