// A quad whose edges cross (a "bow-tie") while its area stays positive must not
// pass silently: the solver names it (stderr) and records it (in the buried-structure cases such an
// element, its top nodes driven below its bottom ones on one side, set the time step for milliseconds with a
// meaningless density; the one-point area check missed it).
#include <gtest/gtest.h>

#include <string>

#include "common/fem_models.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

TEST(SolverDiagnostics, TangledQuadWithPositiveAreaIsReported) {
  test::use_threads(1);
  // One 1 m square, nodes (0,0) (1,0) (0,1) (1,1); the top-right node is driven down at 500 m/s, the
  // others held.
  // Once it is below y = 0 the edge from it to (0,1) crosses the bottom edge: corners 2 and 3 of
  // the element turn inside out while its area, (1 + y) / 2, is still positive down to y = -1.
  Model model = test::block_model(GeometryMode::plane_strain, {{"block", 0, {0, 0, 0}, {1, 1, 0}, {1, 1, 1}}},
                                  test::ElasticConstants{});
  model.mesh.node_sets["corner"] = {3};
  model.mesh.node_sets["others"] = {0, 1, 2};  // held: the element cannot follow its corner
  model.boundaries.push_back(test::velocity("others", 0, 0.0));
  model.boundaries.push_back(test::velocity("others", 1, 0.0));
  model.boundaries.push_back(test::velocity("corner", 0, 0.0));
  model.boundaries.push_back(test::velocity("corner", 1, -500.0));
  Solver<2> solver(model);
  double y_before = 1.0;
  for (int k = 0; k < 200 && solver.first_tangled_cycle() < 0; ++k) {
    y_before = solver.position()[2 * 3 + 1];
    solver.step();
  }
  // Found at the first step that takes the node below the bottom edge, not before, not later
  // (the area check alone would wait until y < -1, and stop the run there).
  const double y = solver.position()[2 * 3 + 1];
  EXPECT_GE(y_before, 0.0);
  EXPECT_LT(y, 0.0);
  EXPECT_GT(y, -1.0);
  EXPECT_EQ(solver.first_tangled_element(), 1);
  EXPECT_EQ(solver.first_tangled_cycle(), solver.cycle());
  EXPECT_GE(solver.cycle(), 1);
  EXPECT_NO_THROW(solver.step());  // reported (stderr), not fatal
}
