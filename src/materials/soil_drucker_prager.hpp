#pragma once
// Strength `soil_drucker_prager` (Wang, Lu, Hao, Chong 2005, eqs. 20-23):
//   sqrt(J2) = Y = (alpha I1 + k (1 - D)) (1 + beta ln(eps_dot_eff / eps_dot_0)),
// I1 = 3 p with p the (gauge) pressure, compression positive; the rate factor
// is applied only for eps_dot_eff > eps_dot_0 (never below 1);
// eps_dot_eff = sqrt(2/3 e_dot:e_dot) of the deviatoric strain rate (eq. 22).
// Non-associated Prandtl-Reuss flow (eq. 23): elastic trial with shear
// modulus G, then radial return in the deviatoric plane (no dilatancy). The
// cohesion is carried by the bonds and softens with the bond damage D (our
// choice, theory section); beyond the apex p <= -k(1-D)/(3 alpha) the yield
// stress is zero and the deviator vanishes (tension cut-off).
#include <memory>

#include "core/parameters.hpp"
#include "materials/material.hpp"

namespace camouflet {

struct SoilDruckerPragerParameters {
  double shear_modulus = 0.0;          // G, Pa
  double friction_slope = 0.0;         // alpha
  double cohesion = 0.0;               // k, Pa
  double rate_sensitivity = 0.0;       // beta
  double reference_strain_rate = 0.0;  // eps_dot_0, 1/s
};

class SoilDruckerPrager final : public StrengthModel {
 public:
  explicit SoilDruckerPrager(const SoilDruckerPragerParameters& p) : p_(p) {}
  std::string type() const override { return "soil_drucker_prager"; }
  void initialise(MaterialPoints& pts) const override;
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override;

  // Yield limit sqrt(J2) of eq. 21 at pressure p (Pa), effective strain rate (1/s) and damage.
  double yield_limit(double pressure, double effective_strain_rate, double damage) const;
  const SoilDruckerPragerParameters& parameters() const { return p_; }
  // The Mohr-Coulomb angle whose triaxial-compression meridian the cone matches:
  // alpha = 2 sin(phi) / (sqrt(3) (3 - sin(phi))), so sin(phi) = 3 sqrt(3) alpha / (2 + sqrt(3) alpha).
  std::optional<double> friction_angle() const override;

 private:
  SoilDruckerPragerParameters p_;
};

std::shared_ptr<const SoilDruckerPrager> make_soil_drucker_prager(Parameters& p);

}  // namespace camouflet
