#pragma once
// RHT concrete strength with its damage (Riedel 2000; Wang et al. 2005,
// eqs. 24-31): elastic trial, hardening from the elastic-limit to the failure
// surface, damage-driven softening to the residual surface, and a radial
// return in the deviatoric plane. Damage lives here because it shapes the
// surfaces; it is written to MaterialPoints::damage.
#include <memory>

#include "core/parameters.hpp"
#include "materials/material.hpp"
#include "materials/rht_surfaces.hpp"

namespace camouflet {

class RhtStrength final : public StrengthModel {
 public:
  explicit RhtStrength(const RhtParameters& p);
  std::string type() const override { return "rht"; }
  void register_state(MaterialPoints& pts) const override;
  void initialise(MaterialPoints& pts) const override;
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override;
  const RhtParameters& parameters() const { return prm_; }

 private:
  RhtParameters prm_;
};

// Equivalent strain rate sqrt(2/3 D:D) (1/s), the rate the RHT factors use.
double rht_equivalent_strain_rate(const SymTensor& strain_rate);

std::shared_ptr<const StrengthModel> make_rht_strength(Parameters& block);

}  // namespace camouflet
