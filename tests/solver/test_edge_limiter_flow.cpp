// The edge viscosity in a smooth flow, with and without its limiter ([run.viscosity] limiter =
// "csw"; fem/edge_viscosity.hpp). A block of cold gas in a uniform pure shear v = k (x, -y):
// no volume change, so a scalar q does nothing, but every edge along y closes. Unlimited, each
// such edge of length l carries F = rho (c_q^2 k l + c_l c) (l / 2) k l, and the block heats at
// sum over elements of rho (c_q^2 k l + c_l c) k^2 l^3: a shear viscosity the flow of a soil
// feels as a drag (docs/buried-structure.md, "The free field's outward flow"). Limited, the
// velocity gradient is the same along every mesh line, psi = 1 on every edge, and no heat.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "../sph/sph_test_models.hpp"
#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr int cells = 10;
constexpr double side = 1.0, cell = side / cells, rate = 2.0;  // m, m, 1/s
constexpr double dt = 1e-4;                                    // s
constexpr int cycles = 20;

// The viscous heat (J/m) after `cycles` fixed steps.
double shear_heat(bool limiter) {
  test::use_threads(1);
  Model model = test::fixed_step_model(GeometryMode::plane_strain, dt, cycles);
  model.run.viscosity_form = ViscosityForm::edge;
  model.run.viscosity_limiter = limiter;
  model.materials.push_back({"gas", test::ideal_gas("gas", 1.0, 1.4, 1e-10), {}});  // c ~ 1e-5 m/s
  Part part;
  part.name = "gas";
  part.material = 0;
  model.parts.push_back(part);
  add_block(model.mesh, {"gas", 0, {-0.5, -0.5, 0}, {side, side, 0}, {cells, cells, 1}});
  Solver<2> solver(model);
  const auto& x = solver.position();
  std::vector<double> v(solver.velocity().size());
  for (std::size_t n = 0; n < v.size() / 2; ++n) v[2 * n] = rate * x[2 * n], v[2 * n + 1] = -rate * x[2 * n + 1];
  solver.set_initial_velocity(v);
  while (solver.cycle() < cycles) solver.step();
  return solver.energy().viscous;
}

}  // namespace

TEST(EdgeLimiterFlow, PureShearHeatsOnlyWithoutTheLimiter) {
  const double without = shear_heat(false), with = shear_heat(true);
  // Unlimited: two closing edges per element, the quadratic term (c ~ 0); the first step's old
  // force is zero (half a step's heat less), and the block deforms by k t = 0.4 % meanwhile.
  const double power = cells * cells * 1.0 * 1.5 * 1.5 * rate * rate * rate * std::pow(cell, 4);  // W/m
  const double expected = power * dt * (cycles - 0.5);
  test::verify({"Edge viscosity, pure shear v = k (x, -y) of a 10 x 10 quad block of cold gas, 20 steps: heat "
                "without the limiter",
                "sum over elements of rho c_q^2 k^3 l^4 dt (two closing edges per element)", expected, without, 0.02,
                true, "J/m"});
  test::record_check("Edge viscosity with the CSW limiter, the same pure shear: heat",
                     "below 1e-12 of the unlimited heat (psi = 1 on every edge of a linear field)",
                     fmt::format("{:.3e} J/m against {:.3e}", with, without), std::abs(with) < 1e-12 * without);
  EXPECT_LT(std::abs(with), 1e-12 * without);
}
