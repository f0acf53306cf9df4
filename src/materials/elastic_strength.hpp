#pragma once
// Isotropic elastic and elastic-perfectly-plastic (von Mises) deviatoric
// response: the shear half of linear elasticity and the simplest metal
// plasticity. Hypoelastic: s_dot = 2 G dev(D) on the Jaumann-rotated
// deviator that Material::update hands over.
#include "materials/material.hpp"

namespace camouflet {

class ElasticStrength : public StrengthModel {
 public:
  explicit ElasticStrength(double shear_modulus);
  std::string type() const override { return "elastic"; }
  double shear_modulus() const { return shear_; }
  void initialise(MaterialPoints& pts) const override;
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override;

 protected:
  double shear_;  // Pa
};

class VonMisesStrength final : public ElasticStrength {
 public:
  VonMisesStrength(double shear_modulus, double yield_stress);
  std::string type() const override { return "von_mises"; }
  double yield_stress() const { return yield_; }
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override;

 private:
  double yield_;  // Pa, uniaxial yield stress
};

}  // namespace camouflet
