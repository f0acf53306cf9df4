#pragma once
// JWL equation of state of detonation products with programmed burn
// (Wang et al. 2005, eq. 37 and Table 5; programmed_burn.hpp).
//
// Case-file keys (block `eos`, type = "jwl"):
//   density              kg/m^3  unreacted density rho0
//   c1, c2               Pa      (A, B in many tables)
//   r1, r2, omega        -
//   e0                   J/m^3   detonation energy per unit *initial volume*, as
//                                tables give it; the specific energy carried by
//                                the points is e = e0 / rho0 (J/kg), so that
//                                the JWL term w E / V becomes w rho e
//   detonation_velocity  m/s     optional, default: the computed CJ velocity
//   burn_width_factor    -       n_burn of the burn ramp, default 1.5
//
// p = F p_JWL(rho, e) with the burn fraction F = max(time ramp, volumetric
// fraction) (programmed_burn.hpp; LS-DYNA *MAT_HIGH_EXPLOSIVE_BURN does the
// same): uncompressed unburnt explosive carries no pressure. It carries its
// full chemical energy e0 / rho0 from the start; the sound speed is that of the
// products at the current state whatever F, so the time step never grows when
// the front arrives.
#include "materials/cj_state.hpp"
#include "materials/material.hpp"

namespace camouflet {

class JwlEos : public EquationOfState {
 public:
  JwlEos(const JwlParameters& p, double detonation_velocity, double burn_width_factor);

  std::string type() const override { return "jwl"; }
  bool programmed_burn() const override { return true; }
  double reference_density() const override { return p_.density; }
  double reference_specific_energy() const override { return p_.e0 / p_.density; }
  void register_state(MaterialPoints& pts) const override;
  void evaluate(MaterialPoints& pts, const MaterialContext& ctx, bool commit) const override;
  void place(MaterialPoints& pts, std::span<const std::array<double, 3>> positions,
             const std::vector<DetonationPoint>& detonations) const override;

  const JwlParameters& parameters() const { return p_; }
  const CjState& cj_state() const { return cj_; }
  double detonation_velocity() const { return detonation_velocity_; }
  double burn_width_factor() const { return burn_width_factor_; }

  // Fully burnt products: pressure (Pa) and squared sound speed (m^2/s^2) at
  // density rho and specific energy e (J/kg).
  double products_pressure(double rho, double e) const;
  double products_sound_speed_squared(double rho, double e) const;

 private:
  JwlParameters p_;
  CjState cj_;
  double detonation_velocity_;
  double burn_width_factor_;
};

}  // namespace camouflet
