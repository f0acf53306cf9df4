#include "materials/johnson_cook_failure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "materials/registry.hpp"

namespace camouflet {

namespace {
// Plastic strain the damage has already counted (the increment of a step is
// the strength model's plastic strain minus this).
const char* const counted_column = "jc_counted_plastic_strain";
}  // namespace

double johnson_cook_failure_strain(const JohnsonCookFailureParameters& p, double triaxiality,
                                   double plastic_strain_rate, double temperature) {
  const double rate = plastic_strain_rate / p.reference_strain_rate;
  const double rate_factor = rate > 1.0 ? 1.0 + p.d4 * std::log(rate) : 1.0;
  double thermal_factor = 1.0;
  if (p.d5 != 0.0) {
    const double t = (temperature - p.room_temperature) / (p.melt_temperature - p.room_temperature);
    thermal_factor = 1.0 + p.d5 * std::clamp(t, 0.0, 1.0);
  }
  // Johnson & Cook 1985, eq. 4.
  const double eps_f = (p.d1 + p.d2 * std::exp(p.d3 * triaxiality)) * rate_factor * thermal_factor;
  return std::max(eps_f, p.minimum_failure_strain);
}

void JohnsonCookFailure::register_state(MaterialPoints& pts) const {
  pts.history.add(counted_column, 0.0);
}

void JohnsonCookFailure::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  double* counted = pts.history.column(pts.history.slot(counted_column));
#pragma omp parallel for schedule(static) if (n >= 256)
  for (std::size_t i = 0; i < n; ++i) {
    const double increment = pts.plastic_strain[i] - counted[i];
    counted[i] = pts.plastic_strain[i];
    if (pts.damage[i] < 1.0 && increment > 0.0) {
      const double sigma_eq = von_mises(pts.deviator[i]);
      // A plastic step has sigma_eq on the yield surface (> 0); a point that
      // lost its strength (melt) has none and gets the hydrostatic limit.
      const double triaxiality = sigma_eq > 0.0 ? -pts.pressure[i] / sigma_eq : 0.0;
      const double eps_f =
          johnson_cook_failure_strain(p_, triaxiality, pts.plastic_strain_rate[i], pts.temperature[i]);
      pts.damage[i] = eps_f > 0.0 ? std::min(1.0, pts.damage[i] + increment / eps_f) : 1.0;
    }
    if (pts.damage[i] >= 1.0) {
      // Failed: no shear and no tension. The deviatoric work of this step was
      // booked with the deviator the strength model left (its second half,
      // material.cpp); take back the half that no longer acts. The pressure
      // change is corrected by Material::update (acting end pressure).
      const double rho_mid = 0.5 * (pts.density[i] + pts.density_previous[i]);
      pts.specific_energy[i] -= 0.5 * ctx.dt * contract(pts.deviator[i], pts.strain_rate[i]) / rho_mid;
      pts.deviator[i] = SymTensor{};
      pts.pressure[i] = std::max(pts.pressure[i], 0.0);
    }
  }
}

std::shared_ptr<const JohnsonCookFailure> make_johnson_cook_failure(Parameters& params) {
  JohnsonCookFailureParameters p;
  p.d1 = params.number("d1");
  p.d2 = params.number("d2");
  p.d3 = params.number("d3", 0.0);
  p.d4 = params.number("d4", 0.0);
  p.d5 = params.number("d5", 0.0);
  p.reference_strain_rate = params.positive("reference_strain_rate", 1.0);
  p.room_temperature = params.positive("room_temperature", 300.0);
  p.minimum_failure_strain = params.non_negative("minimum_failure_strain", 0.0);
  if (p.d5 != 0.0) {
    p.melt_temperature = params.number("melt_temperature");
    if (!(p.melt_temperature > p.room_temperature))
      params.fail("melt_temperature",
                  fmt::format("the melt temperature {} K must exceed the room temperature {} K",
                              p.melt_temperature, p.room_temperature));
  } else if (params.has("melt_temperature")) {
    p.melt_temperature = params.positive("melt_temperature");
  }
  // At the triaxiality of uniaxial tension the failure strain must be positive,
  // or the material could not be stretched at all: a sign error in the set.
  const double tension = johnson_cook_failure_strain(p, 1.0 / 3.0, 0.0, p.room_temperature);
  if (!(tension > 0.0))
    params.fail("d1", fmt::format("the failure strain in uniaxial tension, D1 + D2 exp(D3 / 3) = {:.4g}, "
                                  "must be positive",
                                  tension));
  return std::make_shared<const JohnsonCookFailure>(p);
}

CAMOUFLET_REGISTER_DAMAGE("johnson_cook", [](Parameters& p) -> std::shared_ptr<const DamageModel> {
  return make_johnson_cook_failure(p);
});

}  // namespace camouflet
