// Named concrete parameter sets (registered presets, materials/registry.hpp).
#include "materials/concrete_presets.hpp"

#include <string>

namespace camouflet {

// Wang, Lu, Hao, Chong 2005, Table 3 (RHT strength, P-alpha EOS), with what
// the table omits from the Autodyn CONC-35MPA library set (Riedel 2000): the
// porous sound speed, B0 = B1, BQ, the elastic strength ratios and the rate
// reference rates. Q2,0 = 0.6805 is the library value; the paper's 0.6085 is
// read as a transposition of its digits (docs/theory/rht-concrete.md).
MaterialPreset concrete_35mpa_wang2005() {
  const std::string name = "concrete_35mpa_wang2005";
  // Errors about a preset value name the preset and the key.
  auto at = [&](const std::string& key) { return SourceLocation{"preset " + name, 0, 0, key}; };
  MaterialPreset p;
  p.description =
      "35 MPa concrete, RHT strength + P-alpha EOS: Wang et al. 2005 Table 3, "
      "gaps filled from the Autodyn CONC-35MPA library (Riedel 2000): porous sound speed 2920 m/s, "
      "B0 = B1 = 1.22, BQ = 0.0105, Q2,0 = 0.6805 (paper prints 0.6085), elastic strength ratios 0.7/0.53, "
      "reference rates 3e-5 /s (compression) and 3e-6 /s (tension)";
  Parameters& e = p.eos;
  e.set_string("type", "p_alpha", at("eos.type"));
  e.set_number("density", 2314.0, at("eos.density"));
  e.set_number("solid_density", 2750.0, at("eos.solid_density"));
  e.set_number("crush_pressure", 23.3e6, at("eos.crush_pressure"));
  e.set_number("compaction_pressure", 6.0e9, at("eos.compaction_pressure"));
  e.set_number("compaction_exponent", 3.0, at("eos.compaction_exponent"));
  e.set_number("porous_sound_speed", 2920.0, at("eos.porous_sound_speed"));
  e.set_number("a1", 35.27e9, at("eos.a1"));
  e.set_number("a2", 39.58e9, at("eos.a2"));
  e.set_number("a3", 9.04e9, at("eos.a3"));
  e.set_number("t1", 35.27e9, at("eos.t1"));
  e.set_number("t2", 0.0, at("eos.t2"));
  e.set_number("b0", 1.22, at("eos.b0"));
  e.set_number("b1", 1.22, at("eos.b1"));

  Parameters& s = p.strength;
  s.set_string("type", "rht", at("strength.type"));
  s.set_number("compressive_strength", 35e6, at("strength.compressive_strength"));
  s.set_number("tensile_strength", 3.5e6, at("strength.tensile_strength"));
  s.set_number("failure_a", 1.6, at("strength.failure_a"));
  s.set_number("failure_n", 0.61, at("strength.failure_n"));
  s.set_number("tensile_meridian_ratio", 0.6805, at("strength.tensile_meridian_ratio"));
  s.set_number("meridian_ratio_slope", 0.0105, at("strength.meridian_ratio_slope"));
  s.set_number("compressive_rate_exponent", 0.032, at("strength.compressive_rate_exponent"));
  s.set_number("tensile_rate_exponent", 0.036, at("strength.tensile_rate_exponent"));
  s.set_number("compressive_reference_rate", 3e-5, at("strength.compressive_reference_rate"));
  s.set_number("tensile_reference_rate", 3e-6, at("strength.tensile_reference_rate"));
  s.set_number("elastic_ratio_tension", 0.7, at("strength.elastic_ratio_tension"));
  s.set_number("elastic_ratio_compression", 0.53, at("strength.elastic_ratio_compression"));
  s.set_number("crush_pressure", 23.3e6, at("strength.crush_pressure"));
  s.set_number("compaction_pressure", 6.0e9, at("strength.compaction_pressure"));
  s.set_number("pre_softening_plastic_strain", 1.93e-3, at("strength.pre_softening_plastic_strain"));
  s.set_number("residual_b", 1.6, at("strength.residual_b"));
  s.set_number("residual_m", 0.61, at("strength.residual_m"));
  s.set_number("damage_d1", 0.04, at("strength.damage_d1"));
  s.set_number("damage_d2", 1.0, at("strength.damage_d2"));
  s.set_number("minimum_failure_strain", 0.01, at("strength.minimum_failure_strain"));
  s.set_number("shear_modulus", 16.7e9, at("strength.shear_modulus"));
  s.set_number("residual_shear_modulus", 2.17e9, at("strength.residual_shear_modulus"));
  return p;
}

CAMOUFLET_REGISTER_PRESET("concrete_35mpa_wang2005", concrete_35mpa_wang2005);

}  // namespace camouflet
