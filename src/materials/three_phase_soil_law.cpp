#include "materials/three_phase_soil_law.hpp"

#include <algorithm>
#include <cmath>

namespace camouflet {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr int max_iterations = 200;
// Absolute pressure (Pa) below which pore water cavitates on unloading: its
// vapour pressure (2.3 kPa at 20 C), taken as zero.
constexpr double cavitation_pressure = 0.0;

// Root of a strictly decreasing F(x) by Newton's method kept inside a bracket
// [lo, hi] (either end may be open, +-inf), falling back to bisection, or to a
// bounded step while the bracket is open. `eval(x, F, dFdx)` must leave the
// caller's state at x. A non-finite F counts as "left of the root" (it only
// occurs where a phase volume diverges). Returns false when it did not
// converge; the caller turns that into a NumericalError naming the point.
template <class Eval>
bool solve_decreasing(Eval&& eval, double x, double lo, double hi, double f_tolerance, double max_step,
                      int& iterations) {
  for (iterations = 1; iterations <= max_iterations; ++iterations) {
    double f = 0.0, df = 0.0;
    eval(x, f, df);
    if (std::isfinite(f) && std::abs(f) <= f_tolerance) return true;
    if (!std::isfinite(f) || f > 0.0)
      lo = x;
    else
      hi = x;
    if (std::isfinite(lo) && std::isfinite(hi) &&
        hi - lo <= 4e-16 * std::max({1.0, std::abs(lo), std::abs(hi)}))
      return std::isfinite(f) && std::abs(f) <= 1e4 * f_tolerance;  // rounding floor reached
    double next = (std::isfinite(f) && std::isfinite(df) && df < 0.0) ? x - f / df : std::nan("");
    if (std::isfinite(next) && !(std::isfinite(lo) && std::isfinite(hi)))
      next = std::clamp(next, x - max_step, x + max_step);
    if (!(next > lo && next < hi)) {
      if (std::isfinite(lo) && std::isfinite(hi))
        next = 0.5 * (lo + hi);
      else if (std::isfinite(lo))
        next = lo + max_step;
      else
        next = hi - max_step;
    }
    x = next;
  }
  return false;
}

}  // namespace

double TaitPhase::volume(double p, double p0) const {
  if (fraction == 0.0) return 0.0;
  const double base = 1.0 + exponent * (p - p0) / bulk_modulus;
  if (!(base > 0.0)) return inf;
  return fraction * std::pow(base, -inverse_exponent);
}

double AirPhase::volume(double p, double p0) const {
  if (fraction == 0.0) return 0.0;
  if (!(p > 0.0)) return inf;
  return fraction * std::pow(p / p0, -inverse_exponent);
}

double ThreePhaseSoilConstants::pore_pressure_floor() const {
  if (air.fraction > 0.0) return 0.0;
  return ambient_pressure - water.bulk_modulus / water.exponent;
}

// Wang et al. 2005, eqs. 16-17 with Delta V_p = V_p0 - V_p (compression
// positive) and V_p the current pore volume, all over V0.
double ThreePhaseSoilConstants::skeleton_pressure(double pore_volume, double damage) const {
  const double compaction = pore_fraction() - pore_volume;
  return (friction + bond_modulus * (1.0 - damage) / pore_volume) * compaction;
}

double ThreePhaseSoilConstants::skeleton_stiffness(double pore_volume, double damage) const {
  return friction + bond_modulus * (1.0 - damage) * pore_fraction() / (pore_volume * pore_volume);
}

double ThreePhaseSoilConstants::initial_tangent_modulus() const {
  // Pore fluid: water and air volumes add at the common pore pressure; the
  // air's isentropic tangent modulus is k_g p0 = rho_g0 c_g0^2.
  const double fluid_compliance =
      water.fraction / water.bulk_modulus + air.fraction / (air.exponent * ambient_pressure);
  const double pore_stiffness =
      (fluid_compliance > 0.0 ? 1.0 / fluid_compliance : 0.0) + friction + bond_modulus / pore_fraction();
  return 1.0 / (solid.fraction / solid.bulk_modulus + 1.0 / pore_stiffness);
}

double soil_loading_volume(const ThreePhaseSoilConstants& c, double pore_pressure, double damage,
                           double* pressure) {
  const double p0 = c.ambient_pressure;
  const double vp = c.water.volume(pore_pressure, p0) + c.air.volume(pore_pressure, p0);
  const double p = pore_pressure + c.skeleton_pressure(vp, damage);
  if (pressure) *pressure = p;
  return c.solid.volume(p, p0) + vp;
}

