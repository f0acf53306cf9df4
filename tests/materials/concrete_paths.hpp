#pragma once
// Load paths for the RHT concrete tests: triaxial (confined) compression or
// extension and uniaxial stress, with the peak and the softened end state.
#include <algorithm>
#include <cmath>

#include "concrete_fixture.hpp"
#include "point_driver.hpp"

namespace camouflet::test {

struct PathResult {
  double peak_q = 0.0;            // Pa, peak sqrt(3 J2) = |sigma_axial - sigma_lateral|
  double pressure_at_peak = 0.0;  // Pa
  double axial_at_peak = 0.0;     // Pa, axial stress at the peak (tension positive)
  double rate_at_peak = 0.0;      // 1/s, equivalent strain rate the model used there
  double final_axial = 0.0;       // Pa, axial stress at the end of the path
  double final_pressure = 0.0;    // Pa
  double final_damage = 0.0;
  double worst_lateral_misfit = 0.0;  // Pa
};

// Hydrostatic loading to `confinement` (Pa), then axial strain steps `dexx`
// (negative: compression) at axial strain rate `rate` with the lateral
// stress held, until the damage reaches 1 or `max_steps`. After the peak the
// steps grow by `post_peak_factor` to reach full damage quickly, or the
// path stops there (`stop_after_peak`).
inline PathResult run_axial_path(double confinement, double dexx, double rate, int max_steps,
                                 double post_peak_factor = 1.0, bool stop_after_peak = false) {
  PointDriver d(concrete_35mpa());
  const double dt = std::abs(dexx) / rate;
  while (d.pressure() < confinement) d.strain_step(SymTensor::isotropic(-1e-5), dt);
  const double lateral = confinement > 0.0 ? -d.pressure() : 0.0;
  const std::size_t rate_slot = d.points().history.slot("rht_strain_rate");
  PathResult r;
  bool past_peak = false;
  for (int k = 0; k < max_steps; ++k) {
    const double step = past_peak ? dexx * post_peak_factor : dexx;
    const double misfit = d.axial_step(step, lateral, past_peak ? dt * post_peak_factor : dt);
    r.worst_lateral_misfit = std::max(r.worst_lateral_misfit, std::abs(misfit));
    const double q = std::abs(d.axial_stress() - d.lateral_stress());
    if (q > r.peak_q) {
      r.peak_q = q;
      r.pressure_at_peak = d.pressure();
      r.axial_at_peak = d.axial_stress();
      r.rate_at_peak = d.points().history.column(rate_slot)[0];
    } else if (d.points().damage[0] > 0.05) {
      past_peak = true;
      if (stop_after_peak) break;
    }
    if (d.points().damage[0] >= 1.0) break;
  }
  r.final_axial = d.axial_stress();
  r.final_pressure = d.pressure();
  r.final_damage = d.points().damage[0];
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
