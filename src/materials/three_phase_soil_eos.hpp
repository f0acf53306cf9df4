#pragma once
// Equation of state `three_phase_soil` (Wang, Lu, Hao, Chong 2005, eqs. 11-17):
// grains, pore water, pore air and the bonded, frictional skeleton. The law
// itself is in three_phase_soil_law.hpp; this class reads the parameters,
// keeps the compaction history of every point and runs the law over a batch.
//
// `pressure` is the gauge mean stress (absolute pressure minus the ambient
// p0 = rho_g0 c_g0^2 / k_g), so the reference state is stress free. History
// columns (all gauge pressures in Pa, volumes over the initial volume V0):
//   soil_min_volume         V/V0 at the maximum compaction reached
//   soil_max_pressure       pressure there (start of the unloading branch)
//   soil_max_pore_pressure  pore pressure there
//   soil_pore_pressure      current pore pressure p_b
//   soil_pore_volume        current pore volume V_p / V0
//   soil_eos_branch         0 loading, 1 unloading/reloading, 2 tension cut-off
//   soil_max_water_volume,  v_w and v_s at the maximum compaction (/V0): the
//   soil_max_solid_volume   unloading branch's fixed end, kept to save two pow per solve
//   soil_trial_*            the predictor's root and the density and damage it was
//                           solved at; the corrector at the same inputs takes it
//                           (the law is barotropic) instead of solving again
// The bond damage D of eq. 17 is read from the `damage` column (written by
// the damage model `three_phase_soil`).
#include <memory>

#include "core/parameters.hpp"
#include "materials/material.hpp"
#include "materials/three_phase_soil_law.hpp"

namespace camouflet {

class ThreePhaseSoilEos final : public EquationOfState {
 public:
  explicit ThreePhaseSoilEos(const ThreePhaseSoilConstants& constants, double reference_density);
  std::string type() const override { return "three_phase_soil"; }
  double reference_density() const override { return reference_density_; }
  void register_state(MaterialPoints& pts) const override;
  void evaluate(MaterialPoints& pts, const MaterialContext& ctx, bool commit) const override;

  const ThreePhaseSoilConstants& constants() const { return constants_; }

 private:
  ThreePhaseSoilConstants constants_;
  double reference_density_;  // kg/m^3, sum of alpha_i rho_i0
};

// Reads the `three_phase_soil` keys (docs/theory/three-phase-soil.md lists them).
std::shared_ptr<const ThreePhaseSoilEos> make_three_phase_soil_eos(Parameters& p);

}  // namespace camouflet
