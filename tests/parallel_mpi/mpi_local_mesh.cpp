// The mesh cut among ranks (parallel/local_mesh.hpp) on 1-4 ranks: a hex block with moved nodes,
// each element spreading a value to its nodes (as lumped masses and internal forces are
// assembled), summed over the ranks that share a node, against the serial sum over the whole mesh:
// within 1e-14 relative (the ranks add their partial sums in rank order, the serial run its
// elements in element order: the same numbers added in another order), the same bits on every
// rank that holds the node, every node owned by one rank, and the node and face sets cut to
// the ranks adding up to the whole mesh's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <vector>

#include "common/block_mesh.hpp"
#include "parallel/communicator.hpp"
#include "parallel/local_mesh.hpp"
#include "parallel/partition.hpp"

namespace camouflet {
namespace {

FemMesh moved_block() {
  FemMesh mesh = test::block_mesh(3, {1.2, 0.8, 0.6}, {12, 8, 6});
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) mesh.coordinates[i] += 0.01 * std::sin(1.7 * i);
  return mesh;
}

// What element e gives each of its nodes, per component (3): a value no two elements share.
double contribution(std::int64_t e, int a, int k) {
  return std::sin(0.37 * e + 1.1 * a) + 0.5 * k + 2.0;
}

TEST(MpiLocalMesh, SharedNodesSumToTheSerialAssembly) {
  const Communicator& c = world();
  const FemMesh global = moved_block();
  const std::vector<int> part = partition_elements(global, c.size());
  const LocalMesh local = local_mesh(global, part, c.rank());

  std::vector<double> serial(global.node_count() * 3, 0.0);
  for (std::size_t e = 0; e < global.element_count(); ++e)
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k)
        serial[static_cast<std::size_t>(global.connectivity[e * 8 + static_cast<std::size_t>(a)]) * 3 +
               static_cast<std::size_t>(k)] += contribution(static_cast<std::int64_t>(e), a, k);

  std::vector<double> mine(local.global_node.size() * 3, 0.0);
  for (std::size_t e = 0; e < local.mesh.element_count(); ++e)
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k)
        mine[static_cast<std::size_t>(local.mesh.connectivity[e * 8 + static_cast<std::size_t>(a)]) * 3 +
             static_cast<std::size_t>(k)] += contribution(local.global_element[e], a, k);
  sum_shared_nodes(c, local, mine, 3);

  double worst = 0.0;
  for (std::size_t l = 0; l < local.global_node.size(); ++l)
    for (std::size_t k = 0; k < 3; ++k) {
      const double expected = serial[static_cast<std::size_t>(local.global_node[l]) * 3 + k];
      worst = std::max(worst, std::abs(mine[l * 3 + k] - expected) / std::abs(expected));
    }
  EXPECT_LE(worst, 1e-14) << "rank " << c.rank();

  // The same bits on every holder: each rank sends what it holds of every global node; compare.
  const auto n = static_cast<std::int64_t>(global.node_count());
  std::vector<double> held(global.node_count() * 3, std::nan("")), other;
  for (std::size_t l = 0; l < local.global_node.size(); ++l)
    for (std::size_t k = 0; k < 3; ++k)
      held[static_cast<std::size_t>(local.global_node[l]) * 3 + k] = mine[l * 3 + k];
  const std::vector<double> all = c.all_gather(std::span<const double>(held));
  std::int64_t differing = 0;
  for (std::int64_t g = 0; g < n * 3; ++g) {
    const double* first = nullptr;
    for (int r = 0; r < c.size(); ++r) {
      const double* v = &all[static_cast<std::size_t>(r * n * 3 + g)];
      if (std::isnan(*v)) continue;
      if (first == nullptr)
        first = v;
      else if (std::memcmp(first, v, sizeof(double)) != 0)
        ++differing;
    }
  }
  EXPECT_EQ(differing, 0);

  // Every node owned once; the sets add up to the whole mesh's.
  std::int64_t owned = 0;
  for (char o : local.owned) owned += o;
  EXPECT_EQ(c.sum(owned), n);
  for (const auto& [name, set] : global.node_sets) {
    std::int64_t owned_in_set = 0;
    for (std::int64_t l : local.mesh.node_sets.at(name))
      owned_in_set += local.owned[static_cast<std::size_t>(l)];
    EXPECT_EQ(c.sum(owned_in_set), static_cast<std::int64_t>(set.size())) << name;
  }
  for (const auto& [name, set] : global.face_sets)
    EXPECT_EQ(c.sum(static_cast<std::int64_t>(local.mesh.face_sets.at(name).size())),
              static_cast<std::int64_t>(set.size()))
        << name;
  EXPECT_EQ(c.sum(static_cast<std::int64_t>(local.mesh.element_count())),
            static_cast<std::int64_t>(global.element_count()));
}

}  // namespace
}  // namespace camouflet
