// The first time step votes with the initial velocities: a cold, soft medium
// set moving fast has c << |v|, so l/c alone would take a first step many
// times the stable one and invert the mesh at cycle 1.
#include <gtest/gtest.h>

#include <cmath>

#include "../sph/sph_test_models.hpp"
#include "common/fem_models.hpp"
#include "solver/solver.hpp"

namespace camouflet {
namespace {

constexpr double gas_density = 1.2;       // kg/m^3
constexpr double gas_sound_speed = 340.0;  // m/s
constexpr double inflow_speed = 2000.0;   // m/s, about Mach 6 into the wall

// Cold air as a linear fluid (no shear), K = rho c^2.
test::ElasticConstants cold_gas() {
  test::ElasticConstants c;
  c.density = gas_density;
  c.bulk_modulus = gas_density * gas_sound_speed * gas_sound_speed;
  c.shear_modulus = 0.0;
  return c;
}

TEST(FirstStep, ElementsVoteWithTheInitialVelocity) {
  test::use_threads(1);
  // 20 x 2 cells of 5 mm, all moving at 2000 m/s in +x onto a wall at x = 0.1 m.
  Model model = test::block_model(GeometryMode::plane_strain, {{"gas", 0, {0, 0, 0}, {0.1, 0.01, 0}, {20, 2, 1}}},
                                  cold_gas());
  model.parts[0].initial_velocity = {inflow_speed, 0.0, 0.0};
  model.boundaries.push_back(test::velocity("gas.xmax", 0, 0.0));
  model.run.cfl = 0.5;
  model.run.end_time = 1.0;
  Solver<2> solver(model);
  const double l = 0.005;  // m, the square cells' characteristic length
  const double expected = model.run.cfl * l / (gas_sound_speed + inflow_speed);
  EXPECT_NEAR(solver.next_dt(), expected, 0.01 * expected)
      << "first step " << solver.next_dt() << " s, l/c alone would give " << model.run.cfl * l / gas_sound_speed;
  EXPECT_NE(solver.time_step_limit().reason.find("l/(c+|v|)"), std::string::npos);
  // The first cycles run: no element inverts against the wall.
  for (int k = 0; k < 20; ++k) ASSERT_NO_THROW(solver.step()) << "cycle " << k;
}

TEST(FirstStep, ParticlesVoteWithTheInitialVelocity) {
  test::use_threads(1);
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.run.cfl = 0.5;
  model.run.end_time = 1.0;
  const double dx = 0.005;  // m
  // Ideal gas, gamma 1.4, with c = sqrt(gamma (gamma - 1) e) = 340 m/s.
  const double gamma = 1.4;
  const double e = gas_sound_speed * gas_sound_speed / (gamma * (gamma - 1.0));
  test::add_sph_part(model, "gas", test::ideal_gas("gas", gas_density, gamma, e),
                     test::box_fill({0.0, 0.0, 0.0}, {0.1, 0.05, 0.0}, dx), {inflow_speed, 0.0, 0.0});
  Solver<2> solver(model);
  const TimeStepLimit& limit = solver.time_step_limit();
  ASSERT_NE(limit.reason.find("particle"), std::string::npos) << limit.reason;
  // h/(c + |v| + viscosity): no compression yet, so the viscosity adds 0.6 alpha c.
  const sph::SphOptions options = model.sph;
  const double h = options.smoothing_factor * dx;
  const double expected =
      model.run.cfl * h / (gas_sound_speed + inflow_speed + 0.6 * options.viscosity_alpha * gas_sound_speed);
  EXPECT_NEAR(solver.next_dt(), expected, 0.01 * expected) << limit.reason;
}

}  // namespace
}  // namespace camouflet
