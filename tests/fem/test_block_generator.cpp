// Structured/graded block mesher: counts, graded spacing, shared nodes, sets.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "mesh/block_generator.hpp"

using namespace camouflet;

namespace {

double coord(const FemMesh& m, std::int64_t n, int k) {
  return m.coordinates[static_cast<std::size_t>(n * m.dimension + k)];
}

// Signed area of a 2-D polygon given by node ids (counter-clockwise positive).
double signed_area(const FemMesh& m, const std::int64_t* n, int count) {
  double a = 0.0;
  for (int i = 0; i < count; ++i) {
    const auto p = n[i], q = n[(i + 1) % count];
    a += coord(m, p, 0) * coord(m, q, 1) - coord(m, q, 0) * coord(m, p, 1);
  }
  return 0.5 * a;
}

}  // namespace

TEST(BlockGenerator, GradedCoordinatesSumToSizeWithRequestedRatio) {
  const auto x = graded_coordinates(1.0, 3.0, 6, 4.0);
  ASSERT_EQ(x.size(), 7u);
  EXPECT_DOUBLE_EQ(x.front(), 1.0);
  EXPECT_DOUBLE_EQ(x.back(), 4.0);
  const double first = x[1] - x[0], last = x[6] - x[5];
  EXPECT_NEAR(last / first, 4.0, 1e-12);
  for (int i = 1; i < 5; ++i)
    EXPECT_NEAR((x[i + 1] - x[i]) / (x[i] - x[i - 1]), std::pow(4.0, 1.0 / 5.0), 1e-12);
}

TEST(BlockGenerator, QuadBlockCountsOrientationAndSets) {
  FemMesh mesh;
  mesh.dimension = 2;
  add_block(mesh, {"soil", 0, {0.0, -2.0, 0.0}, {4.0, 2.0, 0.0}, {4, 3, 1}, {2.0, 1.0, 1.0}});
  EXPECT_EQ(mesh.nodes_per_element, 4);
  EXPECT_EQ(mesh.node_count(), 5u * 4u);
  EXPECT_EQ(mesh.element_count(), 12u);
  double area = 0.0;
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    const double a = signed_area(mesh, &mesh.connectivity[e * 4], 4);
    EXPECT_GT(a, 0.0) << "element " << e + 1 << " is not counter-clockwise";
    area += a;
  }
  EXPECT_NEAR(area, 8.0, 1e-12);
  EXPECT_EQ(mesh.node_sets.at("soil.xmin").size(), 4u);
  EXPECT_EQ(mesh.node_sets.at("soil.ymax").size(), 5u);
  EXPECT_EQ(mesh.face_sets.at("soil.ymin").size(), 8u);
  for (auto n : mesh.node_sets.at("soil.xmax")) EXPECT_DOUBLE_EQ(coord(mesh, n, 0), 4.0);
  // Outward normal of a face (a -> b) in 2-D is (dy, -dx).
  const std::map<std::string, std::array<double, 2>> outward = {
      {"soil.xmin", {-1, 0}}, {"soil.xmax", {1, 0}}, {"soil.ymin", {0, -1}}, {"soil.ymax", {0, 1}}};
  for (const auto& [set, normal] : outward) {
    const auto& f = mesh.face_sets.at(set);
    for (std::size_t i = 0; i < f.size(); i += 2) {
      const double dx = coord(mesh, f[i + 1], 0) - coord(mesh, f[i], 0);
      const double dy = coord(mesh, f[i + 1], 1) - coord(mesh, f[i], 1);
      EXPECT_GT(dy * normal[0] - dx * normal[1], 0.0) << set;
    }
  }
}

TEST(BlockGenerator, AdjacentBlocksShareTheirInterfaceNodes) {
  FemMesh mesh;
  mesh.dimension = 2;
  add_block(mesh, {"a", 0, {0, 0, 0}, {1, 1, 0}, {2, 3, 1}, {1, 1, 1}});
  add_block(mesh, {"b", 1, {1, 0, 0}, {2, 1, 0}, {3, 3, 1}, {1, 1, 1}});
  EXPECT_EQ(mesh.node_count(), 3u * 4u + 3u * 4u);  // the 4 interface nodes are shared
  EXPECT_EQ(mesh.element_count(), 6u + 9u);
  auto a = mesh.node_sets.at("a.xmax"), b = mesh.node_sets.at("b.xmin");
  EXPECT_EQ(std::set<std::int64_t>(a.begin(), a.end()), std::set<std::int64_t>(b.begin(), b.end()));
  EXPECT_EQ(mesh.element_part.back(), 1);
}

TEST(BlockGenerator, HexBlockVolumesNormalsAndSharing) {
  FemMesh mesh;
  mesh.dimension = 3;
  add_block(mesh, {"a", 0, {0, 0, 0}, {1, 2, 3}, {2, 3, 4}, {1, 1.5, 0.5}});
  add_block(mesh, {"b", 0, {0, 0, 3}, {1, 2, 1}, {2, 3, 1}, {1, 1.5, 1}});
  EXPECT_EQ(mesh.nodes_per_element, 8);
  EXPECT_EQ(mesh.node_count(), 3u * 4u * 5u + 3u * 4u);
  EXPECT_EQ(mesh.element_count(), 24u + 6u);
  // Bottom face counter-clockwise seen from above: (n1 - n0) x (n3 - n0) points +z; top is above.
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    const auto* n = &mesh.connectivity[e * 8];
    const double ax = coord(mesh, n[1], 0) - coord(mesh, n[0], 0),
                 ay = coord(mesh, n[1], 1) - coord(mesh, n[0], 1);
    const double bx = coord(mesh, n[3], 0) - coord(mesh, n[0], 0),
                 by = coord(mesh, n[3], 1) - coord(mesh, n[0], 1);
    EXPECT_GT(ax * by - ay * bx, 0.0);
    EXPECT_GT(coord(mesh, n[4], 2), coord(mesh, n[0], 2));
  }
  const std::map<std::string, std::array<double, 3>> outward = {
      {"a.xmin", {-1, 0, 0}}, {"a.xmax", {1, 0, 0}},  {"a.ymin", {0, -1, 0}},
      {"a.ymax", {0, 1, 0}},  {"a.zmin", {0, 0, -1}}, {"a.zmax", {0, 0, 1}}};
  for (const auto& [set, normal] : outward) {
    const auto& f = mesh.face_sets.at(set);
    ASSERT_EQ(f.size() % 4, 0u);
    for (std::size_t i = 0; i < f.size(); i += 4) {
      double u[3], v[3];
      for (int k = 0; k < 3; ++k) {
        u[k] = coord(mesh, f[i + 2], k) - coord(mesh, f[i], k);
        v[k] = coord(mesh, f[i + 3], k) - coord(mesh, f[i + 1], k);
      }
      const double nrm[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      EXPECT_GT(nrm[0] * normal[0] + nrm[1] * normal[1] + nrm[2] * normal[2], 0.0) << set;
    }
  }
  EXPECT_EQ(mesh.node_sets.at("a.zmax").size(), 12u);
  auto a = mesh.node_sets.at("a.zmax"), b = mesh.node_sets.at("b.zmin");
  EXPECT_EQ(std::set<std::int64_t>(a.begin(), a.end()), std::set<std::int64_t>(b.begin(), b.end()));
  // Graded z spacing of block a: last/first = 0.5.
  const auto z = graded_coordinates(0.0, 3.0, 4, 0.5);
  EXPECT_NEAR((z[4] - z[3]) / (z[1] - z[0]), 0.5, 1e-12);
}
