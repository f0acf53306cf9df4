// Energy of the smoothed hoop term ([sph] smoothed_hoop): the force and the hoop rate are each
// other's conjugates pair by pair, and the images' mismatch is booked, so the balance closes to
// the time step's first-order error, halving with the step, as with the point hoop term.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

// A block of hot gas at rest on the axis (0.2 m x 0.2 m, 0.01 m spacing) released into vacuum:
// the energy error of an r-z run to 0.3 ms (the rarefaction crosses the block).
double released_block_energy_error(bool smoothed_hoop, double cfl, double band = 0.0) {
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1000.0, 1.4, 1e5),
                     test::box_fill({0, 0, 0}, {0.2, 0.2, 0}, 0.01));
  SphOptions options;
  options.smoothed_hoop = smoothed_hoop;
  options.smoothed_hoop_width = band;
  SphSystem<2> sph(model, options);
  const double e0 = sph.kinetic_energy() + sph.internal_energy();
  double dt_last = 0.0;
  test::run_leapfrog_until(sph, 3e-4, cfl, &dt_last);
  const double e1 = test::synchronised_kinetic_energy(sph, dt_last) + sph.internal_energy();
  return e1 / e0 - 1.0;
}

}  // namespace

TEST(SphAxisSmoothedHoop, EnergyErrorHalvesWithTheStep) {
  const double coarse = released_block_energy_error(true, 0.4), fine = released_block_energy_error(true, 0.2);
  const double point = released_block_energy_error(false, 0.4);
  std::printf("energy error, smoothed hoop: %+.3e (CFL 0.4), %+.3e (CFL 0.2); point hoop %+.3e (CFL 0.4)\n",
              coarse, fine, point);
  // The balance closes to the step's first-order error. Measured on 6 Dec 2026: +4.1e-4 and +1.9e-4
  // (the point hoop term +5.7e-4 at CFL 0.4). The images' booked mismatch is small here (unbooked,
  // the two errors are 6e-5 higher): the buried charge's runs record it (long_axis_reference.cpp).
  test::verify({"r-z SPH with the smoothed hoop term, hot gas block on the axis released into vacuum, 0.3 ms: "
                "energy error at CFL 0.2 over the error at CFL 0.4",
                "1/2 (first order in the step: the force and the hoop rate conjugate, the images booked)", 0.5,
                fine / coarse, 0.2, false, "-"});
}

// With the band next to the axis ([sph] smoothed_hoop_width): each particle's point part has the
// same weight in its force and its rate, so the balance still closes to first order in the step.
TEST(SphAxisSmoothedHoop, EnergyErrorHalvesWithTheStepWithTheBand) {
  const double coarse = released_block_energy_error(true, 0.4, 1.0), fine = released_block_energy_error(true, 0.2, 1.0);
  std::printf("energy error, smoothed hoop with a band of one smoothing length: %+.3e (CFL 0.4), %+.3e (CFL 0.2)\n",
              coarse, fine);
  test::verify({"r-z SPH with the smoothed hoop term and its band of one smoothing length, hot gas block on the "
                "axis released into vacuum, 0.3 ms: energy error at CFL 0.2 over the error at CFL 0.4",
                "1/2 (first order in the step)", 0.5, fine / coarse, 0.2, false, "-"});
}
