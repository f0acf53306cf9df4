#pragma once
// The pressure-volume law of the three-phase soil (Wang, Lu, Hao, Chong 2005,
// eqs. 11-17; Wang, Hao, Lu 2004), free of any batch or history storage so that
// the EOS, the tests and the documentation share one implementation.
//
// All volumes are normalised by the initial total volume V0, so the total
// "specific volume ratio" is v = V/V0 = rho0/rho and phase i starts at its
// volume fraction alpha_i. Pressures inside this file are absolute (Pa); every
// phase starts at the ambient pressure p0 = rho_g0 c_g0^2 / k_g (eq. 15).
// The derivation and every choice the paper leaves open are in
// docs/theory/three-phase-soil.md.
#include <limits>

namespace camouflet {

// A liquid or solid phase obeying the Tait-type law of eqs. 13 (water) and 14
// (grains): p = p0 + K0/k [(rho/rho0)^k - 1], K0 = rho0 c0^2.
struct TaitPhase {
  double fraction = 0.0;      // initial volume fraction alpha
  double bulk_modulus = 0.0;  // K0 = rho0 c0^2, Pa
  double exponent = 1.0;      // k
  double inverse_exponent = 1.0;

  // Volume (/V0) at absolute pressure p; +inf at or below the spinodal p0 - K0/k,
  // where the law admits no density.
  double volume(double p, double p0) const;
  // Tangent bulk modulus K0 + k (p - p0) of the phase at pressure p (Pa).
  double tangent_modulus(double p, double p0) const { return bulk_modulus + exponent * (p - p0); }
};

// Pore air, isentropic polytropic gas of eq. 15: p = p0 (rho/rho0)^k.
struct AirPhase {
  double fraction = 0.0;
  double exponent = 1.4;
  double inverse_exponent = 1.0 / 1.4;
  double volume(double p, double p0) const;  // +inf for p <= 0
};

struct ThreePhaseSoilConstants {
  TaitPhase solid;
  TaitPhase water;
  AirPhase air;
  double ambient_pressure = 0.0;  // p0, Pa (absolute)
  double friction = 0.0;          // f K_p of eq. 16, Pa per unit Delta V_p / V0
  double bond_modulus = 0.0;      // E0 of eq. 17, Pa
  double tensile_strength = 0.0;  // p_t, Pa: intact tensile limit of the mean stress (gauge)

  double pore_fraction() const { return water.fraction + air.fraction; }
  // Lowest pore pressure the pore fluid admits (its volume diverges there).
  double pore_pressure_floor() const;
  // Skeleton pressure p_e = p_a + p_c (eqs. 16-17) at normalised pore volume v_p
  // and bond damage D, and its derivative d p_e / d v_p.
  double skeleton_pressure(double pore_volume, double damage) const;
  double skeleton_stiffness(double pore_volume, double damage) const;  // -d p_e / d v_p >= 0
  // Initial tangent bulk modulus K0 = -dp/dv at v = 1 (hand derivation in the theory section).
  double initial_tangent_modulus() const;
};

// Which part of the law gave the pressure.
enum class SoilBranch : int { loading = 0, unloading = 1, tension_cutoff = 2 };

// Maximum compaction reached so far: the start of the unloading branch.
struct SoilCompaction {
  double volume = 1.0;         // v_min = min V/V0 on the loading (virgin) curve
  double pressure = 0.0;       // absolute p there, Pa
  double pore_pressure = 0.0;  // absolute p_b there, Pa
  // v_w(p_b,max) and v_s(p_max) (/V0), the unloading branch's fixed end: NaN
  // = computed from the pressures above; a caller that stores them saves two
  // pow calls per solve (they change only when the compaction does).
  double water_volume = std::numeric_limits<double>::quiet_NaN();
  double solid_volume = std::numeric_limits<double>::quiet_NaN();
};

struct SoilState {
  double pressure = 0.0;       // absolute, Pa
  double pore_pressure = 0.0;  // absolute, Pa
  double pore_volume = 0.0;    // V_p / V0
  double bulk_modulus = 0.0;   // -v dp/dv on the current branch, Pa
  // -v dp/dv of the stiffest stretch a release from this state meets, Pa
  // (soil_release_modulus; at the cut-off, the branch's there): the time step's.
  double release_modulus = 0.0;
  double water_volume = 0.0;   // v_w at the pore pressure of the last evaluation (/V0)
  double solid_volume = 0.0;   // v_s at the pressure of the last evaluation (/V0)
  SoilBranch branch = SoilBranch::loading;
  int iterations = 0;
  bool converged = false;
};

// Pressure on the loading (virgin) curve at total volume v for bond damage D:
// the monotone root of v_s(p) + v_w(p_b) + v_g(p_b) = v with p = p_b + p_e
// (eqs. 11-12) in the pore pressure p_b. `pore_pressure_guess` warm-starts it.
SoilState soil_loading_state(const ThreePhaseSoilConstants& c, double v, double damage,
                             double pore_pressure_guess);

// Pressure on the unloading branch from `from` (water and grains unload
// elastically, the compacted air voids and the skeleton stay as they were).
// `pressure_guess` (absolute) warm-starts it.
SoilState soil_unloading_state(const ThreePhaseSoilConstants& c, double v, const SoilCompaction& from,
                               double damage, double pressure_guess);

// Tangent bulk modulus -v dp/dv of the unloading branch at total volume v,
// pressure p and pore pressure p_b (absolute): water and grains in series.
double soil_unloading_modulus(const ThreePhaseSoilConstants& c, double v, double pressure,
                              double pore_pressure);
// The same with v_w(p_b) and v_s(p) already known (no pow).
double soil_unloading_modulus(const ThreePhaseSoilConstants& c, double v, double pressure,
                              double pore_pressure, double water_volume, double solid_volume);

// The stiffest tangent -v dp/dv that a release from (v, p, p_b; damage D)
// meets on the unloading branch: the pore pressure falls with the total
// pressure (the skeleton stress stays locked), and where it reaches the
// cavitation pressure before the total pressure reaches the cut-off, the rest
// of the release is carried by the grains alone. Otherwise the water-solid
// modulus of soil_unloading_modulus.
double soil_release_modulus(const ThreePhaseSoilConstants& c, double v, double pressure, double pore_pressure,
                            double water_volume, double solid_volume, double damage);

// The whole law: loading when v < from.volume, otherwise unloading; the
// tension cut-off p >= p0 - (1 - D) p_t on either branch. The guesses only
// speed up the solves (absolute pressure and pore pressure).
SoilState soil_state(const ThreePhaseSoilConstants& c, double v, const SoilCompaction& from, double damage,
                     double pressure_guess, double pore_pressure_guess);

// Total volume on the loading curve for a given pore pressure (explicit: used
// by the tests and the documentation to tabulate the curve independently).
double soil_loading_volume(const ThreePhaseSoilConstants& c, double pore_pressure, double damage,
                           double* pressure = nullptr);

}  // namespace camouflet
