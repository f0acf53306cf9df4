#pragma once
// The Chapman-Jouguet state of a JWL explosive: the point where the Rayleigh
// line from the unreacted state (rho0, p = 0) is tangent to the Hugoniot of
// the detonation products (Fickett & Davis, "Detonation", 1979, ch. 2).
#include <stdexcept>
#include <string>

namespace camouflet {

// JWL parameters (Wang et al. 2005, eq. 37 and Table 5; Lee, Hornig & Kury 1968):
// p = C1 (1 - w/(R1 V)) exp(-R1 V) + C2 (1 - w/(R2 V)) exp(-R2 V) + w E / V,
// V = rho0 / rho, E = internal energy per unit *initial* volume = rho0 e.
struct JwlParameters {
  double density = 0.0;  // kg/m^3, unreacted explosive rho0
  double c1 = 0.0;       // Pa
  double c2 = 0.0;       // Pa
  double r1 = 0.0;
  double r2 = 0.0;
  double omega = 0.0;
  double e0 = 0.0;  // J/m^3, detonation energy per unit initial volume
};

// JWL pressure (Pa) at relative volume V and E (J/m^3 of initial volume).
double jwl_pressure(const JwlParameters& p, double relative_volume, double energy_per_initial_volume);

struct CjState {
  double detonation_velocity = 0.0;  // m/s
  double pressure = 0.0;             // Pa
  double density = 0.0;              // kg/m^3
  double particle_velocity = 0.0;    // m/s
  double relative_volume = 0.0;      // V_CJ = rho0 / rho_CJ
};

// Thrown when no CJ state exists; `key` names the JWL parameter to blame.
class CjStateError : public std::runtime_error {
 public:
  CjStateError(std::string key, const std::string& message)
      : std::runtime_error(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

CjState chapman_jouguet_state(const JwlParameters& p);

}  // namespace camouflet