SoilState soil_loading_state(const ThreePhaseSoilConstants& c, double v, double damage,
                             double pore_pressure_guess) {
  const double p0 = c.ambient_pressure;
  const double floor = c.pore_pressure_floor();
  const double cutoff = p0 - (1.0 - damage) * c.tensile_strength;
  SoilState s;
  double dv_dpb = 0.0, dp_dpb = 1.0;
  // Unknown x = ln(p_b - floor): the pore fluid volume is a power of it, so
  // F(x) is smooth and Newton converges from 1 atm to tens of GPa.
  auto eval = [&](double x, double& f, double& dfdx) {
    const double excess = std::exp(x);
    const double pb = floor + excess;
    const double vw = c.water.volume(pb, p0);
    const double va = c.air.volume(pb, p0);
    const double vp = vw + va;
    const double dvp = (vw > 0.0 ? -vw / c.water.tangent_modulus(pb, p0) : 0.0) +
                       (va > 0.0 ? -va / (c.air.exponent * pb) : 0.0);
    const double p = pb + c.skeleton_pressure(vp, damage);
    dp_dpb = 1.0 - c.skeleton_stiffness(vp, damage) * dvp;  // eq. 12: fluid and skeleton in parallel
    // Grains carry the total pressure (eq. 12); below the cut-off they are
    // held at the cut-off so that F stays monotone (see the theory section).
    const bool above_cutoff = p > cutoff;
    const double p_solid = above_cutoff ? p : cutoff;
    const double vs = c.solid.volume(p_solid, p0);
    const double dvs_dp = (above_cutoff && vs > 0.0) ? -vs / c.solid.tangent_modulus(p_solid, p0) : 0.0;
    dv_dpb = dvs_dp * dp_dpb + dvp;
    f = vs + vp - v;
    dfdx = dv_dpb * excess;
    s.pressure = p;
    s.pore_pressure = pb;
    s.pore_volume = vp;
    s.water_volume = vw;
    s.solid_volume = vs;
  };
  const double guess_excess = pore_pressure_guess - floor;
  const double x0 =
      (std::isfinite(guess_excess) && guess_excess > 0.0) ? std::log(guess_excess) : std::log(p0 - floor);
  s.converged = solve_decreasing(eval, x0, -inf, inf, 1e-12 * std::max(1.0, v), 4.0, s.iterations);
  s.bulk_modulus = -v * dp_dpb / dv_dpb;
  s.branch = SoilBranch::loading;
  if (s.pressure < cutoff) {
    s.pressure = cutoff;
    s.branch = SoilBranch::tension_cutoff;
    s.release_modulus = s.bulk_modulus;
  } else {
    s.release_modulus =
        soil_release_modulus(c, v, s.pressure, s.pore_pressure, s.water_volume, s.solid_volume, damage);
  }
  return s;
}

double soil_unloading_modulus(const ThreePhaseSoilConstants& c, double v, double pressure,
                              double pore_pressure) {
  const double p0 = c.ambient_pressure;
  return soil_unloading_modulus(c, v, pressure, pore_pressure, c.water.volume(pore_pressure, p0),
                                c.solid.volume(pressure, p0));
}

double soil_unloading_modulus(const ThreePhaseSoilConstants& c, double v, double pressure,
                              double pore_pressure, double vw, double vs) {
  const double p0 = c.ambient_pressure;
  const double compliance = (vw > 0.0 ? vw / c.water.tangent_modulus(pore_pressure, p0) : 0.0) +
                            (vs > 0.0 ? vs / c.solid.tangent_modulus(pressure, p0) : 0.0);
  return v / compliance;
}

double soil_release_modulus(const ThreePhaseSoilConstants& c, double v, double pressure, double pore_pressure,
                            double vw, double vs, double damage) {
  const double p0 = c.ambient_pressure;
  const double cutoff = p0 - (1.0 - damage) * c.tensile_strength;
  const bool cavitation_ahead = pore_pressure - (pressure - cutoff) < cavitation_pressure;
  if (!cavitation_ahead) return soil_unloading_modulus(c, v, pressure, pore_pressure, vw, vs);
  // Without grains (a water-only "soil") nothing carries the cavitated stretch.
  if (!(vs > 0.0)) return soil_unloading_modulus(c, v, pressure, pore_pressure, vw, vs);
  return v * c.solid.tangent_modulus(pressure, p0) / vs;
}

