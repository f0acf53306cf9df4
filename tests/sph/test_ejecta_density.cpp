// Ejecta: particles expanded past the smoothing-length cap
// (docs/theory/sph.md, "Ejecta"). In the volume form particle i's continuity
// weighs neighbour j by its volume V_j = m_j / eta_j. Once h stops at
// h_max_factor h0, nothing ties V_j to the kernel any more: two ejecta that
// drift apart slowly stay in each other's support, each one's expansion
// raises the other's rate, d(1/V)/dt = -const, and V -> infinity in finite
// time (the coarse buried case with max_dt = 1.5e-6 stopped on it at 17.4 ms
// with "density 0"). The sums now weigh a point with at most V_q = 1 / W(0, h)
// (eta_q = max(eta, m W(0, h)), its own term of the summation density); its
// own density keeps following the continuity equation.
//
// With V_q and h constant the continuity equation integrates exactly along
// any path: d ln eta_i/dt = sum_j V_q,j v_ij . grad_i W_ij = d/dt sum_j
// V_q,j W(|x_i - x_j|, h), so ln(eta_i(t) / eta_i(0)) = sum_j V_q,j
// (W_ij(t) - W_ij(0)), mirror images across the axis included. The tests
// compare with that, from states the coarse case reached.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

// Puts particle i into an expanded state: planar density eta, reference eta0, mass m, smoothing
// length at the cap h_max_factor x h0, position x and velocity v.
template <int D>
void place(SphSystem<D>& sph, std::size_t i, Vec<D> x, Vec<D> v, double eta, double eta0, double mass,
           double h0) {
  auto& p = sph.particles();
  p.position[i] = x;
  p.velocity[i] = v;
  p.planar_density[i] = eta;
  // The density the material saw last (no p dV work from the set-up itself).
  p.density[i] = eta / (sph.mode() == GeometryMode::axisymmetric ? 2.0 * std::numbers::pi * x[0] : 1.0);
  p.reference_planar_density[i] = eta0;
  p.mass[i] = mass;
  p.reference_smoothing_length[i] = h0;
  p.smoothing_length[i] = sph.options().h_max_factor * h0;
}

// sum_j V_q,j W(|x_i - x_j|, h_ij) over the other particles and the mirror images across r = 0
// of all (r-z), V_q,j = 1 / W(0, h_j) (all limited): the potential whose change is ln eta_i.
template <int D>
double volume_weighted_kernel_sum(const SphSystem<D>& sph, std::size_t i, bool axisymmetric) {
  const auto& p = sph.particles();
  double sum = 0.0;
  for (std::size_t j = 0; j < sph.size(); ++j) {
    const double volume = 1.0 / sph.kernel().value(0.0, p.smoothing_length[j]);
    const double h = 0.5 * (p.smoothing_length[i] + p.smoothing_length[j]);
    if (j != i) sum += volume * sph.kernel().value(norm(p.position[i] - p.position[j]), h);
    if (axisymmetric) {
      Vec<D> image = p.position[j];
      image[0] = -image[0];
      sum += volume * sph.kernel().value(norm(p.position[i] - image), h);
    }
  }
  return sum;
}

// Fixed-step leapfrog of the solver (kick over the mean of the half steps).
template <int D>
void run_fixed(SphSystem<D>& sph, double dt, long cycles, double t0 = 0.0) {
  double t = t0;
  for (long c = 0; c < cycles; ++c) {
    sph.kick(c == 0 ? 0.5 * dt : dt);
    sph.drift(dt);
    t += dt;
    sph.update_state(dt, t);
    sph.compute_accelerations();
  }
}

}  // namespace

TEST(SphEjecta, SeparatingExpandedPairKeepsAFiniteDensity) {
  // Two particles of pressure-free material (ideal gas at e = 0: no force between them, they
  // fly apart at 2 x 10 m/s), 0.1 m spacing, eta0 = 1800 kg/m^3, expanded to eta0 / 200 (as
  // the ejecta of the coarse case) with h at the cap 4 h0 = 0.48 m, 0.24 m apart. Before the
  // limit: eta = eta_start - m (W(r0) - W(r)) reached 0 before they parted (m W(r0) = 2.8 eta).
  omp_set_num_threads(1);
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  test::add_sph_part(model, "dust", test::ideal_gas("dust", 1800.0, 1.4, 0.0),
                     test::box_fill({0, 0, 0}, {0.2, 0.1, 0}, 0.1));
  ASSERT_EQ(model.particles.count(), 2u);
  SphSystem<2> sph(model, SphOptions{});
  const double eta0 = 1800.0, mass = 1800.0 * 0.01, h0 = 0.12, eta_start = eta0 / 200.0;
  place<2>(sph, 0, Vec<2>{{0.0, 0.0}}, Vec<2>{{-10.0, 0.0}}, eta_start, eta0, mass, h0);
  place<2>(sph, 1, Vec<2>{{0.24, 0.0}}, Vec<2>{{10.0, 0.0}}, eta_start, eta0, mass, h0);
  const double potential_start = volume_weighted_kernel_sum(sph, 0, false);
  sph.compute_accelerations();
  // 0.05 s in steps of 1e-4 s: apart beyond 2 h = 0.96 m after 0.036 s.
  run_fixed(sph, 1e-4, 500);
  const auto& p = sph.particles();
  ASSERT_GT(norm(p.position[1] - p.position[0]), 2.0 * 0.48);
  EXPECT_EQ(sph.volume_limited_count(), 2u);
  // ln(eta_end / eta_start) = -V_q W(0.24 m, 0.48 m) = -W(0.24 m, 0.48 m) / W(0, 0.48 m) = -0.719.
  test::verify({"SPH ejecta pair expanded past the h cap, flying apart: density once out of reach",
                "eta_start exp(-W(r0, h_max) / W(0, h_max)), continuity integrated exactly",
                eta_start * std::exp(-potential_start), p.planar_density[0], 1e-3, true, "kg/m^3"});
  EXPECT_DOUBLE_EQ(p.planar_density[0], p.planar_density[1]);
  // Out of reach the density no longer changes, the velocities never did (no pressure, no strength).
  const double eta_apart = p.planar_density[0];
  run_fixed(sph, 1e-4, 100, 0.05);
  EXPECT_EQ(p.planar_density[0], eta_apart);
  EXPECT_EQ(p.velocity[0][0], -10.0);
  EXPECT_EQ(p.velocity[1][0], 10.0);
}

