// Kill safety, through the real
// executable: SIGKILL at random moments always leaves a readable latest
// checkpoint and gauge CSVs made of complete lines, and `run --restart
// latest` finishes the run; SIGTERM writes a checkpoint and exits with 130
// within a few seconds, and the restarted run ends bit-identical to an
// uninterrupted one.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "../solver/restart_helpers.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "run_executable.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;
using clock_type = std::chrono::steady_clock;

// A run of a few seconds on a loaded machine: 2000 quads, ~2600 cycles, a gauge row every cycle.
std::string long_case() {
  std::string text = test::restart_fem_case("", "interval_cycles = 20\nkeep = 2\n");
  text.replace(text.find("end_time = 0.01"), 15, "end_time = 0.02");
  text.replace(text.find("cells = [4, 40]"), 15, "cells = [10, 200]");
  return text;
}

// Waits until the run has written its first gauge row (start-up done), at most 20 s.
void wait_for_start(const fs::path& out) {
  const auto limit = clock_type::now() + std::chrono::seconds(20);
  while (!fs::exists(out / "axis.csv") && clock_type::now() < limit)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

// Odd trials wait for the first checkpoint before their random delay, so at
// least half the kills hit a run that has one, however slow the build (an
// instrumented build starts too slowly for a fixed delay to reach it).
void wait_for_checkpoint(const fs::path& out) {
  const auto limit = clock_type::now() + std::chrono::seconds(60);
  while (list_checkpoints(out / "checkpoints").empty() && clock_type::now() < limit)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

pid_t start_run(const fs::path& case_file, const fs::path& out) {
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string log = (out.parent_path() / (out.filename().string() + ".log")).string();
    freopen(log.c_str(), "w", stderr);
    freopen("/dev/null", "w", stdout);
    execl(CAMOUFLET_EXECUTABLE, CAMOUFLET_EXECUTABLE, "run", "--quiet", "-t", "1", case_file.c_str(), "-o",
          out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// Sends SIGTERM to a run and waits for it: it must exit with 130 within 3 s.
void expect_sigterm_exits_130(pid_t pid) {
  const auto sent = clock_type::now();
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  const double seconds = std::chrono::duration<double>(clock_type::now() - sent).count();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_LT(seconds, 3.0);
}

// Every line ends with '\n' and has the header's number of fields.
void expect_complete_lines(const fs::path& csv) {
  const std::string text = test::read_text(csv);
  ASSERT_FALSE(text.empty()) << csv;
  EXPECT_EQ(text.back(), '\n') << "last row of " << csv << " is incomplete";
  const auto header_end = text.find('\n');
  const auto fields = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(header_end), ',');
  std::size_t start = 0, rows = 0;
  for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1, ++rows)
    ASSERT_EQ(std::count(text.begin() + static_cast<std::ptrdiff_t>(start),
                         text.begin() + static_cast<std::ptrdiff_t>(nl), ','),
              fields)
        << "row " << rows << " of " << csv;
}

TEST(KillSafety, SigkillAtRandomMomentsLeavesReadableCheckpointAndCompleteRows) {
  const fs::path root = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "kill";
  fs::remove_all(root);
  const fs::path case_file = root / "case.toml";
  test::write_text(case_file, long_case());
  std::mt19937 random(20261121);
  std::uniform_int_distribution<int> delay_ms(0, 1200);
  int with_checkpoint = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const fs::path out = root / ("trial" + std::to_string(trial));
    const pid_t pid = start_run(case_file, out);
    wait_for_start(out);
    if (trial % 2 == 1) wait_for_checkpoint(out);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(random)));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    if (fs::exists(out / "axis.csv")) expect_complete_lines(out / "axis.csv");
    const auto list = list_checkpoints(out / "checkpoints");
    if (list.empty()) continue;  // killed before the first checkpoint
    ++with_checkpoint;
    EXPECT_NO_THROW(read_checkpoint(list.front())) << "trial " << trial;
    if (with_checkpoint > 3) continue;  // restarting three of them keeps the test quick
    const auto r = test::run_camouflet("run --quiet -t 1 --restart latest '" + case_file.string() + "' -o '" +
                                       out.string() + "'");
    EXPECT_EQ(r.status, 0) << "trial " << trial << ": " << r.output;
    expect_complete_lines(out / "axis.csv");
  }
  EXPECT_GE(with_checkpoint, 5) << "too few trials got as far as a checkpoint";
}

