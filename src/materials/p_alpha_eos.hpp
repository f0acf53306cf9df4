#pragma once
// Herrmann's P-alpha compaction model with the Carroll-Holt 1/alpha factor on
// a polynomial solid EOS (Wang et al. 2005, eqs. 32-35), as used for the RHT
// concrete of the paper. docs/theory/rht-concrete.md gives the model, the
// elastic (unloading) branch and every choice made here.
#include <memory>

#include "core/parameters.hpp"
#include "materials/material.hpp"

namespace camouflet {

struct PAlphaParameters {
  double density = 0.0;              // kg/m^3, porous reference density rho_0
  double solid_density = 0.0;        // kg/m^3, rho_s of the matrix
  double crush_pressure = 0.0;       // Pa, p_e: compaction starts
  double compaction_pressure = 0.0;  // Pa, p_s: fully compacted
  double compaction_exponent = 3.0;  // n
  double porous_sound_speed = 0.0;   // m/s, c_e: elastic sound speed at rho_0
  // Polynomial solid EOS, mu = rho_solid / rho_s - 1 (Wang et al. 2005, eq. 35).
  double a1 = 0.0, a2 = 0.0, a3 = 0.0, t1 = 0.0, t2 = 0.0;  // Pa
  double b0 = 0.0, b1 = 0.0;                                // Grueneisen-like energy coefficients
};

// Result of the pressure solve at one state.
struct PAlphaState {
  double pressure = 0.0;          // Pa
  double distension = 1.0;        // alpha = rho_solid / rho, total (elastic + plastic)
  double plastic_distension = 1;  // alpha_p after this state (non-increasing)
  bool crushing = false;          // on the compaction (crush) curve
};

class PAlphaEos final : public EquationOfState {
 public:
  explicit PAlphaEos(const PAlphaParameters& p);
  std::string type() const override { return "p_alpha"; }
  double reference_density() const override { return prm_.density; }
  void register_state(MaterialPoints& pts) const override;
  void evaluate(MaterialPoints& pts, const MaterialContext& ctx, bool commit) const override;

  // --- pieces, public for the tests and the theory manual ---
  // Solid EOS f(mu, e) in Pa (eq. 35 with its energy term).
  double solid_pressure(double mu, double specific_energy) const;
  // Compaction curve alpha(p) between p_e and p_s (the Herrmann crush law).
  double crush_distension(double pressure) const;
  // Inverse of crush_distension: the pressure at which alpha_p was reached.
  double crush_pressure_of(double plastic_distension) const;
  // Distension at the start of crushing, alpha_e (slightly below rho_s/rho_0, see the docs).
  double start_distension() const { return alpha_e_; }
  // Pressure solve at (rho, e) from plastic distension alpha_p. Throws
  // NumericalError naming `point` if the bracketed solve fails.
  PAlphaState solve(double density, double specific_energy, double plastic_distension, long point = -1) const;
  // Bulk sound speed consistent with the branch of `state` (m/s).
  double sound_speed(double density, double specific_energy, const PAlphaState& state) const;

 private:
  double elastic_compliance(double plastic_distension) const;  // kappa, 1/Pa
  double elastic_distension(double pressure, double plastic_distension) const;
  // Pressure on one branch only: elastic with fixed alpha_p, or crush.
  double elastic_pressure(double density, double e, double plastic_distension, long point) const;
  // Elastic branch below p = 0, given the residual r0 < 0 at p = 0.
  double tension_pressure(double density, double e, double plastic_distension, double r0, long point) const;
  double crush_branch_pressure(double density, double e, double p_lo, long point, bool* solid) const;

  PAlphaParameters prm_;
  double alpha_e_ = 1.0;            // distension where crushing starts
  double solid_sound_speed_ = 0.0;  // sqrt(A1 / rho_s)
};

std::shared_ptr<const EquationOfState> make_p_alpha_eos(Parameters& block);

}  // namespace camouflet
