#include "materials/sandy_clay_preset.hpp"

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

CAMOUFLET_REGISTER_PRESET("sandy_clay_wang2005", sandy_clay_wang2005);

}  // namespace camouflet
