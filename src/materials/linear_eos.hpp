#pragma once
// Linear equation of state: p = K (rho / rho0 - 1), independent of energy.
// The volumetric half of isotropic linear elasticity.
#include "materials/material.hpp"

namespace camouflet {

class LinearEos final : public EquationOfState {
 public:
  LinearEos(double reference_density, double bulk_modulus);
  std::string type() const override { return "linear"; }
  double reference_density() const override { return rho0_; }
  double bulk_modulus() const { return bulk_; }
  void evaluate(MaterialPoints& pts, const MaterialContext& ctx, bool commit) const override;

 private:
  double rho0_;  // kg/m^3
  double bulk_;  // Pa
};

}  // namespace camouflet
