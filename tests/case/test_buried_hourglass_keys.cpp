// Hourglass keys of the buried-structure generator: `soil.hourglass`
// and `structure.hourglass` ({ form, coefficient }). Their defaults write the
// case as before (stiffness, 0.1 for all: the committed cases stay valid); a
// box form other than the soil's goes on every concrete part; bad values are
// refused naming the key. The soil's erosion key (`soil.erosion`) is checked here too: it is the
// other per-soil numerics key of the generator.
#include <gtest/gtest.h>

#include <string>

#include "buried_structure_checks.hpp"
#include "case/buried_structure_params.hpp"
#include "case/case_reader.hpp"
#include "mesh/buried_structure.hpp"

namespace camouflet {
namespace {

// A small case: its mesh is read, not run.
const std::string small_params = R"(
[domain]
radius = 12.0
depth = 6.0
[mesh]
near = 0.2
structure = 0.05
soil = 0.5
far = 1.5
)";

BuriedStructureSpec spec_of(const std::string& extra) {
  return read_buried_structure_params_text(small_params + extra, "hg.params.toml");
}

// The hourglass control of the parts whose name starts with `prefix`; all must agree.
HourglassControl control_of(const Model& model, const std::string& prefix) {
  std::optional<HourglassControl> found;
  int count = 0;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    if (model.parts[p].name.rfind(prefix, 0) != 0) continue;
    const HourglassControl h = model.hourglass_of(p);
    if (found) {
      EXPECT_EQ(h.form, found->form) << model.parts[p].name;
      EXPECT_EQ(h.coefficient, found->coefficient) << model.parts[p].name;
    }
    found = h;
    ++count;
  }
  EXPECT_GT(count, 0) << prefix;
  return found.value_or(HourglassControl{});
}

TEST(BuriedHourglassKeys, DefaultsWriteTheCaseAsBefore) {
  const std::string plain = buried_structure_case(spec_of(""), "t");
  const std::string explicit_defaults =
      buried_structure_case(spec_of("[soil]\nhourglass = { form = \"stiffness\", coefficient = 0.1 }\n"
                                    "[structure]\nhourglass = { form = \"stiffness\" }\n"),
                            "t");
  EXPECT_EQ(plain, explicit_defaults);
  EXPECT_EQ(plain.find("hourglass = {"), std::string::npos) << "no part carries its own control";
  const Model model = read_case_text(plain, "plain.toml");
  EXPECT_EQ(model.run.hourglass, HourglassForm::stiffness);
  EXPECT_EQ(model.run.hourglass_coefficient, 0.1);
  for (const Part& p : model.parts) EXPECT_FALSE(p.hourglass.has_value()) << p.name;
}

// r-z with an SPH zone (docs/buried-structure.md, "The axis without soil erosion"): the area form,
// the soil's subzonal pressures and edge viscosity as the run's, every concrete part its own point
// q without subzonal pressures, and the particles' smoothed hoop terms with their band. Without the
// zone (the test above) none of it.
TEST(BuriedHourglassKeys, SphZoneCaseCarriesTheAxisTreatmentOnTheSoilOnly) {
  const Model model = read_case_text(buried_structure_case(spec_of("[sph]\nradius = 1.0\n"), "t"), "zone.toml");
  EXPECT_TRUE(model.run.area_weighted_momentum);
  EXPECT_TRUE(model.sph.smoothed_hoop);
  EXPECT_EQ(model.sph.smoothed_hoop_width, 0.5);
  EXPECT_TRUE(model.sph.viscosity_hoop);
  int soil = 0, concrete = 0;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    if (model.parts[p].kind != PartKind::fem) continue;
    const std::string& name = model.parts[p].name;
    if (name.rfind("concrete", 0) == 0) {
      ++concrete;
      EXPECT_EQ(model.subzonal_of(p), 0.0) << name;
      EXPECT_EQ(model.viscosity_form_of(p), ViscosityForm::acceleration) << name;
      EXPECT_EQ(model.hourglass_of(p).coefficient, 0.1) << name;  // the structure's as before
    } else if (name.rfind("soil", 0) == 0) {
      ++soil;
      EXPECT_EQ(model.subzonal_of(p), 1.0) << name;
      EXPECT_EQ(model.viscosity_form_of(p), ViscosityForm::edge) << name;
    }
  }
  EXPECT_GT(soil, 10);
  EXPECT_GT(concrete, 3);
  const Model plain = read_case_text(buried_structure_case(spec_of(""), "t"), "plain.toml");
  EXPECT_FALSE(plain.run.area_weighted_momentum);
  EXPECT_EQ(plain.run.subzonal_pressure, 0.0);
  EXPECT_EQ(plain.run.viscosity_form, ViscosityForm::acceleration);
}

