// Tensile stability: a free elastic plate (plane
// strain, 60 x 6 particles) vibrating in its first axial mode,
// v_x = a c_plate cos(pi x / L), goes through compression and tension every
// period T = 2 L / c_plate. Without a remedy the tensile instability (Swegle,
// Hicks & Attaway 1995, JCP 116, 123) clumps particles in the first tension
// phase (in a larger plate, 100 x 10, the vibration is then lost within a
// period: kinetic energy back to < 0.15 E0); with the
// artificial stress (Gray, Monaghan & Swift 2001) the lattice keeps its
// spacing, the vibration survives several periods and kinetic + internal
// energy (the artificial stress's work booked, sph_motion.cpp) is conserved.
//
// Measured: the smallest pair distance over the run (clumping), the largest
// kinetic energy in the last period relative to the initial (the mode kept),
// and the largest |E - E0| / E0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

constexpr double rho = 1000.0, shear = 4e6, bulk = 20e6 / 3.0;  // Poisson's ratio 0.25
constexpr double length = 0.6, height = 0.06, dx = 0.01, amplitude = 0.05, periods = 2.5;

struct PlateResult {
  double min_pair = 0.0;      // smallest pair distance over the run / dx
  double kept_kinetic = 0.0;  // largest kinetic energy in the last period / E0
  double energy_error = 0.0;  // largest |E - E0| / E0
};

double min_pair_distance(const SphSystem<2>& sph) {
  const auto& p = sph.particles();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sph.size(); ++i)
    for (const auto j : sph.neighbours().neighbours(i)) {
      if (j >= sph.size()) continue;
      const Vec<2> d = p.position[i] - p.position[j];
      best = std::min(best, std::sqrt(dot(d, d)));
    }
  return best;
}

PlateResult vibrate(SphOptions options) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  test::add_sph_part(model, "plate", test::elastic_solid("plate", rho, bulk, shear),
                     test::box_fill({0, 0, 0}, {length, height, 0}, dx));
  SphSystem<2> sph(model, options);
  const double young = 9 * bulk * shear / (3 * bulk + shear);
  const double nu = (3 * bulk - 2 * shear) / (2 * (3 * bulk + shear));
  const double c_plate = std::sqrt(young / (rho * (1 - nu * nu)));  // thin plate in plane strain
  auto& p = sph.particles();
  for (std::size_t i = 0; i < sph.size(); ++i)
    p.velocity[i][0] = amplitude * c_plate * std::cos(std::numbers::pi * p.position[i][0] / length);
  const double period = 2 * length / c_plate;
  omp_set_num_threads(1);
  sph.compute_accelerations();
  const double e0 = sph.kinetic_energy() + sph.internal_energy();
  PlateResult r;
  r.min_pair = std::numeric_limits<double>::infinity();
  double t = 0.0;
  long cycle = 0;
  while (t < periods * period) {
    const double dt = 0.3 * sph.stable_time_step().dt;
    t += dt;
    sph.step(dt, t);
    ++cycle;
    const double e = sph.centred_kinetic_energy() + sph.internal_energy();
    r.energy_error = std::max(r.energy_error, std::abs(e - e0) / e0);
    if (t > (periods - 1.0) * period) r.kept_kinetic = std::max(r.kept_kinetic, sph.kinetic_energy() / e0);
    if (cycle % 10 == 0) r.min_pair = std::min(r.min_pair, min_pair_distance(sph) / dx);
  }
  return r;
}

}  // namespace

TEST(SphTensileStability, VibratingPlateWithAndWithoutArtificialStress) {
  SphOptions off;
  off.artificial_stress = false;
  const PlateResult bare = vibrate(off);
  const PlateResult remedied = vibrate(SphOptions{});  // the default: artificial stress on
  std::printf("without remedy: min pair %.3f dx, kept KE %.3f, energy error %.4f\n", bare.min_pair,
              bare.kept_kinetic, bare.energy_error);
  std::printf("with artificial stress: min pair %.3f dx, kept KE %.3f, energy error %.4f\n",
              remedied.min_pair, remedied.kept_kinetic, remedied.energy_error);
  // The instability shown: particles clump (pairs closer than 0.75 dx) in the tension phases.
  EXPECT_LT(bare.min_pair, 0.75) << "no clumping without the remedy: the test cannot show the instability";
  test::record_check(
      "Tensile instability, vibrating elastic plate without remedy (60 x 6 particles, 5 % strain)",
      "clumping: smallest pair distance < 0.75 dx",
      "min pair " + std::to_string(bare.min_pair) + " dx (peak kinetic energy in the last period " +
          std::to_string(bare.kept_kinetic) + " E0)",
      bare.min_pair < 0.75);
  // With the remedy: no clumping, the vibration kept over 2.5 periods, energy conserved.
  test::verify({"Tensile stability, vibrating elastic plate with artificial stress: smallest pair distance",
                "initial spacing dx (no clumping), within 15 %", 1.0, remedied.min_pair, 0.15, true, "dx"});
  test::verify(
      {"Tensile stability, vibrating elastic plate with artificial stress: peak kinetic energy in the "
       "last period",
       "initial kinetic energy E0 (elastic vibration kept), within 15 %", 1.0, remedied.kept_kinetic, 0.15,
       true, "E0"});
  test::verify({"Tensile stability, vibrating elastic plate with artificial stress: total energy",
                "E0 conserved (artificial-stress work booked)", 0.0, remedied.energy_error, 0.02, false,
                "E0"});
}