SoilState soil_unloading_state(const ThreePhaseSoilConstants& c, double v, const SoilCompaction& from,
                               double damage, double pressure_guess) {
  const double p0 = c.ambient_pressure;
  const double cutoff = p0 - (1.0 - damage) * c.tensile_strength;
  const double vw_max =
      std::isnan(from.water_volume) ? c.water.volume(from.pore_pressure, p0) : from.water_volume;
  const double vs_max = std::isnan(from.solid_volume) ? c.solid.volume(from.pressure, p0) : from.solid_volume;
  SoilState s;
  double dv_dp = 0.0, dv_dp_reported = 0.0;
  // The compacted air voids and the skeleton stay as they were at maximum
  // compaction; water (at p_b = p_b,max + p - p_max) and grains (at p) expand
  // elastically along eqs. 13-14: the water-solid mixture stiffness. The pore
  // water cavitates instead of going below zero absolute pressure (its vapour
  // pressure, ~2 kPa, taken as 0): below that only the grains expand.
  auto eval = [&](double p, double& f) {
    const double pb_elastic = from.pore_pressure + (p - from.pressure);
    const bool cavitated = pb_elastic < cavitation_pressure;
    const double pb = cavitated ? cavitation_pressure : pb_elastic;
    const double vw = c.water.volume(pb, p0);
    const double vs = c.solid.volume(p, p0);
    const double dvw_dp = vw > 0.0 ? -vw / c.water.tangent_modulus(pb, p0) : 0.0;
    const double dvs_dp = vs > 0.0 ? -vs / c.solid.tangent_modulus(p, p0) : 0.0;
    dv_dp = (cavitated ? 0.0 : dvw_dp) + dvs_dp;
    // The sound speed reported (the viscosities' and dashpots') stays that
    // of water and grains together; the grains-only stiffness of the
    // cavitated stretch is the release modulus, which the time step takes.
    dv_dp_reported = dvw_dp + dvs_dp;
    f = from.volume + (vw - vw_max) + (vs - vs_max) - v;
    s.pressure = p;
    s.pore_pressure = pb;
    s.water_volume = vw;
    s.solid_volume = vs;
    s.pore_volume = from.volume - vs_max + (vw - vw_max);
  };
  const double tolerance = 1e-12 * std::max(1.0, v);
  const double top = std::max(from.pressure, cutoff);
  // Newton from the guess inside [cut-off, p_max]. The cut-off end is only
  // evaluated when Newton heads below it, so a point at the cut-off costs one
  // evaluation and a point inside costs one or two with a good guess.
  double lo = cutoff, hi = top;
  bool lo_known = false;  // F(cut-off) > 0 established
  double p = std::isfinite(pressure_guess) ? std::clamp(pressure_guess, cutoff, top) : top;
  for (s.iterations = 1; s.iterations <= 200; ++s.iterations) {
    double f = 0.0;
    eval(p, f);
    if (std::isfinite(f) && std::abs(f) <= tolerance) {
      s.converged = true;
      break;
    }
    if (!std::isfinite(f) || f > 0.0) {
      lo = p;
      lo_known = true;
    } else {
      hi = p;
      if (p == cutoff) {
        // Beyond the cut-off: the mean stress stays at -(1 - D) p_t (gauge)
        // and the stiffness reported is that of the branch at the cut-off,
        // taken at the cut-off's volume v_c = v + f (the point re-stiffens
        // only once re-compressed to it): the sound speed K / rho is then the
        // cut-off state's, -v_c^2 / (rho0 dv/dp). Scaling by the current v
        // instead made an ejected point expanded 200-fold report c ~ 3e5 m/s
        // and collapsed the time step (the coarse buried-structure case).
        s.converged = true;
        const double v_cut = v + f;
        s.bulk_modulus = -v_cut * v_cut / (v * dv_dp_reported);
        // The grains alone where the water has cavitated there (no grains: the water's).
        s.release_modulus = dv_dp < 0.0 ? -v_cut * v_cut / (v * dv_dp) : s.bulk_modulus;
        s.branch = SoilBranch::tension_cutoff;
        return s;
      }
    }
    double next = (std::isfinite(f) && dv_dp < 0.0) ? p - f / dv_dp : std::nan("");
    if (!(next > lo && next < hi)) {
      if (!lo_known && !(next > lo))
        next = cutoff;  // test the cut-off itself
      else
        next = 0.5 * (lo + hi);
    }
    if (hi - lo <= 4e-16 * std::max(1.0, std::abs(hi))) {
      s.converged = std::isfinite(f) && std::abs(f) <= 1e4 * tolerance;
      break;
    }
    p = next;
  }
  s.bulk_modulus = -v / dv_dp_reported;
  s.release_modulus =
      soil_release_modulus(c, v, s.pressure, s.pore_pressure, s.water_volume, s.solid_volume, damage);
  s.branch = SoilBranch::unloading;
  return s;
}

SoilState soil_state(const ThreePhaseSoilConstants& c, double v, const SoilCompaction& from, double damage,
                     double pressure_guess, double pore_pressure_guess) {
  if (v < from.volume) return soil_loading_state(c, v, damage, pore_pressure_guess);
  return soil_unloading_state(c, v, from, damage, pressure_guess);
}

}  // namespace camouflet
