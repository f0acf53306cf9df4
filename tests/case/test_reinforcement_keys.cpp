// Case keys of reinforced concrete: `rebar_layers` on a block
// part, [[bars]], a material's `erosion`; bad values name their key.
#include <gtest/gtest.h>

#include <filesystem>

#include "case/case_reader.hpp"

namespace camouflet {
namespace {

const std::filesystem::path here = std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "tests/case/case.toml";

std::string rc_case(const std::string& layer_cover = "0.03",
                    const std::string& erosion = "geometric_strain = 1.5, damage = 0.99",
                    const std::string& bar_extra = "") {
  return R"([run]
end_time = 1e-3
[materials.concrete]
eos = { type = "linear", density = 2400, bulk_modulus = 2e10 }
strength = { type = "elastic", shear_modulus = 1.2e10 }
erosion = { )" +
         erosion + R"( }
[materials.steel]
preset = "steel_1006_wang2005"
[[parts]]
name = "wall"
material = "concrete"
block = { size = [1.0, 0.2], cells = [10, 4] }
rebar_layers = [
  { cover = )" +
         layer_cover + R"(, steel_area_per_length = 1e-3, face = "ymin", material = "steel" },
  { cover = 0.03, steel_area_per_length = 1e-3, face = "ymax", material = "steel" },
]
[[parts]]
name = "host"
material = "concrete"
block = { origin = [0, 0.3], size = [1.0, 0.2], cells = [10, 4] }
[[bars]]
name = "b1"
from = [0.0, 0.35]
to = [1.0, 0.35]
segments = 10
area = 5e-4
material = "steel"
host = "host"
)" + bar_extra;
}

void expect_error(const std::string& text, const std::string& key) {
  try {
    read_case_text(text, here);
    ADD_FAILURE() << "accepted, expected an error on " << key;
  } catch (const InputError& e) {
    EXPECT_NE(e.where().key.find(key), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(ReinforcementKeys, LayersBarsAndErosionLand) {
  const Model m = read_case_text(rc_case(), here);
  ASSERT_EQ(m.parts.size(), 4u);  // wall, wall.rebar0, wall.rebar1, host
  EXPECT_EQ(m.parts[1].name, "wall.rebar0");
  EXPECT_EQ(m.materials[static_cast<std::size_t>(m.parts[1].material)].name, "steel");
  EXPECT_EQ(m.erosion_of(0).geometric_strain, 1.5);
  EXPECT_EQ(m.erosion_of(0).damage, 0.99);
  EXPECT_FALSE(m.erosion_of(1).enabled());
  ASSERT_EQ(m.bars.size(), 1u);
  EXPECT_EQ(m.bars[0].segments, 10);
  EXPECT_EQ(m.bars[0].area, 5e-4);
  EXPECT_EQ(m.bars[0].host_part, 3);
  EXPECT_TRUE(m.mesh.node_sets.count("wall.ymax"));
}

TEST(ReinforcementKeys, BadValuesNameTheirKey) {
  expect_error(rc_case("-0.01"), "rebar_layers[0].cover");
  expect_error(rc_case("0.25"), "rebar_layers[0].cover");
  expect_error(rc_case("0.03", "damage = 1.5"), "erosion.damage");
  expect_error(rc_case("0.03", ""), "erosion");
  expect_error(rc_case("0.03", "geometric_strain = 1.5", "orientation = \"hoop\"\n"), "orientation");
  std::string zero_area = rc_case();
  zero_area.replace(zero_area.find("area = 5e-4"), 11, "area = 0.0");
  expect_error(zero_area, "area");
}

}  // namespace camouflet
