#include "materials/rht_strength.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "materials/bracketed_root.hpp"
#include "materials/registry.hpp"

namespace camouflet {

namespace {
const char* const kStrainRate = "rht_strain_rate";  // 1/s, equivalent rate of the last step
}

double rht_equivalent_strain_rate(const SymTensor& d) {
  return std::sqrt(2.0 / 3.0 * contract(d, d));
}

RhtStrength::RhtStrength(const RhtParameters& p) : prm_(p) {
  rht_finalise(prm_);
}

void RhtStrength::register_state(MaterialPoints& pts) const {
  pts.history.add(kStrainRate, 0.0);
}

void RhtStrength::initialise(MaterialPoints& pts) const {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pts.shear_modulus[i] = prm_.shear_modulus;
    pts.damage[i] = 0.0;
  }
}

void RhtStrength::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  const double dt = ctx.dt;
  const RhtParameters& m = prm_;
  double* rate_column = pts.history.column(pts.history.slot(kStrainRate));
  std::atomic<long> failed{-1};

#pragma omp parallel for schedule(static) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    const double g = pts.shear_modulus[i];  // from the damage at the start of the step (eq. 31)
    const double damage0 = pts.damage[i];
    const double eps0 = pts.plastic_strain[i];
    const SymTensor trial = pts.deviator[i] + (2.0 * g * dt) * deviator(pts.strain_rate[i]);
    const double j2_trial = j2(trial);
    const double q_trial = std::sqrt(3.0 * j2_trial);
    const double p = pts.pressure[i];
    const double rate = rht_equivalent_strain_rate(pts.strain_rate[i]);
    rate_column[i] = rate;
    if (!std::isfinite(q_trial) || !std::isfinite(p)) {
      long expected = -1;
      failed.compare_exchange_strong(expected, static_cast<long>(i));
      continue;
    }
    const double f_rate = rht_rate_factor(m, rate, p / m.compressive_strength);
    // Lode angle of the trial: the radial return keeps it (eq. 24's R3).
    const double cos3theta =
        j2_trial > 0.0 ? 1.5 * std::sqrt(3.0) * j3(trial) / std::pow(j2_trial, 1.5) : -1.0;
    const double y_fail = rht_failure_strength(m, p, f_rate, cos3theta);
    const double y_elastic = y_fail * rht_elastic_fraction(m, p, f_rate);                // eq. 25
    const double y_residual = std::min(rht_residual_strength(m, p, cos3theta), y_fail);  // eq. 27
    const double eps_failure = rht_failure_strain(m, p);                                 // eq. 29
    const double eps_pre = m.pre_softening_plastic_strain;

    // Damage after a plastic increment dl: only straining beyond the hardening
    // phase counts (eq. 28).
    auto damage_after = [&](double dl) {
      const double softening = std::max(0.0, eps0 + dl - std::max(eps0, eps_pre));
      return std::min(1.0, damage0 + softening / eps_failure);
    };
    // Current strength: linear hardening (eq. 26), then the fracture surface
    // between failure and residual (eq. 30).
    auto strength = [&](double dl) {
      const double h = std::min(1.0, (eps0 + dl) / eps_pre);
      const double y_hard = y_elastic + h * (y_fail - y_elastic);
      const double d = damage_after(dl);
      return (1.0 - d) * y_hard + d * y_residual;
    };
    double dl = 0.0;
    SymTensor s = trial;
    const double r0 = q_trial - strength(0.0);
    if (r0 > 0.0) {
      // Radial return: q_trial - 3 G dl = Y(dl), bracketed in [0, q_trial / 3G].
      auto residual = [&](double x) { return q_trial - 3.0 * g * x - strength(x); };
      const double hi = q_trial / (3.0 * g);
      const double r_hi = residual(hi);
      if (r_hi >= 0.0) {
        dl = hi;  // no strength left at this pressure (beyond the tensile limit): return to s = 0
      } else {
        const RootResult r = bracketed_root(residual, 0.0, hi, r0, r_hi, 1e-14 * hi);
        if (!r.converged) {
          long expected = -1;
          failed.compare_exchange_strong(expected, static_cast<long>(i));
          continue;
        }
        dl = r.x;
      }
      s = trial * std::max(0.0, (q_trial - 3.0 * g * dl) / q_trial);
    }
    const double damage = damage_after(dl);
    pts.deviator[i] = s;
    pts.plastic_strain[i] = eps0 + dl;
    pts.plastic_strain_rate[i] = dt > 0.0 ? dl / dt : 0.0;
    pts.damage[i] = damage;
    pts.shear_modulus[i] = (1.0 - damage) * m.shear_modulus + damage * m.residual_shear_modulus;  // eq. 31
    // Hydrostatic tensile limit -f_t F, lost with damage (the spall cut-off).
    const double p_min = -m.tensile_ratio * m.compressive_strength * f_rate * (1.0 - damage);
    if (pts.pressure[i] < p_min) pts.pressure[i] = p_min;
  }
  if (failed.load() >= 0)
    throw NumericalError(EntityKind::material_point, failed.load(), "deviatoric stress",
                         "RHT return map failed (non-finite trial stress or pressure, or no convergence)");
}

