// A shock of unbounded Mach number in SPH: the planar Noh problem (Noh 1987,
// J. Comput. Phys. 72, 78). Cold gas, gamma = 5/3, rho0 = 1, p0 = 1e-6 (Mach
// about 800), flows at 1 m/s onto a rigid wall at x = 0. Exact: a shock
// leaves the wall at (gamma - 1)/2 = 1/3 m/s; behind it the gas is at rest with
// rho = rho0 (gamma + 1)/(gamma - 1) = 4 and p = rho0 V^2 (1 + 1/3) = 4/3.
//
// Ahead of the shock the sound speed is 1e-3 m/s, so the linear term of the
// Monaghan viscosity (alpha c mu) has almost nothing to work with: the
// quadratic term (beta mu^2) must stop the streams. Without it (beta = 0) the
// streams interpenetrate: the shock lags, the shocked gas rings and is
// over-compressed, and each check fails (checked below on the same problem).
//
// A 2-D plane strip of 4 particle rows between symmetry planes, the wall a
// mirror plane; t = 0.6 s, the shock at 0.2 m.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

constexpr double gamma_gas = 5.0 / 3.0, t_end = 0.6, inflow = 1.0;
constexpr double rho_shocked = 4.0, p_shocked = 4.0 / 3.0, shock_speed = 1.0 / 3.0;

struct NohResult {
  double lattice_density = 0.0;   // mass of the particles in the plateau / its area
  double density = 0.0;           // mean SPH density over the shocked plateau
  double density_spread = 0.0;    // largest |rho - 4| / 4 over the plateau
  double velocity_rms = 0.0;      // m/s, RMS of v_x over the plateau (exact 0)
  double pressure = 0.0;          // Pa, mean over the plateau
  double shock_position = 0.0;    // m, farthest particle above half the shocked density jump
  double h = 0.0;
  double energy_error = 0.0;
};

NohResult run_noh(double dx, double viscosity_beta) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  const double height = 4 * dx;
  const double p0 = 1e-6;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1.0, gamma_gas, p0 / ((gamma_gas - 1.0) * 1.0)),
                     test::box_fill({0, 0, 0}, {1.0, height, 0}, dx), {-inflow, 0.0, 0.0});
  const std::vector<MirrorPlane> planes{
      {1, 0.0, PlaneKind::symmetry}, {1, height, PlaneKind::symmetry}, {0, 0.0, PlaneKind::wall}};
  SphOptions options;
  options.viscosity_beta = viscosity_beta;
  SphSystem<2> sph(model, options, planes);
  const double e0 = sph.kinetic_energy() + sph.internal_energy();
  test::run_until(sph, t_end, 0.3);

  NohResult r;
  r.h = options.smoothing_factor * dx;
  const auto& p = sph.particles();
  // The plateau: clear of the wall (wall heating, Noh 1987) and of the shock by 4 h.
  const double shock = shock_speed * t_end;
  const double from = 4 * r.h, to = shock - 4 * r.h;
  double sum_rho = 0.0, sum_p = 0.0, sum_v2 = 0.0, mass = 0.0;
  int count = 0;
  r.shock_position = 0.0;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    const double x = p.position[i][0];
    if (x > from && x < to) {
      mass += p.mass[i];
      sum_rho += p.density[i];
      sum_p += p.pressure[i];
      sum_v2 += p.velocity[i][0] * p.velocity[i][0];
      r.density_spread = std::max(r.density_spread, std::abs(p.density[i] - rho_shocked) / rho_shocked);
      ++count;
    }
    if (p.density[i] > 0.5 * (1.0 + rho_shocked) && x < 0.5) r.shock_position = std::max(r.shock_position, x);
  }
  r.lattice_density = mass / ((to - from) * height);
  r.density = sum_rho / count;
  r.pressure = sum_p / count;
  r.velocity_rms = std::sqrt(sum_v2 / count);
  r.energy_error = (sph.kinetic_energy() + sph.internal_energy() - e0) / e0;
  std::printf("Noh planar, SPH dx = %.4f, beta = %.1f: lattice rho %.4f, SPH rho %.4f (spread %.3f), p %.4f, "
              "v_rms %.4f, shock %.4f (exact %.4f), energy %.2e\n",
              dx, viscosity_beta, r.lattice_density, r.density, r.density_spread, r.pressure, r.velocity_rms, r.shock_position,
              shock, r.energy_error);
  return r;
}

}  // namespace

TEST(SphNoh, PlanarStrongShockAgainstTheExactSolution) {
  const double dx = 1.0 / 200;
  const NohResult r = run_noh(dx, SphOptions{}.viscosity_beta);
  const std::string res = "Planar Noh problem (Mach ~800), SPH 2-D strip dx = 1/200";
  // The compression of the particle lattice (mass over area) is the jump condition itself.
  test::verify({res + ": shocked density of the particle lattice (mass / area)",
                "rho0 (gamma+1)/(gamma-1) = 4 (Noh 1987)", rho_shocked, r.lattice_density, 0.03, true, "kg/m^3"});
  test::verify({res + ": shock position (half the density jump)", "V t (gamma-1)/2, tolerance 2 smoothing lengths",
                shock_speed * t_end, r.shock_position, 2 * r.h, false, "m"});
  test::verify({res + ": RMS velocity over the shocked plateau / V", "0 (gas at rest behind the shock)", 0.0,
                r.velocity_rms / inflow, 0.02, false, ""});
  // The particles' own density and pressure are noisier: four rows compressed 4:1 in x
  // rearrange into a lattice the kernel sums weigh unevenly (up to 21 % from particle to
  // particle, +5 % on the mean at 1/200 and +7 % at 1/400, measured 1 Dec 2026).
  test::verify({res + ": mean SPH density over the shocked plateau", "4 (Noh 1987), lattice noise allowed: 10 %",
                rho_shocked, r.density, 0.10, true, "kg/m^3"});
  test::verify({res + ": mean SPH pressure over the shocked plateau", "4/3 (Noh 1987), lattice noise allowed: 10 %",
                p_shocked, r.pressure, 0.10, true, "Pa"});
  EXPECT_LT(std::abs(r.energy_error), 0.01);
}

// The same problem without the quadratic viscosity term: the checks above must
// fail, or they would not notice it missing.
TEST(SphNoh, WithoutTheQuadraticViscosityTheChecksFail) {
  const NohResult r = run_noh(1.0 / 200, 0.0);
  const bool density_ok = std::abs(r.lattice_density - rho_shocked) / rho_shocked <= 0.03 &&
                          std::abs(r.density - rho_shocked) / rho_shocked <= 0.10;
  const bool shock_ok = std::abs(r.shock_position - shock_speed * t_end) <= 2 * r.h;
  const bool rest_ok = r.velocity_rms / inflow <= 0.02;
  test::record_check("Planar Noh problem, SPH dx = 1/200, quadratic viscosity removed (beta = 0)",
                     "each of the density, shock-position and rest checks of the full viscosity must fail",
                     "lattice density " + std::to_string(r.lattice_density) + ", SPH density " +
                         std::to_string(r.density) + ", shock " + std::to_string(r.shock_position) + ", v_rms " +
                         std::to_string(r.velocity_rms),
                     !density_ok && !shock_ok && !rest_ok);
  EXPECT_FALSE(density_ok);
  EXPECT_FALSE(shock_ok);
  EXPECT_FALSE(rest_ok);
}
