// The MPI world (parallel/communicator.hpp) on 1-4 ranks: reductions in rank order with the same
// bits on every rank, the lowest rank on a tie, broadcasts, and the partition the same on every
// rank (METIS's fixed seed: rank 0 may partition alone and broadcast, or every rank itself).
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "common/block_mesh.hpp"
#include "parallel/communicator.hpp"
#include "parallel/partition.hpp"

namespace camouflet {
namespace {

TEST(MpiWorld, StartedByTheLauncher) {
  EXPECT_TRUE(started_by_mpi_launcher());
  EXPECT_GE(world().size(), 1);
  EXPECT_LT(world().rank(), world().size());
}

// A value whose sum depends on the order of the additions: 1e16 on rank 0, then 1 and -1e16
// alternating. In rank order: ((1e16 + 1) - 1e16) + ... ; 1e16 + 1 rounds to 1e16.
double order_sensitive(int rank) {
  return rank == 0 ? 1e16 : (rank % 2 == 1 ? 1.0 : -1e16);
}

TEST(MpiWorld, SumsAddInRankOrderWithTheSameBitsOnEveryRank) {
  const Communicator& c = world();
  double expected = 0.0;
  for (int r = 0; r < c.size(); ++r) expected += order_sensitive(r);
  const double total = c.sum(order_sensitive(c.rank()));
  EXPECT_EQ(std::memcmp(&total, &expected, sizeof total), 0) << total << " against " << expected;
  const std::vector<double> everyone = c.all_gather(std::span<const double>(&total, 1));
  for (double t : everyone) EXPECT_EQ(std::memcmp(&t, &total, sizeof t), 0);
  std::vector<double> arrays{order_sensitive(c.rank()), static_cast<double>(c.rank())};
  c.sum(std::span<double>(arrays));
  EXPECT_EQ(arrays[0], expected);
  EXPECT_EQ(arrays[1], c.size() * (c.size() - 1) / 2.0);
  EXPECT_EQ(c.sum(std::int64_t{c.rank() + 1}), std::int64_t{c.size()} * (c.size() + 1) / 2);
}

TEST(MpiWorld, MinimumAndMaximumNameTheLowestRankOnATie) {
  const Communicator& c = world();
  // Rank 0 holds 2, every other rank 1: the minimum is 1 on rank 1 (on one rank: 2 on rank 0).
  const auto low = c.min(c.rank() == 0 ? 2.0 : 1.0);
  EXPECT_EQ(low.value, c.size() == 1 ? 2.0 : 1.0);
  EXPECT_EQ(low.rank, c.size() == 1 ? 0 : 1);
  const auto high = c.max(c.rank() == c.size() - 1 ? 5.0 : 3.0);
  EXPECT_EQ(high.value, 5.0);
  EXPECT_EQ(high.rank, c.size() - 1);
  EXPECT_TRUE(c.any(c.rank() == c.size() - 1));
  EXPECT_FALSE(c.any(false));
}

TEST(MpiWorld, BroadcastCarriesTheRootsBytes) {
  const Communicator& c = world();
  const int root = c.size() - 1;
  std::vector<char> bytes;
  if (c.rank() == root) bytes.assign({'c', 'a', 'm', 'o', 'u', 'f', 'l', 'e', 't'});
  c.broadcast(bytes, root);
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "camouflet");
}

TEST(MpiWorld, EveryRankPartitionsAMeshAlike) {
  const Communicator& c = world();
  const FemMesh mesh = test::block_mesh(3, {2.0, 1.0, 1.0}, {24, 12, 12});
  const std::vector<int> mine = partition_elements(mesh, 4);
  std::vector<char> bytes(mine.size() * sizeof(int));
  std::memcpy(bytes.data(), mine.data(), bytes.size());
  c.broadcast(bytes, 0);
  EXPECT_EQ(std::memcmp(bytes.data(), mine.data(), bytes.size()), 0) << "rank " << c.rank();
}

}  // namespace
}  // namespace camouflet
