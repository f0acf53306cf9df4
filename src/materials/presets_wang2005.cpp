// Material presets from the seed paper (Wang, Lu, Hao, Chong, Computers and
// Structures 83 (2005) 339-356), exactly as a case file would give them.
#include "materials/registry.hpp"

namespace camouflet {

namespace {

SourceLocation preset_location(const std::string& preset, const std::string& key) {
  return SourceLocation{"preset " + preset, 0, 0, key};
}

MaterialPreset tnt_wang2005() {
  // Table 5: TNT, JWL with programmed burn (e0 per unit initial volume).
  const std::string name = "tnt_wang2005";
  MaterialPreset m;
  m.description = "TNT, JWL + programmed burn (Wang et al. 2005, Table 5; Dobratz & Crawford 1985)";
  m.eos.set_string("type", "jwl", preset_location(name, "eos.type"));
  m.eos.set_number("density", 1630.0, preset_location(name, "eos.density"));
  m.eos.set_number("c1", 373.8e9, preset_location(name, "eos.c1"));
  m.eos.set_number("c2", 3.747e9, preset_location(name, "eos.c2"));
  m.eos.set_number("r1", 4.15, preset_location(name, "eos.r1"));
  m.eos.set_number("r2", 0.9, preset_location(name, "eos.r2"));
  m.eos.set_number("omega", 0.35, preset_location(name, "eos.omega"));
  m.eos.set_number("e0", 6.0e9, preset_location(name, "eos.e0"));
  m.eos.set_number("detonation_velocity", 6930.0, preset_location(name, "eos.detonation_velocity"));
  return m;
}

MaterialPreset steel_1006_wang2005() {
  // Table 4 (Autodyn STEEL 1006): linear bulk response p = K (rho / rho0 - 1).
  const std::string name = "steel_1006_wang2005";
  MaterialPreset m;
  m.description = "Steel 1006, Johnson-Cook (Wang et al. 2005, Table 4; Autodyn STEEL 1006)";
  m.eos.set_string("type", "linear", preset_location(name, "eos.type"));
  m.eos.set_number("density", 7896.0, preset_location(name, "eos.density"));
  m.eos.set_number("bulk_modulus", 200.0e9, preset_location(name, "eos.bulk_modulus"));
  auto s = [&](const std::string& key, double v) {
    m.strength.set_number(key, v, preset_location(name, "strength." + key));
  };
  m.strength.set_string("type", "johnson_cook", preset_location(name, "strength.type"));
  s("shear_modulus", 81.8e9);
  s("yield_stress", 350.0e6);
  s("hardening_modulus", 275.0e6);
  s("hardening_exponent", 0.36);
  s("rate_coefficient", 0.022);
  s("thermal_exponent", 1.0);
  s("room_temperature", 300.0);
  s("melt_temperature", 1811.0);
  s("specific_heat", 452.0);
  return m;
}

}  // namespace

CAMOUFLET_REGISTER_PRESET("tnt_wang2005", tnt_wang2005);
CAMOUFLET_REGISTER_PRESET("steel_1006_wang2005", steel_1006_wang2005);

}  // namespace camouflet