std::shared_ptr<const StrengthModel> make_rht_strength(Parameters& b) {
  RhtParameters m;
  m.compressive_strength = b.positive("compressive_strength");
  m.tensile_ratio = b.positive("tensile_strength") / m.compressive_strength;
  if (m.tensile_ratio >= 1.0) b.fail("tensile_strength", "must be smaller than compressive_strength");
  m.failure_a = b.positive("failure_a");
  m.failure_n = b.in_range("failure_n", 1e-6, 1.0, 0.61);
  m.meridian_ratio_0 = b.in_range("tensile_meridian_ratio", 0.5, 1.0, 0.6805);
  m.meridian_ratio_slope = b.non_negative("meridian_ratio_slope", 0.0105);
  m.compressive_rate_exponent = b.non_negative("compressive_rate_exponent", 0.032);
  m.tensile_rate_exponent = b.non_negative("tensile_rate_exponent", 0.036);
  m.compressive_reference_rate = b.positive("compressive_reference_rate", 3e-5);
  m.tensile_reference_rate = b.positive("tensile_reference_rate", 3e-6);
  m.elastic_ratio_tension = b.in_range("elastic_ratio_tension", 1e-6, 1.0, 0.7);
  m.elastic_ratio_compression = b.in_range("elastic_ratio_compression", 1e-6, 1.0, 0.53);
  m.crush_pressure = b.positive("crush_pressure");
  m.compaction_pressure = b.positive("compaction_pressure");
  if (!(m.compaction_pressure > m.crush_pressure))
    b.fail("compaction_pressure", fmt::format("must exceed crush_pressure ({} Pa)", m.crush_pressure));
  m.pre_softening_plastic_strain = b.positive("pre_softening_plastic_strain", 1.93e-3);
  m.residual_b = b.non_negative("residual_b", 1.6);
  m.residual_m = b.in_range("residual_m", 1e-6, 1.0, 0.61);
  m.damage_d1 = b.positive("damage_d1", 0.04);
  m.damage_d2 = b.positive("damage_d2", 1.0);
  m.minimum_failure_strain = b.positive("minimum_failure_strain", 0.01);
  m.shear_modulus = b.positive("shear_modulus");
  m.residual_shear_modulus = b.positive("residual_shear_modulus");
  if (m.residual_shear_modulus > m.shear_modulus)
    b.fail("residual_shear_modulus", "must not exceed shear_modulus");
  return std::make_shared<RhtStrength>(m);
}

CAMOUFLET_REGISTER_STRENGTH("rht", make_rht_strength);

}  // namespace camouflet
