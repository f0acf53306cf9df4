// Elements to ranks (parallel/partition.hpp): METIS's k-way partition of the element face graph
// on structured blocks, against the planar cuts a person would draw: balanced within METIS's
// 3 % load tolerance, each part one piece, the faces cut at most a quarter above the planar cuts'
// (a partition much worse than that costs its halo exchange in proportion), the same partition on
// every call, and a weighted mesh balanced by weight rather than by count.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "common/block_mesh.hpp"
#include "common/verification.hpp"
#include "materials/elastic_strength.hpp"
#include "materials/linear_eos.hpp"
#include "materials/registry.hpp"
#include "mesh/block_generator.hpp"
#include "parallel/element_weights.hpp"
#include "parallel/partition.hpp"

namespace camouflet {
namespace {

FemMesh block_mesh(int dimension, std::array<int, 3> cells) {
  return test::block_mesh(dimension, {1.0 * cells[0], 1.0 * cells[1], 1.0 * cells[2]}, cells);
}

TEST(ElementFaceGraph, EachInteriorFaceJoinsTwoElements) {
  const FemMesh hexes = block_mesh(3, {4, 3, 2});
  const ElementGraph g3 = element_face_graph(hexes);
  // Interior faces of a 4 x 3 x 2 block: 3*3*2 + 4*2*2 + 4*3*1 = 46, each seen from both sides.
  EXPECT_EQ(g3.neighbours.size(), 2u * 46u);
  const FemMesh quads = block_mesh(2, {5, 4, 1});
  const ElementGraph g2 = element_face_graph(quads);
  EXPECT_EQ(g2.neighbours.size(), 2u * (4u * 4u + 5u * 3u));
}

TEST(Partition, BlocksSplitBalancedInOnePieceEachNearThePlanarCuts) {
  struct Case {
    int dimension;
    std::array<int, 3> cells;
    int parts;
    std::int64_t planar_cut;  // faces cut by the best planar cuts
  };
  const Case cases[] = {
      {3, {16, 16, 8}, 2, 16 * 8},                // one cut across x
      {3, {16, 16, 8}, 4, 2 * 16 * 8},            // quadrants
      {3, {16, 16, 8}, 8, 2 * 16 * 8 + 16 * 16},  // octants
      {2, {64, 32, 1}, 4, 3 * 32},                // four slabs across x, or quadrants (32 + 64)
      {2, {64, 32, 1}, 3, 2 * 32},                // three slabs across x
  };
  for (const Case& c : cases) {
    const FemMesh mesh = block_mesh(c.dimension, c.cells);
    const std::vector<int> part = partition_elements(mesh, c.parts);
    const PartitionQuality q = measure_partition(mesh, part, c.parts);
    const std::string what = fmt::format("{}-D block {}x{}{}, {} parts", c.dimension, c.cells[0], c.cells[1],
                                         c.dimension == 3 ? fmt::format("x{}", c.cells[2]) : "", c.parts);
    test::verify({"Partition, " + what + ": heaviest part / mean", "1 (METIS's load tolerance 1.03)", 1.0,
                  q.imbalance, 0.03, true, "-"});
    test::verify({"Partition, " + what + ": faces cut / the planar cuts'", "1 (planar cuts)", 1.0,
                  static_cast<double>(q.cut_faces) / static_cast<double>(c.planar_cut), 0.25, true, "-"});
    EXPECT_EQ(q.split_parts, 0) << what;
    EXPECT_EQ(partition_elements(mesh, c.parts), part) << what << ": the same partition on every call";
  }
}

TEST(Partition, WeightedElementsAreBalancedByWeight) {
  // The x < 8 half of a 16 x 16 x 8 block costs three times the other (soil beside elastic
  // elements): the parts balance the cost, so the heavy half gets more parts' worth of ranks.
  const FemMesh mesh = block_mesh(3, {16, 16, 8});
  std::vector<int> weights(mesh.element_count(), 1);
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    double x = 0.0;
    for (int a = 0; a < 8; ++a)
      x += mesh.coordinates[static_cast<std::size_t>(mesh.connectivity[e * 8 + static_cast<std::size_t>(a)]) *
                            3] /
           8;
    if (x < 8.0) weights[e] = 3;
  }
  const std::vector<int> part = partition_elements(mesh, 4, weights);
  const PartitionQuality by_weight = measure_partition(mesh, part, 4, weights);
  const PartitionQuality by_count = measure_partition(mesh, part, 4);
  test::verify({"Partition, 3-D block, half the elements weighing 3: heaviest part / mean, by weight",
                "1 (METIS's load tolerance 1.03)", 1.0, by_weight.imbalance, 0.03, true, "-"});
  // Balanced by weight, the parts in the light half hold three times the elements of those in the
  // heavy half: by count the heaviest is 1.5 times the mean.
  EXPECT_GT(by_count.imbalance, 1.3);
  EXPECT_EQ(by_weight.split_parts, 0);
}

TEST(ElementWeights, AConcreteWallWeighsItsMeasuredCost) {
  // Elastic soil beside a concrete wall (the RHT preset): each concrete element weighs 59, each
  // elastic one 10 (parallel/element_weights.cpp: 1345 against 229.5 ns per element-cycle), and two
  // parts split the cost, not the count: the wall's rank holds far fewer elements.
  Model model;
  model.run.mode = GeometryMode::three_d;
  model.mesh.dimension = 3;
  model.mesh.nodes_per_element = 8;
  add_block(model.mesh, {"soil", 0, {0, 0, 0}, {12, 8, 8}, {12, 8, 8}});
  add_block(model.mesh, {"wall", 1, {12, 0, 0}, {4, 8, 8}, {4, 8, 8}});
  model.materials.push_back({"soil", std::make_shared<const Material>(
                                         "soil", std::make_shared<const LinearEos>(2000.0, 2e9),
                                         std::make_shared<const ElasticStrength>(1.5e9)),
                             {}});
  model.materials.push_back(
      {"concrete", make_material("concrete", "concrete_35mpa_wang2005", SourceLocation{}, {}, {}, {}), {}});
  model.parts.push_back(Part{"soil", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"wall", PartKind::fem, 1, {}, {}, {}, {}, {}, {}, {}});
  const std::vector<int> weights = element_weights(model);
  EXPECT_EQ(weights.front(), 10);
  EXPECT_EQ(weights.back(), 59);
  const std::vector<int> part = partition_elements(model.mesh, 2, weights);
  const PartitionQuality by_weight = measure_partition(model.mesh, part, 2, weights);
  const PartitionQuality by_count = measure_partition(model.mesh, part, 2);
  test::verify({"Partition, soil beside a concrete wall (weights 10 and 59), 2 parts: heaviest / mean by cost",
                "1 (METIS's load tolerance 1.03)", 1.0, by_weight.imbalance, 0.03, true, "-"});
  // 768 soil elements weigh 7,680, 256 wall elements 15,104: by count the parts differ widely.
  EXPECT_GT(by_count.imbalance, 1.3);
}

TEST(Partition, BadRequestsAreRefused) {
  const FemMesh mesh = block_mesh(2, {2, 2, 1});
  EXPECT_THROW(partition_elements(mesh, 0), std::invalid_argument);
  EXPECT_THROW(partition_elements(mesh, 5), std::invalid_argument);
  const std::vector<int> zero(4, 0);
  EXPECT_THROW(partition_elements(mesh, 2, zero), std::invalid_argument);
  const std::vector<int> short_list(3, 1);
  EXPECT_THROW(partition_elements(mesh, 2, short_list), std::invalid_argument);
  EXPECT_EQ(partition_elements(mesh, 1), std::vector<int>(4, 0));
}

}  // namespace
}  // namespace camouflet
