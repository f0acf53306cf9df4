// The three-phase soil EOS lets the corrector call take the predictor's root
// (the law is barotropic: same density, damage and compaction, same root)
// instead of solving again from it. Both are converged roots of the same
// equation, so they may differ only within the Newton tolerance |F| <= 1e-12 v
// (docs/theory/three-phase-soil.md §2, docs/performance.md "Soil and 2-D quads at 73f910d").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/verification.hpp"
#include "soil_test_support.hpp"

namespace camouflet::test {
namespace {

// Density of point i at step k: loading to its own peak, release into tension,
// reloading past the old peak (loading, unloading, cut-off and reloading).
double density_path(double rho0, std::size_t i, std::size_t n, int k) {
  const double peak = 0.002 + 0.08 * static_cast<double>(i) / static_cast<double>(n);  // volumetric strain
  const double tension = -2e-4 * static_cast<double>(i % 5);
  double strain = 0.0;
  if (k < 20)
    strain = peak * (k + 1) / 20.0;
  else if (k < 40)
    strain = peak + (tension - peak) * (k - 19) / 20.0;
  else
    strain = tension + (1.2 * peak - tension) * (k - 39) / 20.0;
  return rho0 / (1.0 - strain);
}

TEST(ThreePhaseSoilEos, CorrectorReuseAgreesWithAFreshSolveWithinTheNewtonTolerance) {
  single_point_threads();
  const auto eos = soil_eos();
  const Material m("soil", eos);
  const std::size_t n = 64;
  MaterialPoints reuse, fresh;
  m.setup(reuse, n);
  m.setup(fresh, n);
  double* trial_density = fresh.history.column(fresh.history.slot("soil_trial_density"));
  const double rho0 = eos->reference_density();
  double worst = 0.0;  // max |p_reuse - p_fresh| / (rho c^2) over points and steps
  int branch_mismatches = 0;
  for (int k = 0; k < 60; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      reuse.density[i] = fresh.density[i] = density_path(rho0, i, n, k);
    }
    eos->evaluate(reuse, MaterialContext{}, false);
    eos->evaluate(reuse, MaterialContext{}, true);  // takes the predictor's root
    eos->evaluate(fresh, MaterialContext{}, false);
    std::fill(trial_density, trial_density + n, std::nan(""));  // no trial: solve again (the old path)
    eos->evaluate(fresh, MaterialContext{}, true);
    for (std::size_t i = 0; i < n; ++i) {
      const double stiffness = fresh.density[i] * fresh.sound_speed[i] * fresh.sound_speed[i];
      worst = std::max(worst, std::abs(reuse.pressure[i] - fresh.pressure[i]) / stiffness);
      const auto column = [i](MaterialPoints& pts, const char* name) -> double& {
        return pts.history.column(pts.history.slot(name))[i];
      };
      if (column(reuse, "soil_eos_branch") != column(fresh, "soil_eos_branch")) ++branch_mismatches;
      // Keep both batches on one path: the fresh one continues from the reused state.
      fresh.pressure[i] = reuse.pressure[i];
      for (const char* name : {"soil_min_volume", "soil_max_pressure", "soil_max_pore_pressure",
                               "soil_max_water_volume", "soil_max_solid_volume"})
        column(fresh, name) = column(reuse, name);
    }
  }
  EXPECT_EQ(branch_mismatches, 0);
  // Both roots satisfy |F| <= 1e-12 v, so they lie within 2e-12 v of each
  // other in volume: |dp| <= 2e-12 K with the tangent K <= rho c^2 reported.
  verify(
      {"Three-phase soil EOS: corrector taking the predictor's root vs solving again (64 points x 60 steps)",
       "same root within the Newton tolerance |F| <= 1e-12 v: |dp| / (rho c^2) <= 2e-12", 0.0, worst, 2e-12,
       false, "1"});
}

}  // namespace
}  // namespace camouflet::test
