#include "empirical/ground_shock.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"
#include "empirical/imperial_units.hpp"

namespace camouflet::empirical {

namespace {

[[noreturn]] void refuse(const std::string& key, const std::string& message) {
  throw InputError(SourceLocation{"", 0, 0, key}, message);
}

void require_positive(const std::string& key, double v) {
  if (!(v > 0.0) || !std::isfinite(v)) refuse(key, fmt::format("must be positive and finite, got {}", v));
}

void require_coupling(double f) {
  if (!(f > 0.0 && f <= 1.0)) refuse("coupling", fmt::format("must lie in (0, 1], got {}", f));
}

// ∫_{R1}^{R2} R^-m dR, written with expm1 so that m -> 1 (the logarithm) is
// reached smoothly: displacement with n = 2 has m = n - 1 = 1 exactly. log1p
// keeps a narrow span (R2 - R1 << R1) accurate.
double power_integral(double m, double r1, double r2) {
  const double log_ratio = std::log1p((r2 - r1) / r1);
  const double x = (1.0 - m) * log_ratio;
  const double base = std::pow(r1, 1.0 - m);
  if (std::abs(x) < 1e-8) return base * log_ratio * (1.0 + 0.5 * x);
  return base * std::expm1(x) / (1.0 - m);
}

// Scaled distance in ft/lb^(1/3) per m/kg^(1/3): Z_imperial = k · Z_SI, k = 2.5208.
double imperial_scaled_distance_factor() {
  return std::cbrt(imperial::pound_kg) / imperial::foot_m;
}

}  // namespace

double scaled_distance(double range, double charge_mass) {
  require_positive("range", range);
  require_positive("charge_mass", charge_mass);
  return range / std::cbrt(charge_mass);
}

double PowerLaw::value(double charge_mass, double coupling, double range) const {
  require_coupling(coupling);
  const double z = scaled_distance(range, charge_mass);
  return coupling * coefficient * std::pow(charge_mass, charge_exponent) * std::pow(z, -range_exponent);
}

double PowerLaw::span_average(double charge_mass, double coupling, double range_near,
                              double range_far) const {
  require_coupling(coupling);
  require_positive("charge_mass", charge_mass);
  require_positive("span", range_near);
  require_positive("span", range_far);
  if (!(range_far > range_near))
    refuse("span",
           fmt::format("the far end must exceed the near end, got {} .. {} m", range_near, range_far));
  // q = f K W^e (R / s)^-m with s = W^(1/3): the mean over R pulls s^m out of the integral.
  const double s = std::cbrt(charge_mass);
  const double scale =
      coupling * coefficient * std::pow(charge_mass, charge_exponent) * std::pow(s, range_exponent);
  return scale * power_integral(range_exponent, range_near, range_far) / (range_far - range_near);
}

Soil wang2005_sandy_clay() {
  return Soil{1920.0, 1400.0};
}

GroundShockLaw tm5_855_1(const Soil& soil, double n) {
  require_positive("soil_density", soil.density);
  require_positive("seismic_velocity", soil.seismic_velocity);
  require_positive("attenuation", n);
  using namespace imperial;
  const double k = imperial_scaled_distance_factor();
  const double c_fps = soil.seismic_velocity / foot_m;
  const double lb_cbrt = std::cbrt(pound_kg);  // kg^(1/3) per lb^(1/3)

  GroundShockLaw law;
  law.attenuation = n;
  law.source = fmt::format("TM 5-855-1 ch. 5 general equations, rho = {} kg/m^3, c = {} m/s", soil.density,
                           soil.seismic_velocity);
  // V0 = 160 (k Z)^-n ft/s.
  law.velocity = PowerLaw{160.0 * foot_m * std::pow(k, -n), 0.0, n};
  // P0 = ρc · V0: the manual's psi/(ft/s) impedance times ft/s is the SI ρc times m/s.
  law.stress = PowerLaw{soil.density * soil.seismic_velocity * law.velocity.coefficient, 0.0, n};
  // a0 = 50 c (k Z)^-(n+1) / W_lb^(1/3) g, and W_lb^(1/3) = W^(1/3) / lb_cbrt.
  law.acceleration =
      PowerLaw{50.0 * c_fps * standard_gravity * lb_cbrt * std::pow(k, -(n + 1.0)), -1.0 / 3.0, n + 1.0};
  // d0 = 500 / c · W_lb^(1/3) (k Z)^-(n-1) ft.
  law.displacement = PowerLaw{500.0 / c_fps * foot_m / lb_cbrt * std::pow(k, -(n - 1.0)), 1.0 / 3.0, n - 1.0};
  return law;
}

GroundShockLaw wang2005(double n) {
  // Printed coefficients (Wang et al. 2005, eqs. 38-39 and §5.5), per n.
  struct Printed {
    double n, stress_MPa, velocity, acceleration_g;
  };
  static constexpr Printed printed[] = {{2.0, 22.0, 7.38, 2338.0}, {2.5, 15.0, 4.62, 1464.0}};
  constexpr double paper_charge_mass = 100.0;  // kg, Wang et al. 2005 §5

  for (const auto& p : printed) {
    if (std::abs(n - p.n) > 1e-12) continue;
    GroundShockLaw law = tm5_855_1(wang2005_sandy_clay(), n);  // displacement stays the manual's
    law.source = fmt::format(
        "Wang et al. 2005 printed coefficients (n = {}); displacement from TM 5-855-1 with the paper's soil",
        n);
    law.stress = PowerLaw{p.stress_MPa * 1e6, 0.0, n};
    law.velocity = PowerLaw{p.velocity, 0.0, n};
    law.acceleration = PowerLaw{p.acceleration_g * imperial::standard_gravity * std::cbrt(paper_charge_mass),
                                -1.0 / 3.0, n + 1.0};
    return law;
  }
  refuse("attenuation", fmt::format("Wang et al. 2005 print coefficients only for n = 2 and n = 2.5, got {}; "
                                    "use the TM 5-855-1 general law for other values",
                                    n));
}

}  // namespace camouflet::empirical