TEST(KillSafety, SigtermWritesCheckpointAndExits130AndRestartIsBitIdentical) {
  const fs::path root = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "sigterm";
  fs::remove_all(root);
  const fs::path case_file = root / "case.toml";
  test::write_text(case_file, long_case());
  const auto full = test::run_camouflet("run --quiet -t 1 '" + case_file.string() + "' -o '" +
                                        (root / "full").string() + "'");
  ASSERT_EQ(full.status, 0) << full.output;

  const fs::path out = root / "stopped";
  const pid_t pid = start_run(case_file, out);
  wait_for_start(out);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  expect_sigterm_exits_130(pid);
  const std::string log = test::read_text(root / "stopped.log");
  EXPECT_NE(log.find("interrupted by signal 15"), std::string::npos) << log;
  const auto list = list_checkpoints(out / "checkpoints");
  ASSERT_FALSE(list.empty());
  EXPECT_NO_THROW(read_checkpoint(list.front()));
  expect_complete_lines(out / "axis.csv");

  const auto r = test::run_camouflet("run --quiet -t 1 --restart latest '" + case_file.string() + "' -o '" +
                                     out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(test::read_text(root / "full" / "axis.csv"), test::read_text(out / "axis.csv"));
  test::expect_same_final_state(root / "full", out);
}

// A full disk half way (the second snapshot goes to /dev/full): exit 3 with a
// clear message, after a last checkpoint that a restart can use.
TEST(KillSafety, SigtermDuringTheDynamicRelaxationExits130) {
  // A relaxation can run for many minutes before t = 0: one signal must end it as it ends the
  // transient (exit 130 within seconds), saying that no checkpoint was written.
  const fs::path root = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "sigterm_relaxation";
  fs::remove_all(root);
  const fs::path case_file = root / "case.toml";
  std::string text = long_case();
  text.replace(text.find("[run]\n"), 6, "[run]\ngravity = [0, -9.81]\n");
  text += "\n[run.dynamic_relaxation]\nperiod = 1000.0  # s: far from settled within the test\n";
  test::write_text(case_file, text);
  const fs::path out = root / "stopped";
  const pid_t pid = start_run(case_file, out);
  const auto limit = clock_type::now() + std::chrono::seconds(20);
  while (!fs::exists(out) && clock_type::now() < limit) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  expect_sigterm_exits_130(pid);
  const std::string log = test::read_text(root / "stopped.log");
  EXPECT_NE(log.find("interrupted by signal 15 during the dynamic relaxation"), std::string::npos) << log;
}

TEST(IoFailure, FullDiskStopsWithExitThreeAfterALastCheckpoint) {
  const fs::path root = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "full-disk";
  fs::remove_all(root);
  const fs::path case_file = root / "case.toml";
  test::write_text(case_file, test::restart_fem_case());
  const fs::path out = root / "out";
  fs::create_directories(out);
  fs::create_symlink("/dev/full", out / "fields_0001.vtu.tmp");
  const auto r =
      test::run_camouflet("run --quiet -t 1 '" + case_file.string() + "' -o '" + out.string() + "'");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("error: I/O failure: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  const auto list = list_checkpoints(out / "checkpoints");
  ASSERT_FALSE(list.empty()) << r.output;
  EXPECT_NO_THROW(read_checkpoint(list.front()));
  expect_complete_lines(out / "axis.csv");
}

}  // namespace
}  // namespace camouflet
