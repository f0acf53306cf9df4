// Johnson-Cook metals of the cylinder-impact (Taylor) validation
// (docs/theory/explosive-and-steel.md §5.2), exactly as a case file would
// give them. Strength: Johnson & Cook 1983 ("A constitutive model and data
// for metals subjected to large strains, high strain rates and high
// temperatures", 7th Int. Symp. Ballistics, Tables 1-2). Bulk response: the
// Mie-Grueneisen fits and shear moduli of Steinberg 1996 (UCRL-MA-106439),
// which Johnson & Cook do not give. No damage block: failure is the case's
// choice (§5.1 lists the Johnson & Cook 1985 fracture constants of these
// metals and why a negative D1 needs care).
#include "materials/registry.hpp"

namespace camouflet {

namespace {

SourceLocation where(const std::string& preset, const std::string& key) {
  return SourceLocation{"preset " + preset, 0, 0, key};
}

struct JohnsonCookSet {
  double density, c0, s, gamma0;      // kg/m^3, m/s, -, -
  double shear_modulus;               // Pa
  double a, b, n, c, m, t_melt, c_v;  // Pa, Pa, -, -, -, K, J/(kg K)
};

MaterialPreset johnson_cook_preset(const std::string& name, const std::string& description,
                                   const JohnsonCookSet& j) {
  MaterialPreset m;
  m.description = description;
  auto eos = [&](const std::string& key, double v) { m.eos.set_number(key, v, where(name, "eos." + key)); };
  m.eos.set_string("type", "shock", where(name, "eos.type"));
  eos("density", j.density);
  eos("c0", j.c0);
  eos("s", j.s);
  eos("gamma0", j.gamma0);
  auto strength = [&](const std::string& key, double v) {
    m.strength.set_number(key, v, where(name, "strength." + key));
  };
  m.strength.set_string("type", "johnson_cook", where(name, "strength.type"));
  strength("shear_modulus", j.shear_modulus);
  strength("yield_stress", j.a);
  strength("hardening_modulus", j.b);
  strength("hardening_exponent", j.n);
  strength("rate_coefficient", j.c);
  strength("thermal_exponent", j.m);
  strength("room_temperature", 294.0);
  strength("melt_temperature", j.t_melt);
  strength("specific_heat", j.c_v);
  return m;
}

MaterialPreset copper_ofhc() {
  return johnson_cook_preset(
      "copper_ofhc_jc1983", "OFHC copper, Johnson-Cook (Johnson & Cook 1983; EOS and G: Steinberg 1996)",
      {8960.0, 3940.0, 1.49, 2.02, 47.7e9, 90e6, 292e6, 0.31, 0.025, 1.09, 1356.0, 383.0});
}

MaterialPreset steel_4340() {
  return johnson_cook_preset(
      "steel_4340_jc1983",
      "4340 steel (Rc 30), Johnson-Cook (Johnson & Cook 1983; EOS and G: Steinberg 1996)",
      {7830.0, 4578.0, 1.33, 1.67, 77.5e9, 792e6, 510e6, 0.26, 0.014, 1.03, 1793.0, 477.0});
}

}  // namespace

CAMOUFLET_REGISTER_PRESET("copper_ofhc_jc1983", copper_ofhc);
CAMOUFLET_REGISTER_PRESET("steel_4340_jc1983", steel_4340);

}  // namespace camouflet