TEST(BuriedHourglassKeys, ViscousStructureGoesOnEveryConcretePart) {
  const Model model = read_case_text(
      buried_structure_case(spec_of("[structure]\nhourglass = { form = \"viscous\", coefficient = 0.05 }\n"),
                            "t"),
      "viscous_box.toml");
  EXPECT_EQ(model.run.hourglass, HourglassForm::stiffness);
  const HourglassControl box = control_of(model, "concrete");
  EXPECT_EQ(box.form, HourglassForm::viscous);
  EXPECT_EQ(box.coefficient, 0.05);
  const HourglassControl soil = control_of(model, "soil");
  EXPECT_EQ(soil.form, HourglassForm::stiffness);
  EXPECT_EQ(soil.coefficient, 0.1);
}

TEST(BuriedHourglassKeys, SoilFormIsTheRunsAndRunCoefficientIsTheDefault) {
  const BuriedStructureSpec s =
      spec_of("[run]\nhourglass_coefficient = 0.2\n[soil]\nhourglass = { form = \"viscous\" }\n");
  const Model model = read_case_text(buried_structure_case(s, "t"), "viscous_soil.toml");
  EXPECT_EQ(model.run.hourglass, HourglassForm::viscous);
  EXPECT_EQ(model.run.hourglass_coefficient, 0.2);
  const HourglassControl box = control_of(model, "concrete");
  EXPECT_EQ(box.form, HourglassForm::stiffness);
  EXPECT_EQ(box.coefficient, 0.2);
}

TEST(BuriedHourglassKeys, ThreeDimensionalCaseCarriesTheBoxForm) {
  BuriedStructureSpec s = spec_of("[structure]\nhourglass = { form = \"viscous\" }\n");
  s.three_d = true;
  s.box_width = 2.0;
  s.size_structure = 0.1;
  const std::string text = buried_structure_case(s, "t");
  EXPECT_NE(text.find("hourglass = { form = \"viscous\", coefficient = 0.1 }"), std::string::npos);
}

int material_index(const Model& model, const std::string& name) {
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    if (model.materials[m].name == name) return static_cast<int>(m);
  ADD_FAILURE() << "no material " << name;
  return -1;
}

TEST(BuriedHourglassKeys, SoilErosionGoesOnTheSoilMaterialOnly) {
  const Model plain = read_case_text(buried_structure_case(spec_of(""), "t"), "plain.toml");
  for (std::size_t m = 0; m < plain.materials.size(); ++m)
    EXPECT_FALSE(plain.erosion_of(m).enabled()) << plain.materials[m].name;
  const Model eroding = read_case_text(
      buried_structure_case(spec_of("[soil]\nerosion = { geometric_strain = 1.5 }\n"), "t"), "eroding.toml");
  for (std::size_t m = 0; m < eroding.materials.size(); ++m) {
    const ErosionCriteria e = eroding.erosion_of(m);
    if (eroding.materials[m].name == "soil") {
      EXPECT_EQ(e.geometric_strain, 1.5);
      EXPECT_EQ(e.damage, 0.0);
    } else {
      EXPECT_FALSE(e.enabled()) << eroding.materials[m].name;
    }
  }
  EXPECT_GE(material_index(eroding, "soil"), 0);
}

void expect_params_refused(const std::string& extra, const std::string& key, const std::string& fragment) {
  try {
    layout_buried_structure(spec_of(extra));
    ADD_FAILURE() << "accepted; expected an error naming " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, key) << e.what();
    EXPECT_NE(e.message().find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(e.where().file, "hg.params.toml") << e.what();
    EXPECT_GT(e.where().line, 0) << e.what();
  }
}

TEST(BuriedHourglassKeys, BadValuesAreRefusedNamingTheKey) {
  expect_params_refused("[structure]\nhourglass = { form = \"stifness\" }\n", "structure.hourglass.form",
                        "did you mean 'stiffness'");
  expect_params_refused("[soil]\nhourglass = { form = \"none\" }\n", "soil.hourglass.form", "not one of");
  expect_params_refused("[soil]\nhourglass = { coefficient = 0.7 }\n", "soil.hourglass.coefficient",
                        "must lie in (0, 0.5]");
  expect_params_refused("[structure]\nhourglass = { form = \"viscous\", coefficient = 0.0 }\n",
                        "structure.hourglass.coefficient", "must lie in (0, 0.5]");
  expect_params_refused("[structure]\nhourglass = { coefficient = \"0.1\" }\n",
                        "structure.hourglass.coefficient", "expected a number");
  expect_params_refused("[structure]\nhourglass = \"viscous\"\n", "structure.hourglass", "expected a table");
  expect_params_refused("[soil]\nhourglass = { form = \"viscous\", coef = 0.1 }\n", "soil.hourglass.coef",
                        "");
  expect_params_refused("[soil]\nerosion = { geometric_strain = 0.0 }\n", "soil.erosion.geometric_strain",
                        "");
  expect_params_refused("[soil]\nerosion = { strain = 1.5 }\n", "soil.erosion.geometric_strain", "");
}

}  // namespace
}  // namespace camouflet
