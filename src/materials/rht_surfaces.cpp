#include "materials/rht_surfaces.hpp"

#include <algorithm>
#include <cmath>

namespace camouflet {

double rht_rate_factor(const RhtParameters& m, double strain_rate, double p_star) {
  const double rate = std::abs(strain_rate);
  const double fc = rate > m.compressive_reference_rate
                        ? std::pow(rate / m.compressive_reference_rate, m.compressive_rate_exponent)
                        : 1.0;
  const double ft = rate > m.tensile_reference_rate
                        ? std::pow(rate / m.tensile_reference_rate, m.tensile_rate_exponent)
                        : 1.0;
  const double p_c = 1.0 / 3.0, p_t = -m.tensile_ratio / 3.0;  // uniaxial compression / tension points
  if (p_star >= p_c) return fc;
  if (p_star <= p_t) return ft;
  return ft + (fc - ft) * (p_star - p_t) / (p_c - p_t);
}

double rht_meridian_ratio(const RhtParameters& m, double p_star) {
  return std::clamp(m.meridian_ratio_0 + m.meridian_ratio_slope * p_star, 0.5, 1.0);
}

double rht_r3(double cos3theta, double e) {
  // Willam-Warnke (1975) elliptic interpolation between the meridians, in the
  // Lode angle theta of the deviatoric plane.
  const double c3 = std::clamp(cos3theta, -1.0, 1.0);
  const double c = std::cos(std::acos(c3) / 3.0);
  const double q = 1.0 - e * e;
  const double num =
      2.0 * q * c + (2.0 * e - 1.0) * std::sqrt(std::max(0.0, 4.0 * q * c * c + 5.0 * e * e - 4.0 * e));
  const double den = 4.0 * q * c * c + (1.0 - 2.0 * e) * (1.0 - 2.0 * e);
  return num / den;
}

double rht_uniaxial_compression_pressure(const RhtParameters& m) {
  // g(u) = A (u + f_t*)^N - 3u is concave with g(-f_t*) > 0: one root, by bisection.
  const double t = m.tensile_ratio;
  double lo = -t, hi = 1.0;
  while (m.failure_a * std::pow(hi + t, m.failure_n) - 3.0 * hi > 0.0) hi *= 2.0;
  for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
    const double u = 0.5 * (lo + hi);
    (m.failure_a * std::pow(u + t, m.failure_n) - 3.0 * u > 0.0 ? lo : hi) = u;
  }
  return 0.5 * (lo + hi);
}

void rht_finalise(RhtParameters& m) {
  m.uniaxial_compression_point = rht_uniaxial_compression_pressure(m);
}

double rht_static_meridian(const RhtParameters& m, double u) {
  const double t = m.tensile_ratio;
  if (u <= -t) return 0.0;
  const double power = m.failure_a * std::pow(u + t, m.failure_n);  // eq. 24 power law
  const double u_uc = m.uniaxial_compression_point;
  if (u >= u_uc) return power;
  // Uniaxial tension point: p* = -f_t*/3 with tensile-meridian strength f_t*,
  // i.e. compressive-meridian strength f_t*/Q2 there.
  const double u_t = -t / 3.0;
  const double y_t = std::min(t / rht_meridian_ratio(m, u_t), m.failure_a * std::pow(u_t + t, m.failure_n));
  if (u >= u_t) return y_t + (3.0 * u_uc - y_t) * (u - u_t) / (u_uc - u_t);
  return y_t * (u + t) / (u_t + t);
}

double rht_failure_strength(const RhtParameters& m, double pressure, double rate_factor, double cos3theta) {
  const double p_star = pressure / m.compressive_strength;
  return m.compressive_strength * rate_factor * rht_static_meridian(m, p_star / rate_factor) *
         rht_r3(cos3theta, rht_meridian_ratio(m, p_star));
}

double rht_elastic_fraction(const RhtParameters& m, double pressure, double rate_factor) {
  const double u = pressure / m.compressive_strength / rate_factor;
  const double u_c = 1.0 / 3.0, u_t = -m.tensile_ratio / 3.0;
  double ratio = m.elastic_ratio_compression;
  if (u <= u_t)
    ratio = m.elastic_ratio_tension;
  else if (u < u_c)
    ratio = m.elastic_ratio_tension +
            (m.elastic_ratio_compression - m.elastic_ratio_tension) * (u - u_t) / (u_c - u_t);
  // F_CAP: elliptic closure of the elastic surface between p_e and p_s (eq. 25).
  double cap = 1.0;
  if (pressure >= m.compaction_pressure)
    cap = 0.0;
  else if (pressure > m.crush_pressure) {
    const double x = (pressure - m.crush_pressure) / (m.compaction_pressure - m.crush_pressure);
    cap = std::sqrt(1.0 - x * x);
  }
  return ratio * cap;
}

double rht_residual_strength(const RhtParameters& m, double pressure, double cos3theta) {
  if (pressure <= 0.0) return 0.0;
  const double p_star = pressure / m.compressive_strength;
  return m.compressive_strength * m.residual_b * std::pow(p_star, m.residual_m) *
         rht_r3(cos3theta, rht_meridian_ratio(m, p_star));
}

double rht_failure_strain(const RhtParameters& m, double pressure) {
  const double x = pressure / m.compressive_strength + m.tensile_ratio;
  const double eps = x > 0.0 ? m.damage_d1 * std::pow(x, m.damage_d2) : 0.0;
  return std::max(eps, m.minimum_failure_strain);
}

}  // namespace camouflet
