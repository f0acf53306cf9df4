// Per-part hourglass control: two disconnected blocks, one part with
// the viscous form and one with the stiffness form, move as each block alone
// under the run-wide form of its part (to round-off: the colour-block force
// assembly adds each node's element forces in colour order, and the pair's mesh
// is coloured otherwise than a block alone); the hourglass energy of the pair
// is the sum of the two; a run split at a checkpoint ends bit-identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "common/fem_models.hpp"
#include "common/history_difference.hpp"
#include "common/test_output.hpp"
#include "common/verification.hpp"
#include "restart_helpers.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

// Block k of the pair: a coarse elastic block at x = 2k that strikes a sticking
// wall at 20 m/s (the corner elements shear: hourglass modes are excited, as in
// test_hourglass.cpp). 5 cells a side: 25 quads or 125 hexes, so a pack of
// elements holds both parts whatever the pack width (2, 4 or 8).
template <int D>
BlockSpec block_of(int k) {
  const std::string name = k == 0 ? "left" : "right";
  return {name, k, {2.0 * k, 0, 0}, {1, 1, 1}, {5, 5, 5}};
}

// The pair (both blocks) or block `only` alone, whose part `form`s are
// {viscous, stiffness}; alone, the block's form is the run's. Fixed step
// (initial_dt = max_dt, below the stability limit) so that the runs step alike.
template <int D>
Model blocks(int only, std::int64_t max_cycles = std::numeric_limits<std::int64_t>::max()) {
  const ElasticConstants c;
  const GeometryMode mode = D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d;
  const HourglassControl forms[2] = {{HourglassForm::viscous, 0.1}, {HourglassForm::stiffness, 0.1}};
  Model model;
  model.run.mode = mode;
  model.mesh.dimension = D;
  model.mesh.nodes_per_element = D == 2 ? 4 : 8;
  model.materials.push_back({"solid", test::elastic_material(c), {}});
  for (int k = 0; k < 2; ++k) {
    if (only >= 0 && k != only) continue;
    BlockSpec b = block_of<D>(k);
    b.part = static_cast<int>(model.parts.size());
    add_block(model.mesh, b);
    Part part;
    part.name = b.name;
    part.material = 0;
    part.initial_velocity[D - 1] = -20.0;
    if (only < 0)
      part.hourglass = forms[k];
    else
      model.run.hourglass = forms[k].form, model.run.hourglass_coefficient = forms[k].coefficient;
    model.parts.push_back(part);
    BoundaryCondition fixed;
    fixed.kind = BoundaryKind::fixed;
    fixed.set = b.name + (D == 2 ? ".ymin" : ".zmin");
    model.boundaries.push_back(fixed);
  }
  const double dt = 0.25 * 0.2 / c.p_wave_speed();  // a quarter of the crossing time of a cell
  model.run.initial_dt = model.run.max_dt = dt;
  model.run.end_time = 4.0 / c.p_wave_speed();  // two round trips of the P-wave
  model.run.max_cycles = max_cycles;
  return model;
}


template <int D>
void expect_pair_as_each_alone(const std::string& label) {
  test::use_threads(1);
  const Model pair_model = blocks<D>(-1);
  Solver<D> pair(pair_model);
  std::vector<std::unique_ptr<Solver<D>>> alone;
  std::vector<Model> alone_models{blocks<D>(0), blocks<D>(1)};
  for (const Model& m : alone_models) alone.push_back(std::make_unique<Solver<D>>(m));
  const std::size_t nodes0 = alone[0]->node_count();
  ASSERT_EQ(pair.node_count(), nodes0 + alone[1]->node_count());
  int steps = 0;
  while (pair.time() < pair_model.run.end_time) {
    pair.step();
    for (auto& s : alone) s->step();
    ++steps;
  }
  ASSERT_GT(steps, 50);
  // Node k of block 1 alone is node nodes0 + k of the pair.
  const auto part = [&](const std::vector<double>& whole, std::size_t first, std::size_t count) {
    return std::vector<double>(whole.begin() + static_cast<std::ptrdiff_t>(first * D),
                               whole.begin() + static_cast<std::ptrdiff_t>((first + count) * D));
  };
  const std::size_t nodes1 = alone[1]->node_count();
  for (int block = 0; block < 2; ++block) {
    const std::size_t first = block == 0 ? 0 : nodes0, count = block == 0 ? nodes0 : nodes1;
    const Solver<D>& one = *alone[static_cast<std::size_t>(block)];
    const double dx = test::relative_difference(part(pair.displacement(), first, count), one.displacement());
    const double dv = test::relative_difference(part(pair.velocity(), first, count), one.velocity());
    test::verify({label + ": " + (block == 0 ? "viscous" : "stiffness") +
                      " part of the pair vs its block alone, node displacements and velocities",
                  "the same motion (round-off of the summation order)", 0.0, std::max(dx, dv), 1e-12, false,
                  "relative"});
  }
  // The two blocks' motions differ (the forms act differently), so the
  // comparison above tells the forms apart.
  const std::vector<double>& v0 = alone[0]->velocity();
  const std::vector<double>& v1 = alone[1]->velocity();
  EXPECT_NE(std::memcmp(v0.data(), v1.data(), v0.size() * sizeof(double)), 0);
  // Hourglass energy: the viscous block's dissipated work plus the stiffness
  // block's stored energy (only the summation order differs).
  const double sum = alone[0]->energy().hourglass + alone[1]->energy().hourglass;
  EXPECT_GT(alone[0]->energy().hourglass, 0.0);
  EXPECT_GT(alone[1]->energy().hourglass, 0.0);
  test::verify({label + ": hourglass energy of the pair", "sum of each block alone", sum,
                pair.energy().hourglass, 1e-12, true, "J"});
}

TEST(HourglassParts, QuadBlocksOfTwoFormsMoveAsEachAlone) {
  expect_pair_as_each_alone<2>("Per-part hourglass, quads");
}

TEST(HourglassParts, HexBlocksOfTwoFormsMoveAsEachAlone) {
  expect_pair_as_each_alone<3>("Per-part hourglass, hexes");
}

// The pair with checkpoints, a gauge in each block.
Model pair_with_checkpoints(std::int64_t max_cycles) {
  Model model = blocks<2>(-1, max_cycles);
  model.checkpoint.interval_cycles = 1000000;
  GaugeGroup group;
  group.name = "blocks";
  group.points.push_back({"left", {0.5, 0.5, 0.0}, {}});
  group.points.push_back({"right", {2.5, 0.5, 0.0}, {}});
  model.gauges.push_back(group);
  return model;
}

TEST(HourglassParts, MixedFormRunSplitAtACheckpointIsBitIdentical) {
  test::use_threads(1);
  const auto root = test::fresh_test_output(std::filesystem::path("restart") / "hourglass_parts");
  const std::int64_t cycles = test::expect_split_run_bit_identical(root, pair_with_checkpoints, "blocks.csv");
  EXPECT_GT(cycles, 50);
}

}  // namespace
