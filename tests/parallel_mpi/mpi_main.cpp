// The MPI tests' main: MPI initialised before GoogleTest (the test runs under mpirun, see
// tests/CMakeLists.txt), results printed by rank 0 only, and a failure on any rank fails the run
// on every rank.
#include <gtest/gtest.h>

#include "parallel/communicator.hpp"

int main(int argc, char** argv) {
  camouflet::ParallelSession session(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (camouflet::world().rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int failed = RUN_ALL_TESTS();
  return camouflet::world().any(failed != 0) ? 1 : 0;
}
