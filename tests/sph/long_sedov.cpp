// Sedov-Taylor point blast (issue 3, must-show 3), spherical, in 2-D
// axisymmetric r-z, run through the solver's cycle (Solver<2>): gamma = 1.4,
// rho0 = 1, E = 1 deposited in the particles within 2.5 spacings of the
// origin, cold gas (p = 0) elsewhere. The shock radius follows
//   R(t) = xi0 (E t^2 / rho0)^(1/5),  xi0 = 1.033 for gamma = 1.4
// (Taylor 1950, Proc. R. Soc. A 201, 159; Sedov 1959). The shock is
// located at the peak of the radially binned density.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/verification.hpp"
#include "solver/solver.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;

TEST(SphSedov, AxisymmetricSphericalBlastShockRadiusAndEnergy) {
  const double gamma = 1.4, rho0 = 1.0, energy = 1.0, xi0 = 1.033, dx = 0.02;
  const double t_end = 0.15;
  const double r_exact = xi0 * std::pow(energy * t_end * t_end / rho0, 0.2);

  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  model.run.cfl = 0.3;
  model.sph.set_number("smoothing_factor", 1.5);
  model.sph.set_bool("kernel_correction", true);
  // Cold gas everywhere first; the hot particles are moved to a second part below.
  test::add_sph_part(model, "cold", test::ideal_gas("cold", rho0, gamma, 0.0),
                     test::box_fill({0, -1, 0}, {1, 1, 0}, dx));
  const double r_hot = 2.5 * dx;
  double hot_mass = 0.0;
  std::vector<std::size_t> hot;
  for (std::size_t i = 0; i < model.particles.count(); ++i) {
    const double r = std::hypot(model.particles.coordinates[2 * i], model.particles.coordinates[2 * i + 1]);
    if (r < r_hot) hot.push_back(i), hot_mass += rho0 * model.particles.volume[i];
  }
  ASSERT_FALSE(hot.empty());
  model.materials.push_back({"hot", test::ideal_gas("hot", rho0, gamma, energy / hot_mass), {}});
  Part hot_part;
  hot_part.name = "hot";
  hot_part.kind = PartKind::sph;
  hot_part.material = 1;
  model.parts.push_back(hot_part);
  for (auto i : hot) model.particles.particle_part[i] = 1;

  omp_set_num_threads(1);
  Solver<2> solver(model);
  const double e0 = solver.energy().initial_total;
  while (solver.time() < t_end * (1 - 1e-12)) {
    solver.limit_next_step(t_end - solver.time());
    solver.step();
  }
  solver.step();  // the energy balance is evaluated at the start of a step (time-centred)
  const auto& p = solver.particles()->particles();
  // Radially binned mean density; the shock is at the densest bin.
  const int bins = 100;
  std::vector<double> mass(bins, 0.0), volume(bins, 0.0);
  for (std::size_t i = 0; i < solver.particles()->size(); ++i) {
    const double r = std::hypot(p.position[i][0], p.position[i][1]);
    const int b = static_cast<int>(r / 1.0 * bins);
    if (b >= bins) continue;
    mass[b] += p.density[i] * p.mass[i] / p.density[i];
    volume[b] += p.mass[i] / p.density[i];
  }
  int peak = 0;
  for (int b = 1; b < bins; ++b)
    if (volume[b] > 0 && mass[b] / volume[b] > mass[peak] / std::max(volume[peak], 1e-300)) peak = b;
  const double r_shock = (peak + 0.5) / bins;
  const double peak_density = mass[peak] / volume[peak];
  test::verify({"Sedov-Taylor blast, SPH r-z (dx = 0.02, t = 0.15): shock radius (peak of binned density)",
                "R = xi0 (E t^2 / rho0)^(1/5), xi0 = 1.033 (Taylor 1950)", r_exact, r_shock, 0.03, true,
                "m"});
  const double e_end = solver.energy().kinetic + solver.energy().internal;
  test::verify({"Sedov-Taylor blast, SPH r-z: total energy at t_end", "E deposited (conserved)", e0, e_end,
                0.01, true, "J"});
  test::record_check("Sedov-Taylor blast, SPH r-z: peak density",
                     "strong-shock limit (gamma+1)/(gamma-1) rho0 = 6",
                     "peak binned density " + std::to_string(peak_density), peak_density > 2.5);
  std::printf("Sedov r-z: R %.4f (exact %.4f), peak rho %.3f, E %.6f -> %.6f, cycles %ld\n", r_shock, r_exact,
              peak_density, e0, e_end, static_cast<long>(solver.cycle()));
}
