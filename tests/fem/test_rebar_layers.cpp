// The steel-layer generator (Wang et al. 2005, section 5.1): the
// layers share nodes with the concrete, the steel volume equals the rebar
// volume (area per unit width x span x depth), and bad input names its key.
#include <gtest/gtest.h>

#include "common/verification.hpp"
#include "fem/fem_elements.hpp"
#include "mesh/rebar_layers.hpp"

using namespace camouflet;

namespace {

RebarWallSpec wall_2d() {
  RebarWallSpec w;
  w.name = "wall";
  w.concrete_part = 0;
  w.origin = {0.5, -0.1, 0.0};
  w.size = {2.0, 0.2, 0.0};
  w.cells = {16, 6, 1};
  w.layers = {{0.03, 1.13e-3, RebarFace::ymin, 1}, {0.04, 0.79e-3, RebarFace::ymax, 2}};
  return w;
}

template <int D>
std::vector<double> volume_per_part(const FemMesh& mesh, int parts) {
  const FemElements<D> elements(mesh, D == 3 ? GeometryMode::three_d : GeometryMode::plane_strain,
                                mesh.coordinates);
  std::vector<double> v(static_cast<std::size_t>(parts), 0.0);
  for (std::size_t e = 0; e < elements.volume.size(); ++e)
    v[static_cast<std::size_t>(mesh.element_part[e])] += elements.volume[e];
  return v;
}

}  // namespace

TEST(RebarLayers, SteelVolumeEqualsRebarVolumeAndNodesAreShared2d) {
  FemMesh mesh;
  mesh.dimension = 2;
  const RebarWallSpec w = wall_2d();
  add_rebar_wall(mesh, w);
  // Stack: cover 0.03 | steel | core | steel | cover 0.04: 5 layers, the
  // concrete ones sharing the 6 cells by thickness (1, 4, 1).
  const auto stack = rebar_stack(w);
  ASSERT_EQ(stack.size(), 5u);
  int y_cells = 0;
  for (const auto& l : stack) y_cells += l.cells;
  EXPECT_EQ(mesh.node_count(), static_cast<std::size_t>(17 * (y_cells + 1))) << "layers share their nodes";
  const auto v = volume_per_part<2>(mesh, 3);
  test::verify({"Rebar layers (2-D): steel volume of the ymin layer", "steel_area_per_length x span",
                1.13e-3 * 2.0, v[1], 1e-12, true, "m^3/m"});
  test::verify({"Rebar layers (2-D): steel volume of the ymax layer", "steel_area_per_length x span",
                0.79e-3 * 2.0, v[2], 1e-12, true, "m^3/m"});
  EXPECT_NEAR(v[0] + v[1] + v[2], 2.0 * 0.2, 1e-12);
  // The ymax layer sits at cover 0.04 below the top face.
  EXPECT_NEAR(stack[3].y0 + stack[3].thickness, 0.1 - 0.04, 1e-15);
  EXPECT_EQ(mesh.node_sets.at("wall.xmin").size(), static_cast<std::size_t>(y_cells + 1));
  EXPECT_EQ(mesh.face_sets.at("wall.ymax").size(), 2u * 16u);
}

TEST(RebarLayers, SteelVolume3d) {
  FemMesh mesh;
  mesh.dimension = 3;
  mesh.nodes_per_element = 8;
  RebarWallSpec w = wall_2d();
  w.size[2] = 0.5;
  w.cells[2] = 2;
  add_rebar_wall(mesh, w);
  const auto v = volume_per_part<3>(mesh, 3);
  test::verify({"Rebar layers (3-D): steel volume of the ymin layer", "steel_area_per_length x span x depth",
                1.13e-3 * 2.0 * 0.5, v[1], 1e-12, true, "m^3"});
}

TEST(RebarLayers, BadInputNamesTheKey) {
  auto expect_key = [](RebarWallSpec w, const std::string& key) {
    FemMesh mesh;
    mesh.dimension = 2;
    try {
      add_rebar_wall(mesh, w);
      ADD_FAILURE() << "accepted bad input, expected an error on " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().key, key) << e.what();
    }
  };
  RebarWallSpec w = wall_2d();
  w.layers[0].cover = -0.01;
  expect_key(w, "rebar_layers[0].cover");
  w = wall_2d();
  w.layers[1].steel_area_per_length = 0.0;
  expect_key(w, "rebar_layers[1].steel_area_per_length");
  w = wall_2d();
  w.layers[0].cover = 0.2;  // cover + layer thicker than the wall
  expect_key(w, "rebar_layers[0].cover");
  w = wall_2d();
  w.layers[1].cover = 0.2 - 0.03 - 1.13e-3 - 0.5e-3;  // overlaps the ymin layer
  expect_key(w, "rebar_layers[1].cover");
  w = wall_2d();
  w.layers.clear();
  expect_key(w, "rebar_layers");
}
