#include <gtest/gtest.h>

#include "output/progress.hpp"

namespace camouflet {
namespace {

TEST(Progress, LineNamesTimeCycleDtReasonErrorAndRemaining) {
  // Half-way after 10 s of wall time: 10 s should remain.
  const std::string line =
      ProgressReporter::format_line(5e-3, 1e-2, 1234, 2.5e-7, "element 17 (steel): l/(c+|v|)", 3.2e-5, 10.0);
  EXPECT_NE(line.find("t = 5.0000e-03 s"), std::string::npos) << line;
  EXPECT_NE(line.find("50.0%"), std::string::npos) << line;
  EXPECT_NE(line.find("cycle 1234"), std::string::npos) << line;
  EXPECT_NE(line.find("dt = 2.500e-07 s [element 17 (steel): l/(c+|v|)]"), std::string::npos) << line;
  EXPECT_NE(line.find("energy error 3.20e-05"), std::string::npos) << line;
  EXPECT_NE(line.find("elapsed 10.0s"), std::string::npos) << line;
  EXPECT_NE(line.find("remaining 10.0s"), std::string::npos) << line;
}

TEST(Progress, RemainingTimeCountsFromTheOrigin) {
  // A restart at 2 ms (or a relaxation that took 6 s of wall time before t = 0): 4 s of wall for
  // 3 ms of simulated time since then, 5 ms to go: 6.7 s remain, not the 10 s that the whole
  // elapsed time over the whole simulated time would give.
  const std::string line = ProgressReporter::format_line(5e-3, 1e-2, 1234, 2.5e-7, "x", 0.0, 10.0, 2e-3, 6.0);
  EXPECT_NE(line.find("remaining 6.7s"), std::string::npos) << line;
  EXPECT_NE(line.find("elapsed 10.0s"), std::string::npos) << line;
}

TEST(Progress, DurationsReadable) {
  EXPECT_EQ(format_duration(6.71), "6.7s");
  EXPECT_EQ(format_duration(245.0), "4m05s");
  EXPECT_EQ(format_duration(3723.0), "1h02m03s");
  EXPECT_EQ(format_duration(-1.0), "?");
}

TEST(Progress, QuietAndPlainStylesDoNotThrow) {
  ProgressReporter quiet(ProgressStyle::none, 1.0);
  quiet.update(0.5, 1, 1e-3, "x", 0.0, 1.0);
  quiet.done();
  ProgressReporter automatic(ProgressStyle::automatic, 1.0);
  EXPECT_NE(automatic.style(), ProgressStyle::automatic);
}

}  // namespace
}  // namespace camouflet
