// r-z: a node that crosses the axis must be reported, naming it, the cycle and the time (the
// join-face nodes next to the axis of the buried-structure case once ran across it and the run went on
// for 20 ms with inverted ring elements, unreported, because the element centres stayed at r > 0).
// A warning, as a tangled element (solver_checks.cpp, docs/reliability.md).
#include <gtest/gtest.h>

#include "common/fem_models.hpp"
#include "core/error.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

// Two 0.1 m squares side by side, r in [0, 0.2], z in [0, 0.1]; the nodes on the axis are held by
// the axis condition, the middle pair (r = 0.1) is driven inwards at `inward_speed` m/s, the
// outer pair held. (The solver keeps a reference to the model.)
Model driven_ring(double inward_speed) {
  Model model =
      test::block_model(GeometryMode::axisymmetric, {{"block", 0, {0, 0, 0}, {0.2, 0.1, 0}, {2, 1, 1}}},
                        test::ElasticConstants{});
  model.mesh.node_sets["middle"] = {1, 4};
  model.mesh.node_sets["outer"] = {2, 5};
  model.mesh.node_sets["axis"] = {0, 3};
  model.boundaries.push_back(test::velocity("axis", 0, 0.0));
  model.boundaries.push_back(test::velocity("middle", 0, -inward_speed));
  model.boundaries.push_back(test::velocity("middle", 1, 0.0));
  model.boundaries.push_back(test::velocity("outer", 0, 0.0));
  model.boundaries.push_back(test::velocity("outer", 1, 0.0));
  return model;
}

}  // namespace

TEST(SolverDiagnostics, NodeCrossingTheAxisIsReported) {
  test::use_threads(1);
  // A stable step never carries a velocity-driven node across: the step
  // shrinks with the element between it and the axis. A prescribed first
  // step of 30 us moves it 0.15 m, past the axis, as an unstable step would.
  Model model = driven_ring(5000.0);
  model.run.initial_dt = 3e-5;
  Solver<2> solver(model);
  double r_before = 0.1;
  for (int k = 0; k < 2000 && solver.first_axis_crossing_cycle() < 0; ++k) {
    r_before = solver.position()[2 * 1];
    try {
      solver.step();
    } catch (const NumericalError&) {
      break;  // the element between it and the axis has collapsed: checked after the crossing
    }
  }
  // Found at the step that took node 2 (1-based) past r = 0, not before.
  EXPECT_GE(r_before, 0.0);
  EXPECT_LT(solver.position()[2 * 1], 0.0);
  EXPECT_EQ(solver.first_axis_crossing_node(), 2);
  EXPECT_EQ(solver.first_axis_crossing_cycle(), solver.cycle());
}

TEST(SolverDiagnostics, NodesOnTheAxisAndMovingOutwardsAreNotAxisCrossings) {
  test::use_threads(1);
  const Model model = driven_ring(-50.0);  // outwards
  Solver<2> solver(model);
  EXPECT_NO_THROW(for (int k = 0; k < 50; ++k) solver.step());
  EXPECT_EQ(solver.position()[0], 0.0);  // the axis node stays exactly on the axis
  EXPECT_LT(solver.first_axis_crossing_cycle(), 0);
}
