#pragma once
// Johnson-Cook strength (Johnson & Cook 1983; Wang et al. 2005, eq. 36):
//   Y = [Y0 + B eps_p^n] [1 + C ln(rate*)] [1 - T_H^m],
//   rate* = eps_p_dot / eps_dot_0 with the reference rate eps_dot_0 = 1 /s
//   (key `reference_strain_rate`), T_H = (T - T_room) / (T_melt - T_room).
// Conventions (documented choices):
// * rate* < 1 gives no rate term (the factor is held at 1, as in Autodyn), so
//   the yield stress never falls below the quasi-static curve;
// * T < T_room: no thermal term; T >= T_melt: Y = 0 (melt);
// * the rate is the plastic strain rate of the step, Delta eps_p / dt, solved
//   together with the hardening in the return map (Newton on Delta eps_p,
//   safeguarded by bisection), so the returned stress lies exactly on the
//   current yield surface;
// * temperature rises adiabatically from plastic work, dT = chi Y d eps_p / (rho C_v)
//   with the Taylor-Quinney factor chi (default 0.9), using the temperature at
//   the start of the step in the yield stress (explicit in T); `isothermal =
//   true` switches the heating off (tests, quasi-static calibration).
// Keys: shear_modulus, yield_stress, hardening_modulus (Pa), hardening_exponent,
// rate_coefficient, thermal_exponent, room_temperature (K, default 300),
// melt_temperature (K), specific_heat (J/kg K), taylor_quinney (default 0.9),
// reference_strain_rate (1/s, default 1), isothermal (default false).
// Failure: the `johnson_cook` damage model (johnson_cook_failure.hpp).
#include "materials/material.hpp"

namespace camouflet {

struct JohnsonCookParameters {
  double shear_modulus = 0.0;          // Pa
  double yield_stress = 0.0;           // Pa, Y0 (the "A" of most tables)
  double hardening_modulus = 0.0;      // Pa, B
  double hardening_exponent = 1.0;     // n
  double rate_coefficient = 0.0;       // C
  double thermal_exponent = 1.0;       // m
  double room_temperature = 300.0;     // K
  double melt_temperature = 0.0;       // K
  double specific_heat = 0.0;          // J/(kg K)
  double taylor_quinney = 0.9;         // chi
  double reference_strain_rate = 1.0;  // 1/s
  bool isothermal = false;
};

// Yield stress (Pa) at plastic strain, plastic strain rate (1/s) and temperature (K).
double johnson_cook_yield(const JohnsonCookParameters& p, double plastic_strain, double plastic_strain_rate,
                          double temperature);

class JohnsonCookStrength : public StrengthModel {
 public:
  explicit JohnsonCookStrength(const JohnsonCookParameters& p) : p_(p) {}
  std::string type() const override { return "johnson_cook"; }
  void initialise(MaterialPoints& pts) const override;
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override;
  const JohnsonCookParameters& parameters() const { return p_; }

 private:
  JohnsonCookParameters p_;
};

}  // namespace camouflet
