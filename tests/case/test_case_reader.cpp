// The case reader on valid input: every section lands in the Model with the
// values and locations given; defaults apply where keys are absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "case/case_reader.hpp"

namespace camouflet {
namespace {

const std::filesystem::path here = std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "tests/case/case.toml";

const char* full_case = R"(title = "reader test"
[run]
geometry = "axisymmetric"
end_time = 2e-3
cfl = 0.5
min_dt = 1e-12
max_dt = 1e-4
max_cycles = 5000
energy_error_limit = 0.05
viscosity = { linear = 0.1, quadratic = 2.0 }
hourglass = { form = "stiffness", coefficient = 0.05 }

[output]
field_interval = 1e-4
gauge_interval = 1e-6
log_interval = 2.0

[materials.rock]
eos = { type = "linear", density = 2650, bulk_modulus = 5e10 }
strength = { type = "von_mises", shear_modulus = 3e10, yield_stress = 1e8 }

[[parts]]
name = "ground"
material = "rock"
initial_velocity = [0.0, -1.0]
block = { origin = [0.0, -2.0], size = [2.0, 2.0], cells = [4, 4], grading = [2.0, 1.0] }

[[parts]]
name = "slab"
material = "charge"
gmsh = "meshes/two_quads.msh"
physical = "plate"

[[boundary]]
type = "axis"
set = "ground.xmin"

[[boundary]]
type = "pressure"
set = "ground.ymax"
value = 1e6
history = [[0, 0], [1e-3, 1], [2e-3, 0]]

[[boundary]]
type = "velocity"
set = "bottom"
components = ["y"]
value = [0.5]

[[gauges]]
name = "surface"
points = [{ name = "near", position = [0.1, -0.1] }, { name = "far", position = [1.9, -1.9] }]

[[gauges]]
name = "depth"
from = [0.5, -0.1]
to = [0.5, -1.9]
count = 4

[[detonation]]
position = [0.5, 0.5]
time = 1e-5

[materials.charge]
preset = "tnt_wang2005"
)";

TEST(CaseReader, EverySectionLands) {
  const Model m = read_case_text(full_case, here);
  EXPECT_EQ(m.title, "reader test");
  EXPECT_EQ(m.run.mode, GeometryMode::axisymmetric);
  EXPECT_EQ(m.run.end_time, 2e-3);
  EXPECT_EQ(m.run.cfl, 0.5);
  EXPECT_EQ(m.run.min_dt, 1e-12);
  EXPECT_EQ(m.run.max_dt, 1e-4);
  EXPECT_EQ(m.run.max_cycles, 5000);
  EXPECT_EQ(m.run.energy_error_limit, 0.05);
  EXPECT_EQ(m.run.viscosity_linear, 0.1);
  EXPECT_EQ(m.run.viscosity_quadratic, 2.0);
  EXPECT_EQ(m.run.hourglass, HourglassForm::stiffness);
  EXPECT_EQ(m.run.hourglass_coefficient, 0.05);
  EXPECT_EQ(m.output.field_interval, 1e-4);
  EXPECT_EQ(m.output.gauge_interval, 1e-6);
  EXPECT_EQ(m.output.log_interval_s, 2.0);

  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].material->reference_density(), 2650.0);
  EXPECT_EQ(m.materials[0].material->strength()->type(), "von_mises");

  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[0].initial_velocity[1], -1.0);
  EXPECT_EQ(m.parts[1].name, "slab");
  EXPECT_EQ(m.parts[0].where.line, 22);
  EXPECT_EQ(m.mesh.element_count(), 16u + 2u);
  EXPECT_EQ(m.mesh.element_part.back(), 1);
  // Grading 2 along x: the last cell twice the first; 4 cells over 2 m.
  EXPECT_TRUE(m.mesh.node_sets.count("ground.xmin"));
  EXPECT_TRUE(m.mesh.face_sets.count("bottom"));

  ASSERT_EQ(m.boundaries.size(), 3u);
  EXPECT_EQ(m.boundaries[0].kind, BoundaryKind::axis);
  EXPECT_EQ(m.boundaries[1].kind, BoundaryKind::pressure);
  EXPECT_EQ(m.boundaries[1].value[0], 1e6);
  ASSERT_TRUE(m.boundaries[1].history);
  EXPECT_DOUBLE_EQ(m.boundaries[1].history->at(5e-4), 0.5);
  EXPECT_TRUE(m.boundaries[2].components[1]);
  EXPECT_FALSE(m.boundaries[2].components[0]);
  EXPECT_EQ(m.boundaries[2].value[1], 0.5);

  ASSERT_EQ(m.gauges.size(), 2u);
  EXPECT_EQ(m.gauges[0].points[1].name, "far");
  EXPECT_EQ(m.gauges[0].points[1].where.key, "gauges[0].points[1].position");
  ASSERT_EQ(m.gauges[1].points.size(), 4u);
  EXPECT_EQ(m.gauges[1].points[3].name, "p4");
  EXPECT_DOUBLE_EQ(m.gauges[1].points[3].position[1], -1.9);
  EXPECT_DOUBLE_EQ(m.gauges[1].points[1].position[1], -0.7);

  ASSERT_EQ(m.detonations.size(), 1u);
  EXPECT_EQ(m.detonations[0].time, 1e-5);
  EXPECT_EQ(m.detonation_where[0].line, 60);
}

