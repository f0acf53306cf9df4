// Failures the solver must name (the
// NumericalError contract), the driver's bookkeeping, and thread-count
// independence of the trajectory.
#include <gtest/gtest.h>

#include <cmath>

#include "common/fem_models.hpp"
#include "solver/run.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

Model small_block() {
  return test::block_model(GeometryMode::plane_strain, {{"block", 0, {0, 0, 0}, {1, 1, 0}, {3, 3, 1}}},
                           ElasticConstants{});
}

}  // namespace

TEST(SolverErrors, InvertedElementIsRefusedNamingIt) {
  test::use_threads(1);
  Model model = small_block();
  // Element 5 (the middle one): swap two of its nodes, turning it clockwise.
  std::swap(model.mesh.connectivity[4 * 4 + 1], model.mesh.connectivity[4 * 4 + 3]);
  try {
    Solver<2> solver(model);
    FAIL() << "an inverted element must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 5 "), std::string::npos) << e.what();
  }
}

TEST(SolverErrors, DegenerateHexIsRefusedNamingIt) {
  test::use_threads(1);
  Model model = test::block_model(GeometryMode::three_d, {{"b", 0, {0, 0, 0}, {1, 1, 1}, {2, 1, 1}}},
                                  ElasticConstants{});
  for (int a = 4; a < 8; ++a)  // collapse the top face of element 2 onto its bottom
    model.mesh.connectivity[8 + static_cast<std::size_t>(a)] =
        model.mesh.connectivity[8 + static_cast<std::size_t>(a - 4)];
  EXPECT_THROW(
      {
        try {
          Solver<3> solver(model);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("element 2 "), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
}

TEST(SolverErrors, ElementInvertedDuringTheRunIsNamed) {
  test::use_threads(1);
  Model model = small_block();
  model.run.cfl = 8.0;  // far beyond stability: a corner node overshoots its element
  model.mesh.node_sets["corner"] = {15};
  model.boundaries.push_back(test::velocity("corner", 0, -3000.0));
  model.boundaries.push_back(test::velocity("corner", 1, -3000.0));
  Solver<2> solver(model);
  try {
    for (int k = 0; k < 50; ++k) solver.step();
    FAIL() << "the element must invert";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.kind(), EntityKind::element);
    // The first element (lowest id) found inverted is named, 1-based.
    EXPECT_GE(e.id(), 1);
    EXPECT_LE(e.id(), 9);
    EXPECT_NE(std::string(e.what()).find("element " + std::to_string(e.id()) + " "), std::string::npos)
        << e.what();
    EXPECT_EQ(e.quantity(), "volume");
    EXPECT_GE(e.cycle(), 0);
    EXPECT_NE(std::string(e.what()).find("solid"), std::string::npos) << e.what();
    // The diagnostic also says where: material and element centre.
    EXPECT_NE(std::string(e.what()).find("(material 'solid', centre ("), std::string::npos) << e.what();
  }
}

TEST(SolverErrors, TimeStepCollapseIsNamed) {
  test::use_threads(1);
  Model model = small_block();
  model.run.min_dt = 1.0;  // s: every step is "too small"
  try {
    Solver<2> solver(model);
    FAIL() << "a time step below min_dt must stop the run";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.quantity(), "time step");
    EXPECT_EQ(e.kind(), EntityKind::element);
  }
}

TEST(SolverErrors, UnknownBoundarySetSuggestsTheNearest) {
  test::use_threads(1);
  Model model = small_block();
  model.boundaries.push_back(test::velocity("block.xmn", 0, 1.0));
  try {
    Solver<2> solver(model);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("block.xmin"), std::string::npos) << e.what();
  }
}

TEST(RunModel, RunsToTheEndTimeWithABalancedEnergy) {
  test::use_threads(1);
  Model model = small_block();
  model.boundaries.push_back(test::velocity("block.xmin", 0, 2.0));  // a piston pushes the block
  model.run.end_time = 2e-3;
  RunOptions options;
  options.progress = ProgressStyle::none;
  options.threads = 1;
  const RunSummary s = run_model(model, options);
  EXPECT_DOUBLE_EQ(s.time, 2e-3);
  EXPECT_GT(s.cycles, 10);
  EXPECT_FALSE(s.failed);
  EXPECT_EQ(s.stop_reason, "end time reached");
  EXPECT_FALSE(s.last_limit.reason.empty());
  // The piston's work goes into the block: the balance must hold with it.
  EXPECT_GT(s.energy.boundary_work, 0.0);
  EXPECT_GT(s.energy.kinetic, 0.1 * s.energy.boundary_work);
  EXPECT_LT(s.energy.relative_error, 1e-3);
}

TEST(RunModel, DeterministicForAGivenThreadCount) {
  // Large enough (> parallel_threshold elements) for the threaded loops to run.
  Model model = test::block_model(GeometryMode::three_d, {{"b", 0, {0, 0, 0}, {1, 1, 0.5}, {16, 16, 10}}},
                                  ElasticConstants{});
  model.parts[0].initial_velocity = {0.0, 0.0, -5.0};
  BoundaryCondition fixed;
  fixed.kind = BoundaryKind::fixed;
  fixed.set = "b.zmin";
  model.boundaries.push_back(fixed);
  const auto displacement_after = [&](int threads) {
    test::use_threads(threads);
    Solver<3> solver(model);
    for (int k = 0; k < 10; ++k) solver.step();
    return solver.displacement();
  };
  const auto two_a = displacement_after(2), two_b = displacement_after(2), one = displacement_after(1);
  test::use_threads(1);
  // Same thread count: bit for bit (per-thread force buffers summed in thread order).
  EXPECT_EQ(two_a, two_b);
  // Another thread count only changes the summation order: round-off.
  double largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < one.size(); ++k) {
    largest = std::max(largest, std::abs(one[k]));
    difference = std::max(difference, std::abs(one[k] - two_a[k]));
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(difference, 1e-12 * largest);
}

TEST(SolverErrors, AxisOutsideAxisymmetricModeIsRefused) {
  test::use_threads(1);
  Model axis_in_plane_strain = small_block();
  BoundaryCondition axis;
  axis.kind = BoundaryKind::axis;
  axis.set = "block.xmin";
  axis_in_plane_strain.boundaries.push_back(axis);
  EXPECT_THROW(Solver<2> solver(axis_in_plane_strain), InputError);
}
