#include "materials/soil_drucker_prager.hpp"

#include <algorithm>
#include <cmath>

#include "materials/registry.hpp"

namespace camouflet {

double SoilDruckerPrager::yield_limit(double pressure, double effective_strain_rate, double damage) const {
  const double rate_factor =
      effective_strain_rate > p_.reference_strain_rate
          ? 1.0 + p_.rate_sensitivity * std::log(effective_strain_rate / p_.reference_strain_rate)
          : 1.0;
  const double static_limit = p_.friction_slope * 3.0 * pressure + p_.cohesion * (1.0 - damage);  // eq. 20
  return std::max(0.0, static_limit * rate_factor);                                               // eq. 21
}

std::optional<double> SoilDruckerPrager::friction_angle() const {
  if (!(p_.friction_slope > 0.0)) return std::nullopt;
  const double a = std::sqrt(3.0) * p_.friction_slope;
  const double sin_phi = 3.0 * a / (2.0 + a);
  // alpha >= 1/sqrt(3) has no Mohr-Coulomb angle: the cone would open past phi = 90 degrees.
  if (!(sin_phi < 1.0)) return std::nullopt;
  return std::asin(sin_phi);
}

void SoilDruckerPrager::initialise(MaterialPoints& pts) const {
  std::fill(pts.shear_modulus.begin(), pts.shear_modulus.end(), p_.shear_modulus);
}

void SoilDruckerPrager::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  const double dt = ctx.dt;
  const double g = p_.shear_modulus;
// Small batches (a material-point driver, a few particles) run serially: a
// thread team costs more than the points.
#pragma omp parallel for schedule(static) if (n >= 256)
  for (std::size_t i = 0; i < n; ++i) {
    const SymTensor rate = deviator(pts.strain_rate[i]);
    const double effective_rate = std::sqrt(2.0 / 3.0 * contract(rate, rate));  // eq. 22
    SymTensor trial = pts.deviator[i] + rate * (2.0 * g * dt);
    const double y = yield_limit(pts.pressure[i], effective_rate, pts.damage[i]);
    const double root_j2 = std::sqrt(j2(trial));
    double plastic_increment = 0.0;
    if (root_j2 > y) {
      // Radial return along the Prandtl-Reuss potential of eq. 23.
      trial *= root_j2 > 0.0 ? y / root_j2 : 0.0;
      plastic_increment = (root_j2 - y) / (std::sqrt(3.0) * g);
    }
    pts.deviator[i] = trial;
    pts.shear_modulus[i] = g;
    pts.plastic_strain[i] += plastic_increment;
    pts.plastic_strain_rate[i] = dt > 0.0 ? plastic_increment / dt : 0.0;
  }
}

std::shared_ptr<const SoilDruckerPrager> make_soil_drucker_prager(Parameters& p) {
  SoilDruckerPragerParameters s;
  s.shear_modulus = p.positive("shear_modulus");
  for (const char* key : {"friction_slope", "cohesion"})
    if (!p.has(key)) p.fail(key, "required parameter is missing");
  s.friction_slope = p.non_negative("friction_slope", 0.0);
  s.cohesion = p.non_negative("cohesion", 0.0);
  s.rate_sensitivity = p.non_negative("rate_sensitivity", 0.0);
  s.reference_strain_rate = p.positive("reference_strain_rate", 0.01 / 60.0);  // 1 %/min (Table 2)
  if (!(s.friction_slope > 0.0 || s.cohesion > 0.0))
    p.fail("cohesion", "friction_slope and cohesion cannot both be zero (no strength)");
  return std::make_shared<const SoilDruckerPrager>(s);
}

CAMOUFLET_REGISTER_STRENGTH("soil_drucker_prager", [](Parameters& p) -> std::shared_ptr<const StrengthModel> {
  return make_soil_drucker_prager(p);
});

}  // namespace camouflet
