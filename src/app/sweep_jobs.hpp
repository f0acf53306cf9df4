#pragma once
// Child processes for `camouflet sweep`: each case runs as its own
// `camouflet run` process, so that a case that fails, aborts or runs out of
// memory ends only itself; at most `jobs` run at once.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace camouflet::app {

struct SweepJob {
  std::vector<std::string> arguments;  // argv[1..] of this executable
  std::filesystem::path log;           // stdout and stderr of the child
  // Filled in when the child has ended:
  int status = -1;  // exit code; 128 + signal when it was killed
  double wall_seconds = 0.0;
  std::string message;  // the child's last `error:` line, else its last line (failures only)
};

// Runs every job with at most `jobs` at once; `started(i)` is called before job
// i starts (to prepare its input; returning false skips it, keeping the job's
// status and message) and `done(i)` after it ends. Returns when all have ended.
void run_sweep_jobs(std::vector<SweepJob>& list, int jobs, const std::function<bool(std::size_t)>& started,
                    const std::function<void(std::size_t)>& done);

// The path of this executable (/proc/self/exe).
std::filesystem::path self_executable();

}  // namespace camouflet::app
