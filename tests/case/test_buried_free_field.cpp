// The free-field variant of the buried-structure generator (`structure.kind = "free_field"`):
// the same case with the box's place and its interior filled with soil, the reference run the
// box's motion is weighed against. Checked on the mesh the case reader builds: no concrete and no
// bars are left; the mesh covers exactly what the box case covers plus the box's interior (the
// area, r-z, and the volume, 3-D, summed element by element against the box's inner
// dimensions); the members measure the soil in the members' places; a bad kind is refused
// naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case/buried_structure_params.hpp"
#include "case/case_reader.hpp"
#include "core/error.hpp"
#include "mesh/buried_structure.hpp"

namespace camouflet {
namespace {

// `domain`, `structure`: extra keys of [domain] (the geometry) and [structure].
std::string small_params(const std::string& domain = "", const std::string& structure = "") {
  return "[structure]\n" + structure + "[domain]\n" + domain + R"(radius = 12.0
depth = 6.0
[mesh]
near = 0.25
structure = 0.1
soil = 0.5
far = 1.5
[rebar]
cover = 0.03
ratio = 0.01
)";
}

Model model_of(const std::string& domain, std::string structure, const std::string& kind) {
  if (!kind.empty()) structure += "kind = \"" + kind + "\"\n";
  const BuriedStructureSpec spec = read_buried_structure_params_text(small_params(domain, structure), "ff.params.toml");
  return read_case_text(buried_structure_case(spec, "t"), "ff.toml");
}

int material_index(const Model& model, const std::string& name) {
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    if (model.materials[m].name == name) return static_cast<int>(m);
  return -1;
}

std::size_t elements_of(const Model& model, const std::string& material) {
  const int m = material_index(model, material);
  std::size_t count = 0;
  for (const int part : model.mesh.element_part)
    if (model.parts[static_cast<std::size_t>(part)].material == m) ++count;
  return count;
}

// Sum of the elements' areas (2-D, shoelace) or volumes (3-D hex8 as 6 tetrahedra... here: the
// generator's hexes are axis-aligned bricks, so the product of their edge lengths).
double mesh_measure(const Model& model) {
  const FemMesh& mesh = model.mesh;
  const int D = mesh.dimension, N = mesh.nodes_per_element;
  double total = 0.0;
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    auto x = [&](int a, int i) {
      return mesh.coordinates[static_cast<std::size_t>(mesh.connectivity[e * N + a] * D + i)];
    };
    if (D == 2) {
      double twice = 0.0;
      for (int a = 0; a < 4; ++a) twice += x(a, 0) * x((a + 1) % 4, 1) - x((a + 1) % 4, 0) * x(a, 1);
      total += 0.5 * twice;
    } else {
      double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
      for (int a = 0; a < 8; ++a)
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], x(a, i)), hi[i] = std::max(hi[i], x(a, i));
      total += (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    }
  }
  return total;
}

void expect_free_field(const std::string& domain, const std::string& structure) {
  const Model box = model_of(domain, structure, "");
  const Model free = model_of(domain, structure, "free_field");
  const BuriedStructureSpec s = read_buried_structure_params_text(small_params(domain, structure), "ff.params.toml");
  EXPECT_GT(elements_of(box, "concrete"), 0u);
  EXPECT_FALSE(box.bars.empty()) << "the box case has its reinforcement";
  EXPECT_EQ(elements_of(free, "concrete"), 0u) << "no concrete in the free field";
  EXPECT_TRUE(free.bars.empty()) << "no bars in the free field; the [rebar] block is ignored";
  // The box's interior, now soil: (L - 2t)(H - 2t) in the r-z plane; in 3-D the half-width
  // (y >= 0, symmetry plane) too.
  const double t = s.wall_thickness;
  double interior = (s.box_length - 2.0 * t) * (s.box_height - 2.0 * t);
  if (s.three_d) interior *= 0.5 * s.box_width - t;
  const double gained = mesh_measure(free) - mesh_measure(box);
  EXPECT_NEAR(gained, interior, 1e-9 * mesh_measure(free)) << "the free field fills the box's interior";
  // The members measure soil where the box's members would be.
  const int soil = material_index(free, "soil");
  int members = 0;
  for (const GaugeGroup& g : free.gauges)
    for (const GaugePoint& p : g.points)
      if (p.member) {
        ++members;
        EXPECT_EQ(p.member_material, soil) << p.name;
      }
  EXPECT_EQ(members, 4);
}

TEST(BuriedFreeField, BoxPlaceAndInteriorAreSoilAxisymmetric) { expect_free_field("", ""); }

TEST(BuriedFreeField, BoxPlaceAndInteriorAreSoil3d) {
  expect_free_field("geometry = \"3d\"\nside = 12.0\n", "width = 3.0\n");
}

// The case header's generator line (read by scripts/report.py) marks a free-field case, so that
// the report names its "structure" section for the soil it measures; a box case carries no mark.
TEST(BuriedFreeField, TheGeneratorLineMarksTheFreeField) {
  for (const std::string domain : {"", "geometry = \"3d\"\nside = 12.0\n"}) {
    const std::string structure = domain.empty() ? "" : "width = 3.0\n";
    const auto generator_line = [&](const std::string& kind) {
      const std::string text = buried_structure_case(
          read_buried_structure_params_text(small_params(domain, structure + kind), "ff.params.toml"), "t");
      const std::size_t at = text.find("# generator:");
      return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
    };
    const std::string free_field = generator_line("kind = \"free_field\"\n"), box = generator_line("");
    EXPECT_NE(free_field.find(" structure_kind=free_field"), std::string::npos) << free_field;
    EXPECT_FALSE(box.empty());
    EXPECT_EQ(box.find("structure_kind"), std::string::npos) << box;
  }
}

TEST(BuriedFreeField, AnUnknownKindIsRefusedNamingTheKey) {
  try {
    (void)read_buried_structure_params_text(small_params("", "kind = \"free\"\n"), "ff.params.toml");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("kind"), std::string::npos) << what;
    EXPECT_NE(what.find("ff.params.toml"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace camouflet
