// Named concrete parameter sets (registered presets, materials/registry.hpp).
#include "materials/concrete_presets.hpp"

namespace camouflet {

// Wang, Lu, Hao, Chong 2005, Table 3 (RHT strength, P-alpha EOS), with what
// the table omits from the Autodyn CONC-35MPA library set (Riedel 2000): the
// porous sound speed, B0 = B1, BQ, the elastic strength ratios and the rate
// reference rates. Q2,0 = 0.6805 is the library value; the paper's 0.6085 is
// read as a transposition of its digits (docs/theory/rht-concrete.md).
MaterialPreset concrete_35mpa_wang2005() {
  MaterialPreset p;
  p.description =
      "35 MPa concrete, RHT strength + P-alpha EOS: Wang et al. 2005 Table 3, "
      "gaps filled from the Autodyn CONC-35MPA library (Riedel 2000): porous sound speed 2920 m/s, "
      "B0 = B1 = 1.22, BQ = 0.0105, Q2,0 = 0.6805 (paper prints 0.6085), elastic strength ratios 0.7/0.53, "
      "reference rates 3e-5 /s (compression) and 3e-6 /s (tension)";
  Parameters& e = p.eos;
  e.set_string("type", "p_alpha");
  e.set_number("density", 2314.0);
  e.set_number("solid_density", 2750.0);
  e.set_number("crush_pressure", 23.3e6);
  e.set_number("compaction_pressure", 6.0e9);
  e.set_number("compaction_exponent", 3.0);
  e.set_number("porous_sound_speed", 2920.0);
  e.set_number("a1", 35.27e9);
  e.set_number("a2", 39.58e9);
  e.set_number("a3", 9.04e9);
  e.set_number("t1", 35.27e9);
  e.set_number("t2", 0.0);
  e.set_number("b0", 1.22);
  e.set_number("b1", 1.22);

  Parameters& s = p.strength;
  s.set_string("type", "rht");
  s.set_number("compressive_strength", 35e6);
  s.set_number("tensile_strength", 3.5e6);
  s.set_number("failure_a", 1.6);
  s.set_number("failure_n", 0.61);
  s.set_number("tensile_meridian_ratio", 0.6805);
  s.set_number("meridian_ratio_slope", 0.0105);
  s.set_number("compressive_rate_exponent", 0.032);
  s.set_number("tensile_rate_exponent", 0.036);
  s.set_number("compressive_reference_rate", 3e-5);
  s.set_number("tensile_reference_rate", 3e-6);
  s.set_number("elastic_ratio_tension", 0.7);
  s.set_number("elastic_ratio_compression", 0.53);
  s.set_number("crush_pressure", 23.3e6);
  s.set_number("compaction_pressure", 6.0e9);
  s.set_number("pre_softening_plastic_strain", 1.93e-3);
  s.set_number("residual_b", 1.6);
  s.set_number("residual_m", 0.61);
  s.set_number("damage_d1", 0.04);
  s.set_number("damage_d2", 1.0);
  s.set_number("minimum_failure_strain", 0.01);
  s.set_number("shear_modulus", 16.7e9);
  s.set_number("residual_shear_modulus", 2.17e9);
  return p;
}

CAMOUFLET_REGISTER_PRESET("concrete_35mpa_wang2005", concrete_35mpa_wang2005);

}  // namespace camouflet
