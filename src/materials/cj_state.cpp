#include "materials/cj_state.hpp"

#include <fmt/format.h>

#include <cmath>

namespace camouflet {

double jwl_pressure(const JwlParameters& p, double v, double e) {
  return p.c1 * (1.0 - p.omega / (p.r1 * v)) * std::exp(-p.r1 * v) +
         p.c2 * (1.0 - p.omega / (p.r2 * v)) * std::exp(-p.r2 * v) + p.omega * e / v;
}

namespace {

// Product Hugoniot from the unreacted state (V = 1, E = e0, p0 = 0): the
// energy jump E - e0 = p (1 - V) / 2 (per unit initial volume) inserted into
// the JWL form gives p_H(V) = (f(V) + w e0 / V) / (1 - w (1 - V) / (2 V)).
double hugoniot_denominator(const JwlParameters& p, double v) {
  return 1.0 - p.omega * (1.0 - v) / (2.0 * v);
}
double hugoniot_pressure(const JwlParameters& p, double v) {
  return jwl_pressure(p, v, p.e0) / hugoniot_denominator(p, v);
}

// rho0 D^2 = p / (1 - V) along the Rayleigh line; the CJ state minimises it.
double rayleigh_slope(const JwlParameters& p, double v) {
  return hugoniot_pressure(p, v) / (1.0 - v);
}

// The parameter to blame for a non-positive Hugoniot pressure at V.
std::string blame(const JwlParameters& p, double v) {
  if (!(p.e0 > 0.0)) return "e0";
  const double t1 = p.c1 * (1.0 - p.omega / (p.r1 * v)) * std::exp(-p.r1 * v);
  const double t2 = p.c2 * (1.0 - p.omega / (p.r2 * v)) * std::exp(-p.r2 * v);
  if (t2 < 0.0 && t2 <= t1) return "c2";
  if (t1 < 0.0) return "c1";
  return "e0";
}

}  // namespace

CjState chapman_jouguet_state(const JwlParameters& p) {
  // The Hugoniot exists for V_low < V < 1, V_low = w / (2 + w) where its
  // denominator vanishes (p_H -> +infinity); there, and at V -> 1, the Rayleigh
  // slope grows without bound, so a positive Hugoniot always has an interior
  // minimum. Scan for the global minimum, then refine by golden section.
  const double v_low = p.omega / (2.0 + p.omega);
  constexpr int samples = 4000;
  int best = -1;
  double best_slope = 0.0;
  for (int k = 1; k < samples; ++k) {
    const double v = v_low + (1.0 - v_low) * k / samples;
    const double ph = hugoniot_pressure(p, v);
    if (!(ph > 0.0) || !std::isfinite(ph))
      throw CjStateError(
          blame(p, v),
          fmt::format("no Chapman-Jouguet state: the JWL product Hugoniot from the initial state has "
                      "pressure {:.4g} Pa at relative volume {:.4f}, so no Rayleigh line from "
                      "(rho0, p = 0) can touch it",
                      ph, v));
    const double s = ph / (1.0 - v);
    if (best < 0 || s < best_slope) {
      best = k;
      best_slope = s;
    }
  }
  if (best <= 1 || best >= samples - 1)
    throw CjStateError("omega",
                       "no Chapman-Jouguet state: the Rayleigh slope has no interior minimum on the "
                       "JWL product Hugoniot");
  double a = v_low + (1.0 - v_low) * (best - 1) / samples;
  double b = v_low + (1.0 - v_low) * (best + 1) / samples;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
  double f1 = rayleigh_slope(p, x1), f2 = rayleigh_slope(p, x2);
  while (b - a > 1e-13) {
    if (f1 < f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - golden * (b - a);
      f1 = rayleigh_slope(p, x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + golden * (b - a);
      f2 = rayleigh_slope(p, x2);
    }
  }
  CjState cj;
  cj.relative_volume = 0.5 * (a + b);
  cj.pressure = hugoniot_pressure(p, cj.relative_volume);
  cj.detonation_velocity = std::sqrt(rayleigh_slope(p, cj.relative_volume) / p.density);
  cj.density = p.density / cj.relative_volume;
  // Mass conservation across the front: u = D (1 - V).
  cj.particle_velocity = cj.detonation_velocity * (1.0 - cj.relative_volume);
  return cj;
}

}  // namespace camouflet
