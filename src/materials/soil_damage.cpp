#include "materials/soil_damage.hpp"

#include <algorithm>
#include <cmath>

#include "materials/registry.hpp"

namespace camouflet {

namespace {
const char* const strain_columns[6] = {"soil_strain_xx", "soil_strain_yy", "soil_strain_zz",
                                       "soil_strain_xy", "soil_strain_yz", "soil_strain_zx"};
}  // namespace

double soil_effective_strain(const SymTensor& strain) {
  // Eq. 19: sum over pairs of principal differences = 3 e:e for the deviator e.
  const SymTensor e = deviator(strain);
  return std::sqrt(2.0 / 3.0 * contract(e, e));
}

double SoilBondDamage::damage_at(double effective_strain) const {
  // g = 1 (Table 2) without pow: pow(x, 1) is x exactly, so the same numbers.
  const double scaled = b_ * effective_strain;
  return 1.0 - std::exp(-(g_ == 1.0 ? scaled : std::pow(scaled, g_)) / g_);  // eq. 18
}

void SoilBondDamage::register_state(MaterialPoints& pts) const {
  for (const char* name : strain_columns) pts.history.add(name, 0.0);
  pts.history.add("soil_effective_strain", 0.0);
}

void SoilBondDamage::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  const double dt = ctx.dt;
  double* col[6];
  for (int k = 0; k < 6; ++k) col[k] = pts.history.column(pts.history.slot(strain_columns[k]));
  double* effective = pts.history.column(pts.history.slot("soil_effective_strain"));
// Small batches (a material-point driver, a few particles) run serially: a
// thread team costs more than the points.
#pragma omp parallel for schedule(static) if (n >= 256)
  for (std::size_t i = 0; i < n; ++i) {
    SymTensor strain{col[0][i], col[1][i], col[2][i], col[3][i], col[4][i], col[5][i]};
    strain += jaumann_increment(strain, pts.spin[i], dt);
    strain += pts.strain_rate[i] * dt;
    col[0][i] = strain.xx;
    col[1][i] = strain.yy;
    col[2][i] = strain.zz;
    col[3][i] = strain.xy;
    col[4][i] = strain.yz;
    col[5][i] = strain.zx;
    effective[i] = soil_effective_strain(strain);
    pts.damage[i] = std::max(pts.damage[i], damage_at(effective[i]));
  }
}

std::shared_ptr<const SoilBondDamage> make_soil_bond_damage(Parameters& p) {
  const double b = p.positive("strain_coefficient");
  const double g = p.positive("exponent");
  return std::make_shared<const SoilBondDamage>(b, g);
}

CAMOUFLET_REGISTER_DAMAGE("three_phase_soil", [](Parameters& p) -> std::shared_ptr<const DamageModel> {
  return make_soil_bond_damage(p);
});

}  // namespace camouflet
