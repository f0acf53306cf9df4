#pragma once
// The three strength surfaces of the RHT concrete model (Riedel 2000; Wang et
// al. 2005, eqs. 24-31) as plain functions of normalised pressure p* = p/f_c,
// Lode angle and strain-rate factor. The strength model (rht_strength.cpp)
// combines them with hardening, damage and the return map. Every formula and
// every departure from the paper's printed form is in docs/theory/rht-concrete.md.

namespace camouflet {

struct RhtParameters {
  double compressive_strength = 35e6;    // Pa, f_c
  double failure_a = 1.6;                // A
  double failure_n = 0.61;               // N
  double tensile_ratio = 0.1;            // f_t / f_c
  double meridian_ratio_0 = 0.6805;      // Q2,0 (tensile/compressive meridian at p* = 0)
  double meridian_ratio_slope = 0.0105;  // BQ
  double compressive_rate_exponent = 0.032;
  double tensile_rate_exponent = 0.036;
  double compressive_reference_rate = 3e-5;  // 1/s
  double tensile_reference_rate = 3e-6;      // 1/s
  double elastic_ratio_tension = 0.7;        // f_t,el / f_t
  double elastic_ratio_compression = 0.53;   // f_c,el / f_c
  double crush_pressure = 23.3e6;            // Pa, p_e: the cap starts
  double compaction_pressure = 6e9;          // Pa, p_s: the cap closes
  double pre_softening_plastic_strain = 1.93e-3;
  double residual_b = 1.6;   // B
  double residual_m = 0.61;  // M
  double damage_d1 = 0.04;
  double damage_d2 = 1.0;
  double minimum_failure_strain = 0.01;
  double shear_modulus = 16.7e9;           // Pa, G_initial
  double residual_shear_modulus = 2.17e9;  // Pa, G_residual
  // Derived (rht_finalise): p* of the static uniaxial-compression point.
  double uniaxial_compression_point = 0.0;
};

// Computes the derived members; call once after setting the parameters.
void rht_finalise(RhtParameters& m);

// Strain-rate factor: (rate/rate_0)^beta (1 below the reference rate), the
// compressive one for p* >= 1/3, the tensile one for p* <= -f_t*/3, linear in
// p* between (the transition of the Autodyn and LS-DYNA implementations).
double rht_rate_factor(const RhtParameters& m, double strain_rate, double p_star);

// Meridian ratio Q2 = Q2,0 + BQ p*, kept inside the Willam-Warnke range [0.5, 1].
double rht_meridian_ratio(const RhtParameters& m, double p_star);

// Willam-Warnke third-invariant factor R3 for cos(3 theta) = 3 sqrt(3)/2 J3/J2^1.5
// (theta = 0 tensile meridian: R3 = Q2; theta = 60 deg compressive: R3 = 1).
double rht_r3(double cos3theta, double q2);

// Normalised compressive meridian of the static failure surface Y*_c(p*):
// the power law A (p* + f_t*)^N above its uniaxial-compression point, and
// below it straight lines through the uniaxial-tension point to zero at the
// hydrostatic tensile strength -f_t*.
double rht_static_meridian(const RhtParameters& m, double p_star);

// Uniaxial-compression point of the static power law: p*_uc with 3 p*_uc = A(p*_uc + f_t*)^N.
double rht_uniaxial_compression_pressure(const RhtParameters& m);

// Failure surface Y_fail (Pa) at pressure p (Pa), rate factor F and Lode
// angle: f_c F Y*_c(p*/F) R3 (eq. 24 with the rate scaling of the docs).
double rht_failure_strength(const RhtParameters& m, double pressure, double rate_factor, double cos3theta);

// Elastic-limit fraction F_elastic(p*) F_CAP(p) of the failure surface (eq. 25).
double rht_elastic_fraction(const RhtParameters& m, double pressure, double rate_factor);

// Residual surface (Pa): f_c B p*^M R3 (eq. 27), zero in tension.
double rht_residual_strength(const RhtParameters& m, double pressure, double cos3theta);

// Plastic strain to failure D1 (p* + f_t*)^D2, at least eps_f,min (eq. 29).
double rht_failure_strain(const RhtParameters& m, double pressure);

}  // namespace camouflet