TEST(SphEjecta, AxisEjectaOfTheCoarseCaseFlyOn) {
  // Particles 334, 363 and 364 of cases/wang2005/coarse.toml with max_dt = 1.5e-6 at
  // t = 17.25 ms (r-z, seismic sandy clay, 11 m above the ground at 630-665 m/s, all three
  // expanded past the cap, their only neighbours each other and their mirror images). Before
  // the limit the run stopped 0.155 ms later: V_334 and V_364 grew as 1/(t* - t) to 1e11 m^2,
  // then particle 334's density underflowed to 0 in the soil EOS. Now they fly on for 2 ms and
  // each density follows the exact integral of the continuity equation.
  omp_set_num_threads(1);
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  test::add_sph_part(
      model, "soil",
      make_material("soil", "sandy_clay_wang2005_seismic", {}, Parameters{}, Parameters{}, Parameters{}),
      test::box_fill({0, 0, 0}, {0.3, 0.1, 0}, 0.1));
  ASSERT_EQ(model.particles.count(), 3u);
  SphSystem<2> sph(model, SphOptions{});
  place<2>(sph, 0, Vec<2>{{0.0488, 10.9023}}, Vec<2>{{0.0, 652.25}}, 0.3882, 1807.0, 18.07, 0.12);
  place<2>(sph, 1, Vec<2>{{0.8874, 11.2911}}, Vec<2>{{48.02, 665.25}}, 2.315, 602.3, 6.023, 0.12);
  place<2>(sph, 2, Vec<2>{{0.4071, 10.6459}}, Vec<2>{{12.58, 631.89}}, 0.352, 1807.0, 18.07, 0.12);
  // The material state at these densities (the soil cannot pull: its stress vanishes).
  sph.update_state(1e-12, 0.0);
  double potential_start[3], eta_start[3];
  for (std::size_t i = 0; i < 3; ++i) {
    potential_start[i] = volume_weighted_kernel_sum(sph, i, true);
    eta_start[i] = sph.particles().planar_density[i];
  }
  sph.compute_accelerations();
  ASSERT_NO_THROW(run_fixed(sph, 1.5e-6, 1333));
  const auto& p = sph.particles();
  EXPECT_EQ(sph.volume_limited_count(), 3u);
  const char* names[3] = {"334 (on the axis)", "363", "364"};
  for (std::size_t i = 0; i < 3; ++i) {
    const double expected =
        eta_start[i] * std::exp(volume_weighted_kernel_sum(sph, i, true) - potential_start[i]);
    test::verify(
        {fmt::format("SPH ejecta of the coarse buried case (r-z, soil), particle {}: density after 2 ms",
                     names[i]),
         "eta_start exp(sum_j V_q,j dW_ij), continuity integrated exactly", expected, p.planar_density[i],
         1e-3, true, "kg/m^2"});
  }
}

TEST(SphEjecta, ExpandedGasCloudConservesEnergy) {
  // A 3 x 3 cloud of ideal gas (gamma 1.4, e = 1e5 J/kg) expanded to eta0 / 100 with h at the
  // cap, particles 0.5 m apart (h0 = 0.12 m), let go for 10 ms: every pair weight is the limited
  // volume. The
  // momentum sum uses the same weights as the continuity equation, so the pressure work is
  // the internal energy lost (were the momentum sum to keep V = m / eta, twice V_q, the
  // kinetic energy gained would be twice the internal energy lost).
  omp_set_num_threads(1);
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1.0, 1.4, 1e5),
                     test::box_fill({0, 0, 0}, {0.3, 0.3, 0}, 0.1));
  ASSERT_EQ(model.particles.count(), 9u);
  SphSystem<2> sph(model, SphOptions{});
  for (std::size_t i = 0; i < 9; ++i)
    place<2>(sph, i, Vec<2>{{0.5 * static_cast<double>(i % 3), 0.5 * static_cast<double>(i / 3)}}, Vec<2>{},
             1.0 / 100.0, 1.0, 0.01, 0.12);
  sph.update_state(1e-12, 0.0);
  const double e0 = sph.internal_energy() + sph.kinetic_energy();
  double dt_last = 0.0;
  test::run_leapfrog_until(sph, 1e-2, 0.25, &dt_last);  // 42 cycles
  const double kinetic = test::synchronised_kinetic_energy(sph, dt_last);
  ASSERT_GT(kinetic, 0.05 * e0);  // the cloud has done work
  EXPECT_EQ(sph.volume_limited_count(), 9u);
  test::verify({"SPH gas cloud expanded past the h cap (3 x 3, plane, eta0 / 100): kinetic + internal energy",
                "conserved (pair weights of momentum and continuity equal)", e0,
                sph.internal_energy() + kinetic, 0.005, true, "J"});
}
