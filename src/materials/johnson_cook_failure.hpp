#pragma once
// Damage model `johnson_cook` (Johnson & Cook 1985, Eng. Fract. Mech. 21,
// 31-48): cumulative ductile damage
//   D = sum d(eps_p) / eps_f,
//   eps_f = [D1 + D2 exp(D3 sigma*)] [1 + D4 ln(rate*)] [1 + D5 T*],
// with the stress triaxiality sigma* = sigma_m / sigma_eq = -p / sqrt(3 J2),
// rate* = eps_p_dot / eps_dot_0 and the homologous temperature
// T* = (T - T_room) / (T_melt - T_room). The plastic strain increment is what
// the strength model added this step (any strength model with plastic
// strain), so the failure strain uses the stress, rate and temperature at the
// end of the step.
// Conventions (documented choices, docs/theory/explosive-and-steel.md §5.1):
// * rate* < 1 gives no rate term (factor 1), as the Johnson-Cook strength;
// * T* is held in [0, 1];
// * eps_f is bounded below by `minimum_failure_strain` (default 0, the bare
//   formula). With a negative D1 the formula reaches eps_f <= 0 at high
//   triaxiality (4340 steel of JC 1985: sigma* >= 1.93, as in the release
//   behind an impact face), where it was never fitted; eps_f <= 0 fails the
//   point at its next plastic increment;
// * at D = 1 the point has failed: from then on it carries no deviator and no
//   tension (pressure >= 0), and `erosion = { damage = 1 }` on the material
//   removes its element (solver erosion path, docs/case-format.md "Erosion").
// Keys: d1 .. d5 (d1, d2 required; d3, d4, d5 default 0), reference_strain_rate
// (1/s, default 1), room_temperature (K, default 300), melt_temperature (K,
// required when d5 != 0), minimum_failure_strain (default 0).
#include <memory>

#include "core/parameters.hpp"
#include "materials/material.hpp"

namespace camouflet {

struct JohnsonCookFailureParameters {
  double d1 = 0.0, d2 = 0.0, d3 = 0.0, d4 = 0.0, d5 = 0.0;
  double reference_strain_rate = 1.0;   // 1/s
  double room_temperature = 300.0;      // K
  double melt_temperature = 0.0;        // K; only read when d5 != 0
  double minimum_failure_strain = 0.0;  // lower bound of eps_f
};

// eps_f at triaxiality sigma*, plastic strain rate (1/s) and temperature (K).
double johnson_cook_failure_strain(const JohnsonCookFailureParameters& p, double triaxiality,
                                   double plastic_strain_rate, double temperature);

class JohnsonCookFailure final : public DamageModel {
 public:
  explicit JohnsonCookFailure(const JohnsonCookFailureParameters& p) : p_(p) {}
  std::string type() const override { return "johnson_cook"; }
  void register_state(MaterialPoints& pts) const override;
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override;
  const JohnsonCookFailureParameters& parameters() const { return p_; }

 private:
  JohnsonCookFailureParameters p_;
};

std::shared_ptr<const JohnsonCookFailure> make_johnson_cook_failure(Parameters& p);

}  // namespace camouflet
