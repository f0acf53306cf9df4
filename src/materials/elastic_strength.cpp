#include "materials/elastic_strength.hpp"

#include <cmath>

#include "materials/registry.hpp"

namespace camouflet {

ElasticStrength::ElasticStrength(double shear_modulus) : shear_(shear_modulus) {}

void ElasticStrength::initialise(MaterialPoints& pts) const {
  for (auto& g : pts.shear_modulus) g = shear_;
}

void ElasticStrength::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  const double two_g_dt = 2.0 * shear_ * ctx.dt;
#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
  for (std::size_t i = 0; i < n; ++i) pts.deviator[i] += two_g_dt * deviator(pts.strain_rate[i]);
}

VonMisesStrength::VonMisesStrength(double shear_modulus, double yield_stress)
    : ElasticStrength(shear_modulus), yield_(yield_stress) {}

void VonMisesStrength::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  const double dt = ctx.dt;
  const double two_g_dt = 2.0 * shear_ * dt;
#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
  for (std::size_t i = 0; i < n; ++i) {
    // Elastic trial, then radial return onto sqrt(3 J2) = Y (Wilkins 1964):
    // exact for perfect plasticity, plastic strain increment (q_trial - Y) / 3G.
    SymTensor s = pts.deviator[i] + two_g_dt * deviator(pts.strain_rate[i]);
    const double q_trial = von_mises(s);
    double dep = 0.0;
    if (q_trial > yield_) {
      s *= yield_ / q_trial;
      dep = (q_trial - yield_) / (3.0 * shear_);
    }
    pts.deviator[i] = s;
    pts.plastic_strain[i] += dep;
    pts.plastic_strain_rate[i] = dt > 0.0 ? dep / dt : 0.0;
  }
}

namespace {
std::shared_ptr<const StrengthModel> make_elastic(Parameters& p) {
  return std::make_shared<const ElasticStrength>(p.positive("shear_modulus"));
}
std::shared_ptr<const StrengthModel> make_von_mises(Parameters& p) {
  const double g = p.positive("shear_modulus");
  const double y = p.positive("yield_stress");
  return std::make_shared<const VonMisesStrength>(g, y);
}
}  // namespace

CAMOUFLET_REGISTER_STRENGTH("elastic", make_elastic);
CAMOUFLET_REGISTER_STRENGTH("von_mises", make_von_mises);

}  // namespace camouflet
