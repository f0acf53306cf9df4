#include "materials/jwl_eos.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "materials/programmed_burn.hpp"
#include "materials/registry.hpp"

namespace camouflet {

JwlEos::JwlEos(const JwlParameters& p, double detonation_velocity, double burn_width_factor)
    : p_(p),
      cj_(chapman_jouguet_state(p)),
      detonation_velocity_(detonation_velocity),
      burn_width_factor_(burn_width_factor) {
  if (!(detonation_velocity_ > 0.0)) detonation_velocity_ = cj_.detonation_velocity;
}

double JwlEos::products_pressure(double rho, double e) const {
  // w E / V with E = rho0 e and V = rho0 / rho is w rho e.
  return jwl_pressure(p_, p_.density / rho, p_.density * e);
}

double JwlEos::products_sound_speed_squared(double rho, double e) const {
  // c^2 = dp/drho|_e + (p / rho^2) dp/de|_rho, with dV/drho = -V / rho and
  // d/dV [C (1 - w/(R V)) exp(-R V)] = C exp(-R V) (w/(R V^2) + w/V - R).
  const double v = p_.density / rho;
  auto dterm = [&](double c, double r) {
    return c * std::exp(-r * v) * (p_.omega / (r * v * v) + p_.omega / v - r);
  };
  const double dp_dv = dterm(p_.c1, p_.r1) + dterm(p_.c2, p_.r2);
  const double p = products_pressure(rho, e);
  return -v / rho * dp_dv + p_.omega * e + p * p_.omega / rho;
}

void JwlEos::register_state(MaterialPoints& pts) const {
  pts.history.add("lighting_time", std::numeric_limits<double>::infinity());
  pts.history.add("burn_fraction", 0.0);
}

void JwlEos::place(MaterialPoints& pts, std::span<const std::array<double, 3>> positions,
                   const std::vector<DetonationPoint>& detonations) const {
  double* lit = pts.history.column(pts.history.slot("lighting_time"));
  for (std::size_t i = 0; i < pts.size() && i < positions.size(); ++i)
    lit[i] = lighting_time(positions[i], detonations, detonation_velocity_);
}

void JwlEos::evaluate(MaterialPoints& pts, const MaterialContext& ctx, bool commit) const {
  const double* lit = pts.history.column(pts.history.slot("lighting_time"));
  double* burnt = pts.history.column(pts.history.slot("burn_fraction"));
  const std::size_t n = pts.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    // The fraction never decreases (a point that has burnt stays burnt).
    const double rho = pts.density[i];
    const double f = std::max({burnt[i],
                               burn_fraction(ctx.time, lit[i], detonation_velocity_, burn_width_factor_,
                                             pts.characteristic_length[i]),
                               volume_burn_fraction(p_.density / rho, cj_.relative_volume)});
    if (commit) burnt[i] = f;
    const double e = pts.specific_energy[i];
    pts.pressure[i] = f * products_pressure(rho, e);
    pts.sound_speed[i] = std::sqrt(std::max(0.0, products_sound_speed_squared(rho, e)));
  }
}

namespace {

std::shared_ptr<const EquationOfState> make_jwl(Parameters& params) {
  JwlParameters p;
  p.density = params.positive("density");
  p.c1 = params.number("c1");
  p.c2 = params.number("c2");
  p.r1 = params.positive("r1");
  p.r2 = params.positive("r2");
  p.omega = params.positive("omega");
  p.e0 = params.number("e0");
  // 0 = use the computed CJ velocity.
  const double velocity = params.has("detonation_velocity") ? params.positive("detonation_velocity") : 0.0;
  const double width = params.positive("burn_width_factor", default_burn_width_factor);
  try {
    return std::make_shared<JwlEos>(p, velocity, width);
  } catch (const CjStateError& e) {
    params.fail(e.key(), e.what());
  }
}

}  // namespace

CAMOUFLET_REGISTER_EOS("jwl", make_jwl);

}  // namespace camouflet
