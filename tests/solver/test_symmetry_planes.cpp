// Symmetry planes that meet at an angle: a node on several planes must end on
// their intersection, whatever the order they are given in. Removing the
// normal components one after another is that projection only for orthogonal
// normals; for the edge of a conical sector (two planes at less than 90
// degrees) it left the first plane again. Here against the exact projections.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "boundary/boundary_conditions.hpp"
#include "common/fem_models.hpp"

using namespace camouflet;

namespace {

double dot(const double* a, std::array<double, 3> b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

TEST(SymmetryPlanes, ANodeOnPlanesAtAnAngleEndsOnTheirIntersection) {
  const double t = std::tan(5.0 * std::acos(-1.0) / 180.0);
  const std::array<double, 3> n1{1, 0, -t}, n2{0, 1, -t}, slanted{1, 0, 1};
  Model model;
  model.run.mode = GeometryMode::three_d;
  model.mesh.dimension = 3;
  model.mesh.coordinates = {t, t, 1, 0, 0, 1, 0, 0, 1};
  // Node 0: the edge of a square pyramid (planes x = t z and y = t z); node 1: the
  // same plane given twice; node 2: a slanted plane and the plane z = 0.
  model.mesh.node_sets["x_side"] = {0, 1, 1};
  model.mesh.node_sets["y_side"] = {0};
  model.mesh.node_sets["slanted"] = {2};
  model.mesh.node_sets["floor"] = {2};
  model.boundaries.push_back(test::symmetry("x_side", n1));
  model.boundaries.push_back(test::symmetry("y_side", n2));
  model.boundaries.push_back(test::symmetry("slanted", slanted));
  model.boundaries.push_back(test::symmetry("floor", {0, 0, 1}));
  BoundaryConditions<3> bc(model);
  double v[9] = {1, 2, 3, 1, 2, 3, 1, 2, 3};
  bc.constrain(v, 0.0);

  // Node 0: the projection of (1, 2, 3) onto the edge's direction (t, t, 1).
  const double len2 = 2 * t * t + 1, along = (1 * t + 2 * t + 3) / len2;
  EXPECT_NEAR(v[0], along * t, 1e-14);
  EXPECT_NEAR(v[1], along * t, 1e-14);
  EXPECT_NEAR(v[2], along, 1e-14);
  EXPECT_NEAR(dot(v, n1), 0.0, 1e-14);
  EXPECT_NEAR(dot(v, n2), 0.0, 1e-14);
  // Node 1: one plane, given twice: its normal component removed once.
  const double n1n1 = 1 + t * t, vn = (1 - 3 * t) / n1n1;
  EXPECT_NEAR(v[3], 1 - vn, 1e-14);
  EXPECT_NEAR(v[4], 2.0, 1e-14);
  EXPECT_NEAR(v[5], 3 + vn * t, 1e-14);
  // Node 2: z = 0 and x + z = 0 leave y alone.
  EXPECT_NEAR(v[6], 0.0, 1e-14);
  EXPECT_NEAR(v[7], 2.0, 1e-14);
  EXPECT_NEAR(v[8], 0.0, 1e-14);
}

}  // namespace
