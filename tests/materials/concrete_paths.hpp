#pragma once
// Load paths for the RHT concrete tests: triaxial (confined) compression or
// extension and uniaxial stress through drive_material, with the peak and the
// softened end state.
#include <algorithm>
#include <cmath>
#include <vector>

#include "concrete_fixture.hpp"
#include "materials/material_driver.hpp"

namespace camouflet::test {

struct PathResult {
  double peak_q = 0.0;            // Pa, peak sqrt(3 J2) = |sigma_axial - sigma_lateral|
  double pressure_at_peak = 0.0;  // Pa
  double axial_at_peak = 0.0;     // Pa, axial stress at the peak (tension positive)
  double rate_at_peak = 0.0;      // 1/s, equivalent strain rate the model used there
  double final_axial = 0.0;       // Pa, axial stress at the end of the path
  double final_pressure = 0.0;    // Pa
  double final_damage = 0.0;
};

// Triaxial path through the shared material-point driver: hydrostatic
// loading to `confinement` (Pa; 0 gives uniaxial stress), then `steps` axial
// steps at axial rate `rate` (1/s; negative: compression) up to
// `final_strain`, the lateral stress held. The peak, the equivalent strain
// rate there (from the strain increments of the rows) and the end state.
// A fully damaged point in tension carries no stress at all, so the held
// lateral stress there needs a looser (relative, floor 1 Pa) tolerance.
inline PathResult run_axial_path(double confinement, double rate, double final_strain, int steps,
                                 double stress_tolerance = 1e-9) {
  DriverSpec spec;
  spec.path = confinement > 0.0 ? LoadPath::triaxial : LoadPath::uniaxial_stress;
  spec.strain_rate = rate;
  spec.final_strain = final_strain;
  spec.confining_pressure = confinement;
  spec.steps = steps;
  spec.stress_tolerance = stress_tolerance;
  const std::vector<DriverRow> rows = drive_material(*concrete_35mpa(), spec);
  PathResult r;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const DriverRow& row = rows[k];
    const double q = std::abs(row.stress.xx - row.stress.yy);
    if (q > r.peak_q && row.axial_strain != rows[k - 1].axial_strain) {
      r.peak_q = q;
      r.pressure_at_peak = row.pressure;
      r.axial_at_peak = row.stress.xx;
      const double dt = row.time - rows[k - 1].time;
      const double d_axial = (row.axial_strain - rows[k - 1].axial_strain) / dt;
      const double d_lateral = 0.5 * ((row.volumetric_strain - rows[k - 1].volumetric_strain) / dt - d_axial);
      r.rate_at_peak = std::sqrt(2.0 / 3.0 * (d_axial * d_axial + 2.0 * d_lateral * d_lateral));
    }
  }
  r.final_axial = rows.back().stress.xx;
  r.final_pressure = rows.back().pressure;
  r.final_damage = rows.back().damage;
  return r;
}

// Library parameters of the preset, for the closed-form references.
struct ConcreteReference {
  double fc = 35e6, ft = 3.5e6, a = 1.6, n = 0.61, b = 1.6, m = 0.61, q20 = 0.6805, bq = 0.0105;
  // Compressive meridian, power-law part: f_c A (p* + f_t/f_c)^N (Wang et al. 2005, eq. 24, F = 1).
  double txc(double p) const { return fc * a * std::pow(p / fc + ft / fc, n); }
  // Static uniaxial compressive strength: sigma with sigma = txc(sigma / 3), by bisection.
  double uniaxial_compression() const {
    double lo = 0.0, hi = 3.0 * fc;
    for (int k = 0; k < 200; ++k) {
      const double s = 0.5 * (lo + hi);
      (txc(s / 3.0) > s ? lo : hi) = s;
    }
    return 0.5 * (lo + hi);
  }
};

}  // namespace camouflet::test
