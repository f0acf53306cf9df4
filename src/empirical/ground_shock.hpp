#pragma once
// Free-field ground shock from a buried charge after TM 5-855-1 (1986), ch. 5,
// as used by Wang et al. 2005 §5.3 and §5.5. Every peak is a power law in the
// scaled distance Z = R / W^(1/3) (m/kg^(1/3)):
//
//   q(R) = f · K · W^e · Z^(-m)
//
// with the coupling factor f, the attenuation coefficient n and
//   peak stress        K_p [Pa]             e = 0     m = n
//   peak velocity      K_v [m/s]            e = 0     m = n
//   peak acceleration  K_a [m/s^2·kg^(1/3)] e = -1/3  m = n + 1
//   peak displacement  K_d [m/kg^(1/3)]     e = +1/3  m = n - 1
//
// The coefficients come either from the manual's general equations and a soil
// (density, seismic velocity), or from the numbers printed in the paper for
// its sandy clay. docs/theory/tm5-855-1.md derives both and compares them.
#include <string>

namespace camouflet::empirical {

// One free-field peak as a function of range.
struct PowerLaw {
  double coefficient = 0.0;      // K, SI units of the quantity times kg^(-e)
  double charge_exponent = 0.0;  // e: power of W outside the scaled distance
  double range_exponent = 0.0;   // m: decay exponent in Z

  // q(R) for charge mass W (kg, TNT), coupling f and range R (m).
  double value(double charge_mass, double coupling, double range) const;
  // (1 / (R2 - R1)) ∫_{R1}^{R2} q(R) dR, in closed form (Wang et al. 2005 §5.5).
  double span_average(double charge_mass, double coupling, double range_near, double range_far) const;
};

// The soil properties the manual's equations need.
struct Soil {
  double density = 0.0;           // kg/m^3, in situ (total) density
  double seismic_velocity = 0.0;  // m/s, loading wave speed c
};

// The paper's sandy clay (Wang et al. 2005, Table 1: total density ~1920 kg/m^3,
// seismic velocity 1400 m/s, attenuation coefficient n = 2-2.5).
Soil wang2005_sandy_clay();

struct GroundShockLaw {
  double attenuation = 0.0;  // n
  PowerLaw stress;           // Pa, compression positive
  PowerLaw velocity;         // m/s
  PowerLaw acceleration;     // m/s^2
  PowerLaw displacement;     // m
  std::string source;        // where the coefficients come from, for reports
};

// The manual's general equations (imperial units, R in ft, W in lb, c in ft/s,
// ρc in psi/(ft/s)) converted exactly to SI:
//   P0 = f·ρc·160·(R/W^(1/3))^-n psi,      V0 = f·160·(R/W^(1/3))^-n ft/s,
//   a0·W^(1/3) = f·50·c·(R/W^(1/3))^-(n+1) g,
//   d0/W^(1/3) = f·500·(1/c)·(R/W^(1/3))^-(n-1) ft.
// Throws InputError when the soil or n is not positive.
GroundShockLaw tm5_855_1(const Soil& soil, double attenuation);

// The coefficients printed in Wang et al. 2005 for n = 2 and n = 2.5:
// stress 22 / 15 MPa (eqs. 38-39), velocity 7.38 / 4.62 m/s and acceleration
// 2338 / 1464 g (§5.5). The printed accelerations hold W^(-1/3) of the paper's
// W = 100 kg; they are stored as K_a = printed · 100^(1/3) so that other
// charge masses scale as the manual says. The paper gives no displacement:
// that law is the manual's, with the paper's soil. Throws InputError for any
// other n.
GroundShockLaw wang2005(double attenuation);

// Scaled distance Z = R / W^(1/3) (m/kg^(1/3)).
double scaled_distance(double range, double charge_mass);

}  // namespace camouflet::empirical
