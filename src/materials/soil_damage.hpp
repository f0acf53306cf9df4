#pragma once
// Damage model `three_phase_soil` (Wang, Lu, Hao, Chong 2005, eqs. 18-19):
// breaking of the bonds between grains,
//   D = 1 - exp[-(1/g) (b eps_eff)^g],
//   eps_eff = (sqrt 2 / 3) [(e1 - e2)^2 + (e2 - e3)^2 + (e3 - e1)^2]^(1/2),
// with e1..e3 the principal values of the accumulated total strain (history
// columns soil_strain_xx .. soil_strain_zx, integrated with the Jaumann rate
// like the stress). The root expression equals sqrt(2/3 e:e) of the strain
// deviator, which is what is computed (no eigenvalues needed). D never
// decreases: broken bonds stay broken. The EOS reads D in the bond term of
// eq. 17 and the strength model in the cohesion.
#include <memory>

#include "core/parameters.hpp"
#include "materials/material.hpp"

namespace camouflet {

class SoilBondDamage final : public DamageModel {
 public:
  SoilBondDamage(double strain_coefficient, double exponent) : b_(strain_coefficient), g_(exponent) {}
  std::string type() const override { return "three_phase_soil"; }
  void register_state(MaterialPoints& pts) const override;
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override;

  // Eq. 18 for one effective strain.
  double damage_at(double effective_strain) const;

 private:
  double b_;  // b of eq. 18 (1/strain)
  double g_;  // g of eq. 18
};

// Effective strain of eq. 19 from a (total) strain tensor.
double soil_effective_strain(const SymTensor& strain);

std::shared_ptr<const SoilBondDamage> make_soil_bond_damage(Parameters& p);

}  // namespace camouflet