TEST(CaseReader, DefaultsWhereKeysAreAbsent) {
  const Model m = read_case_text(R"([run]
end_time = 1.0
[materials.m]
eos = { type = "linear", density = 1000, bulk_modulus = 2e9 }
[[parts]]
name = "p"
material = "m"
block = { size = [1, 1], cells = [2, 3] }
)",
                                 here);
  const RunControl defaults;
  EXPECT_EQ(m.run.mode, GeometryMode::plane_strain);
  EXPECT_EQ(m.run.cfl, defaults.cfl);
  EXPECT_EQ(m.run.hourglass, defaults.hourglass);
  EXPECT_EQ(m.output.gauge_interval, 0.0);
  EXPECT_EQ(m.mesh.element_count(), 6u);
}

TEST(CaseReader, MisspeltKeyInsteadOfMissingRequired) {
  try {
    read_case_text("[run]\nend_tmie = 1.0\n", here);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().key, "run.end_tmie");
    EXPECT_NE(e.message().find("did you mean 'end_time'"), std::string::npos) << e.what();
  }
}

TEST(CaseReader, ThreeDimensionalBlockAndDescribe) {
  const Model m = read_case_text(R"([run]
geometry = "3d"
end_time = 1.0
[materials.m]
eos = { type = "linear", density = 1000, bulk_modulus = 2e9 }
[[parts]]
name = "p"
material = "m"
block = { size = [1, 1, 1], cells = [1, 2, 3] }
[[gauges]]
name = "g"
points = [{ name = "c", position = [0.5, 0.5, 0.5] }]
)",
                                 here);
  EXPECT_EQ(m.mesh.dimension, 3);
  EXPECT_EQ(m.mesh.element_count(), 6u);
  const std::string d = describe_model(m);
  EXPECT_NE(d.find("geometry 3d"), std::string::npos) << d;
  EXPECT_NE(d.find("6 elements"), std::string::npos) << d;
}

}  // namespace
}  // namespace camouflet

#include "materials/registry.hpp"

namespace camouflet {
namespace {

// A preset for this test only: its blocks lie under the case's, so keys the
// case gives win and the rest come from the preset.
MaterialPreset test_preset() {
  MaterialPreset p;
  p.description = "test only";
  p.eos.set_string("type", "linear");
  p.eos.set_number("density", 2500.0);
  p.eos.set_number("bulk_modulus", 1e10);
  p.strength.set_string("type", "elastic");
  p.strength.set_number("shear_modulus", 5e9);
  return p;
}
CAMOUFLET_REGISTER_PRESET("test_case_reader_rock", test_preset);

TEST(CaseReader, PresetWithOverride) {
  const Model m = read_case_text(R"([run]
end_time = 1.0
[materials.rock]
preset = "test_case_reader_rock"
eos = { density = 2600.0 }
[materials.plain]
preset = "test_case_reader_rock"
[[parts]]
name = "p"
material = "rock"
block = { size = [1, 1], cells = [1, 1] }
)",
                                 here);
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].name, "rock");  // in the order of the file
  EXPECT_EQ(m.materials[0].material->reference_density(), 2600.0);
  EXPECT_EQ(m.materials[1].material->reference_density(), 2500.0);
  ASSERT_NE(m.materials[0].material->strength(), nullptr);
  EXPECT_EQ(m.materials[0].material->strength()->type(), "elastic");
}

}  // namespace
}  // namespace camouflet
