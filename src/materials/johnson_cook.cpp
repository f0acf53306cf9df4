#include "materials/johnson_cook.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "materials/registry.hpp"

namespace camouflet {

namespace {

double thermal_factor(const JohnsonCookParameters& p, double temperature) {
  const double th = (temperature - p.room_temperature) / (p.melt_temperature - p.room_temperature);
  if (th <= 0.0) return 1.0;
  if (th >= 1.0) return 0.0;
  return 1.0 - std::pow(th, p.thermal_exponent);
}

double rate_factor(const JohnsonCookParameters& p, double rate) {
  const double r = rate / p.reference_strain_rate;
  return r > 1.0 ? 1.0 + p.rate_coefficient * std::log(r) : 1.0;
}

double hardening(const JohnsonCookParameters& p, double eps) {
  return p.yield_stress + (eps > 0.0 ? p.hardening_modulus * std::pow(eps, p.hardening_exponent) : 0.0);
}

// Plastic strain increment that puts the trial stress on the yield surface:
// f(d) = sigma_trial - 3 G d - Y(eps + d, d / dt, T) = 0 (Wilkins radial
// return with rate and hardening solved implicitly). f decreases monotonically
// from f(0) > 0 to f(sigma_trial / 3G) = -Y <= 0, so a Newton iteration kept
// inside that bracket always converges. Returns a negative value on failure.
double plastic_increment(const JohnsonCookParameters& p, double sigma_trial, double eps, double dt,
                         double thermal) {
  const double g3 = 3.0 * p.shear_modulus;
  double lo = 0.0, hi = sigma_trial / g3;
  double d = std::max(0.0, (sigma_trial - hardening(p, eps) * thermal) / g3);
  const double tol = 1e-12 * sigma_trial;
  for (int it = 0; it < 200; ++it) {
    const double e = eps + d;
    const double rate = dt > 0.0 ? d / dt : 0.0;
    const double h = hardening(p, e);
    const double r = rate_factor(p, rate);
    const double f = sigma_trial - g3 * d - h * r * thermal;
    if (std::abs(f) <= tol) return d;
    if (f > 0.0)
      lo = d;
    else
      hi = d;
    const double dh =
        e > 0.0 ? p.hardening_modulus * p.hardening_exponent * std::pow(e, p.hardening_exponent - 1.0) : 0.0;
    const double dr = (rate / p.reference_strain_rate > 1.0 && d > 0.0) ? p.rate_coefficient / d : 0.0;
    const double df = -g3 - (dh * r + h * dr) * thermal;
    double next = d - f / df;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 1e-15 * sigma_trial / g3) return 0.5 * (lo + hi);
    d = next;
  }
  return -1.0;
}

}  // namespace

double johnson_cook_yield(const JohnsonCookParameters& p, double plastic_strain, double plastic_strain_rate,
                          double temperature) {
  return hardening(p, plastic_strain) * rate_factor(p, plastic_strain_rate) * thermal_factor(p, temperature);
}

void JohnsonCookStrength::initialise(MaterialPoints& pts) const {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pts.shear_modulus[i] = p_.shear_modulus;
    pts.temperature[i] = p_.room_temperature;
  }
}

void JohnsonCookStrength::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  const double dt = ctx.dt;
  const double g = p_.shear_modulus;
  long failed = -1;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    SymTensor s = pts.deviator[i] + (2.0 * g * dt) * deviator(pts.strain_rate[i]);
    const double sigma_trial = von_mises(s);
    const double thermal = thermal_factor(p_, pts.temperature[i]);
    const double eps = pts.plastic_strain[i];
    // Elastic when inside the quasi-static surface: the rate factor is >= 1
    // and equals 1 for a vanishing plastic increment.
    if (sigma_trial <= hardening(p_, eps) * thermal) {
      pts.deviator[i] = s;
      pts.plastic_strain_rate[i] = 0.0;
      continue;
    }
    const double d = plastic_increment(p_, sigma_trial, eps, dt, thermal);
    if (d < 0.0) {
#pragma omp atomic write
      failed = static_cast<long>(i);
      continue;
    }
    const double sigma = std::max(0.0, sigma_trial - 3.0 * g * d);
    pts.deviator[i] = s * (sigma / sigma_trial);
    pts.plastic_strain[i] = eps + d;
    pts.plastic_strain_rate[i] = dt > 0.0 ? d / dt : 0.0;
    if (!p_.isothermal)
      pts.temperature[i] += p_.taylor_quinney * sigma * d / (pts.density[i] * p_.specific_heat);
  }
  if (failed >= 0)
    throw NumericalError(EntityKind::material_point, failed, "plastic strain",
                         "Johnson-Cook return map did not converge");
}

namespace {

std::shared_ptr<const StrengthModel> make_johnson_cook(Parameters& params) {
  JohnsonCookParameters p;
  p.shear_modulus = params.positive("shear_modulus");
  p.yield_stress = params.positive("yield_stress");
  p.hardening_modulus = params.number("hardening_modulus");
  if (p.hardening_modulus < 0.0)
    params.fail("hardening_modulus", "the hardening modulus B must not be negative");
  p.hardening_exponent = params.number("hardening_exponent");
  if (!(p.hardening_exponent > 0.0))
    params.fail("hardening_exponent",
                fmt::format("the hardening exponent n must be positive, got {}", p.hardening_exponent));
  p.rate_coefficient = params.non_negative("rate_coefficient", 0.0);
  p.thermal_exponent = params.positive("thermal_exponent", 1.0);
  p.room_temperature = params.positive("room_temperature", 300.0);
  p.melt_temperature = params.number("melt_temperature");
  if (!(p.melt_temperature > p.room_temperature))
    params.fail("melt_temperature",
                fmt::format("the melt temperature {} K must exceed the room temperature {} K",
                            p.melt_temperature, p.room_temperature));
  p.specific_heat = params.positive("specific_heat");
  p.taylor_quinney = params.in_range("taylor_quinney", 0.0, 1.0, 0.9);
  p.reference_strain_rate = params.positive("reference_strain_rate", 1.0);
  p.isothermal = params.flag("isothermal", false);
  return std::make_shared<JohnsonCookStrength>(p);
}

}  // namespace

CAMOUFLET_REGISTER_STRENGTH("johnson_cook", make_johnson_cook);

}  // namespace camouflet
