#include "materials/sandy_clay_preset.hpp"

#include <stdexcept>

namespace camouflet {

MaterialPreset sandy_clay_wang2005() {
  MaterialPreset m;
  m.description =
      "Sandy clay, three-phase soil model (Wang, Lu, Hao, Chong 2005, Tables 1-2); rho0 = 1917 kg/m^3 "
      "(0.58 solid, 0.38 water, 0.04 air by volume)";
  const SourceLocation here{"preset sandy_clay_wang2005", 0, 0, ""};
  Parameters& e = m.eos;
  e.set_string("type", "three_phase_soil", here);
  // Order fixed by the density check 0.58*2650 + 0.38*1000 + 0.04*1.2 = 1917 ~ 1920 (physics.md).
  e.set_number("solid_fraction", 0.58, here);
  e.set_number("water_fraction", 0.38, here);
  e.set_number("air_fraction", 0.04, here);
  e.set_number("solid_density", 2650.0, here);
  e.set_number("solid_sound_speed", 4500.0, here);
  e.set_number("solid_exponent", 3.0, here);
  e.set_number("water_density", 1000.0, here);
  e.set_number("water_sound_speed", 1500.0, here);
  e.set_number("water_exponent", 7.0, here);
  e.set_number("air_density", 1.2, here);
  e.set_number("air_sound_speed", 340.0, here);
  e.set_number("air_exponent", 1.4, here);
  e.set_number("friction_coefficient", 0.56, here);
  e.set_number("friction_modulus", 165e6, here);
  e.set_number("bond_modulus", 20e6, here);
  // Our choice: the hydrostatic tensile limit equals the apex k / (3 alpha) of the
  // Drucker-Prager surface below, so the EOS and strength cut-offs coincide.
  e.set_number("tensile_strength", 0.2e6 / (3.0 * 0.25), here);

  Parameters& s = m.strength;
  s.set_string("type", "soil_drucker_prager", here);
  s.set_number("shear_modulus", 55e6, here);
  s.set_number("friction_slope", 0.25, here);
  s.set_number("cohesion", 0.2e6, here);  // "k = 0.2" read as MPa (physics.md)
  s.set_number("rate_sensitivity", 0.1, here);
  s.set_number("reference_strain_rate", 0.01 / 60.0, here);  // 1 %/min

  Parameters& d = m.damage;
  d.set_string("type", "three_phase_soil", here);
  d.set_number("strain_coefficient", 5.0, here);
  d.set_number("exponent", 1.0, here);
  return m;
}

double friction_modulus_for_seismic_velocity(const Parameters& eos, double shear_modulus,
                                             double seismic_velocity) {
  Parameters e = eos;  // read through a copy: the preset's keys stay unconsumed
  const double as = e.number("solid_fraction"), aw = e.number("water_fraction"),
               ag = e.number("air_fraction");
  const double rho_s = e.number("solid_density"), c_s = e.number("solid_sound_speed");
  const double rho_w = e.number("water_density"), c_w = e.number("water_sound_speed");
  const double rho_g = e.number("air_density"), c_g = e.number("air_sound_speed");
  const double rho0 = as * rho_s + aw * rho_w + ag * rho_g;
  const double k_s = rho_s * c_s * c_s, k_w = rho_w * c_w * c_w;
  const double k_air = rho_g * c_g * c_g;  // k_g p0 (eq. 15)
  // Theory section 5: K0 = [a_s/K_s + 1/(K_f + f K_p + E0/a_p)]^-1, and the
  // P-wave modulus K0 + 4G/3 = rho0 c^2.
  const double k0 = rho0 * seismic_velocity * seismic_velocity - 4.0 / 3.0 * shear_modulus;
  const double k_pore = 1.0 / (1.0 / k0 - as / k_s);
  const double k_fluid = 1.0 / (aw / k_w + ag / k_air);
  const double friction_part = k_pore - k_fluid - e.number("bond_modulus") / (aw + ag);
  if (!(k0 > 0.0 && k_pore > 0.0 && friction_part > 0.0))
    throw std::invalid_argument("seismic velocity below what the phases and bonds alone give");
  return friction_part / e.number("friction_coefficient");
}

// Wang et al. 2005 Table 2 with K_p raised so that the small-strain P-wave
// speed is Table 1's seismic velocity, 1400 m/s (K_p = 6.76 GPa instead of
// 165 MPa): the calibration a user needs for the TM 5-855-1 peak stresses,
// which scale with rho c (theory section 12).
MaterialPreset sandy_clay_wang2005_seismic() {
  MaterialPreset m = sandy_clay_wang2005();
  m.description =
      "Sandy clay, three-phase soil model (Wang et al. 2005, Tables 1-2) with the skeleton friction "
      "modulus K_p calibrated to Table 1's seismic velocity 1400 m/s (theory manual section 12)";
  const SourceLocation here{"preset sandy_clay_wang2005_seismic", 0, 0, ""};
  Parameters strength = m.strength;  // a copy, as above
  m.eos.set_number("friction_modulus",
                   friction_modulus_for_seismic_velocity(m.eos, strength.number("shear_modulus"), 1400.0),
                   here);
  return m;
}

CAMOUFLET_REGISTER_PRESET("sandy_clay_wang2005", sandy_clay_wang2005);
CAMOUFLET_REGISTER_PRESET("sandy_clay_wang2005_seismic", sandy_clay_wang2005_seismic);

}  // namespace camouflet
