// Gmsh import through the Gmsh library, on tiny checked-in meshes
// (tests/case/meshes): a clockwise quad is reordered, boundary lines become
// node and face sets with outward normals, hexes keep their volume.
#include <gtest/gtest.h>

#include <filesystem>

#include "mesh/gmsh_import.hpp"
#include "model/isoparametric.hpp"

namespace camouflet {
namespace {

const std::filesystem::path meshes = std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "tests/case/meshes";

TEST(GmshImport, QuadsReorientedAndBoundarySetsOutward) {
  FemMesh mesh;
  mesh.dimension = 2;
  mesh.nodes_per_element = 4;
  import_gmsh_part(mesh, {meshes / "two_quads.msh", "plate", 0, {}, {}});
  ASSERT_EQ(mesh.node_count(), 6u);
  ASSERT_EQ(mesh.element_count(), 2u);
  // Both elements counter-clockwise (the file's second one is clockwise): area 1 each.
  for (std::int64_t e = 0; e < 2; ++e) {
    double x[8];
    gather_element(2, mesh.coordinates, mesh.connectivity, e, x);
    EXPECT_NEAR(4.0 * jacobian_determinant(2, x, Natural{0, 0, 0}), 1.0, 1e-14) << "element " << e;
  }
  ASSERT_EQ(mesh.node_sets.at("bottom").size(), 3u);
  ASSERT_EQ(mesh.node_sets.at("top").size(), 3u);
  // Every face's normal (dy, -dx) points out: down for bottom, up for top.
  for (const auto& [name, sign] : {std::pair<std::string, double>{"bottom", -1.0}, {"top", 1.0}}) {
    const auto& faces = mesh.face_sets.at(name);
    ASSERT_EQ(faces.size(), 4u) << name;
    for (std::size_t f = 0; f < faces.size(); f += 2) {
      const double dx = mesh.coordinates[2 * faces[f + 1]] - mesh.coordinates[2 * faces[f]];
      EXPECT_DOUBLE_EQ(-dx * sign, 1.0) << name << " face " << f / 2;  // normal_y = -dx
    }
  }
  EXPECT_EQ(mesh.element_part, (std::vector<int>{0, 0}));
}

TEST(GmshImport, HexVolumeAndFaceSet) {
  FemMesh mesh;
  mesh.dimension = 3;
  mesh.nodes_per_element = 8;
  import_gmsh_part(mesh, {meshes / "one_hex.msh", "cube", 2, {}, {}});
  ASSERT_EQ(mesh.element_count(), 1u);
  double x[24];
  gather_element(3, mesh.coordinates, mesh.connectivity, 0, x);
  EXPECT_NEAR(8.0 * jacobian_determinant(3, x, Natural{0, 0, 0}), 6.0, 1e-13);  // 2 x 1 x 3 m
  const auto& base = mesh.face_sets.at("base");
  ASSERT_EQ(base.size(), 4u);
  // The file's base quad has its normal along +z (into the hex); it must come out along -z.
  auto at = [&](std::int64_t n, int i) { return mesh.coordinates[static_cast<std::size_t>(3 * n + i)]; };
  const double d1x = at(base[2], 0) - at(base[0], 0), d1y = at(base[2], 1) - at(base[0], 1);
  const double d2x = at(base[3], 0) - at(base[1], 0), d2y = at(base[3], 1) - at(base[1], 1);
  EXPECT_LT(d1x * d2y - d1y * d2x, 0.0);
  EXPECT_EQ(mesh.element_part[0], 2);
}

TEST(GmshImport, ErrorsNameTheKey) {
  FemMesh mesh;
  mesh.dimension = 2;
  mesh.nodes_per_element = 4;
  SourceLocation physical{"c.toml", 7, 1, "parts[0].physical"};
  try {
    import_gmsh_part(mesh, {meshes / "two_quads.msh", "plat", 0, {}, physical});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "parts[0].physical");
    EXPECT_NE(std::string(e.what()).find("did you mean 'plate'"), std::string::npos) << e.what();
  }
  // A 3-D request of a 2-D group names the group as missing in 3-D.
  mesh.dimension = 3;
  mesh.nodes_per_element = 8;
  EXPECT_THROW(import_gmsh_part(mesh, {meshes / "two_quads.msh", "plate", 0, {}, physical}), InputError);
  EXPECT_EQ(mesh.node_count(), 0u);  // a failed import leaves the mesh untouched
}

}  // namespace
}  // namespace camouflet
