// The serial communicator (parallel/communicator.hpp): what a run without mpirun reduces with.
// Started without an MPI launcher, the world is serial and every reduction is the value itself.
#include <gtest/gtest.h>

#include <vector>

#include "parallel/communicator.hpp"

namespace camouflet {
namespace {

TEST(SerialCommunicator, ReductionsAreTheValueItself) {
  const SerialCommunicator c;
  EXPECT_EQ(c.rank(), 0);
  EXPECT_EQ(c.size(), 1);
  EXPECT_EQ(c.sum(2.5), 2.5);
  EXPECT_EQ(c.sum(std::int64_t{7}), 7);
  const auto low = c.min(-3.0), high = c.max(4.0);
  EXPECT_EQ(low.value, -3.0);
  EXPECT_EQ(low.rank, 0);
  EXPECT_EQ(high.value, 4.0);
  EXPECT_TRUE(c.any(true));
  EXPECT_FALSE(c.any(false));
  std::vector<double> v{1.0, 2.0};
  c.sum(std::span<double>(v));
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.0}));
  std::vector<char> bytes{'a', 'b'};
  c.broadcast(bytes, 0);
  EXPECT_EQ(bytes.size(), 2u);
}

TEST(SerialCommunicator, WithoutALauncherTheWorldIsSerial) {
  if (started_by_mpi_launcher()) GTEST_SKIP() << "started by an MPI launcher";
  EXPECT_EQ(world().size(), 1);
  int argc = 0;
  char** argv = nullptr;
  ParallelSession session(argc, argv);  // no launcher: no MPI
  EXPECT_EQ(world().size(), 1);
}

}  // namespace
}  // namespace camouflet
