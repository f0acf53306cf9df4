#pragma once
// Stopping a run on SIGINT/SIGTERM: the signal handler only sets a
// flag (async-signal-safe); run_model() sees it after the current cycle,
// writes a checkpoint, completes its output and throws RunInterrupted, which
// the command line turns into exit code 130 (docs/exit-codes.md).
#include <stdexcept>

namespace camouflet {

// Async-signal-safe: only stores the signal number.
void request_stop(int signal) noexcept;
int stop_requested() noexcept;  // 0 when none
void clear_stop_request() noexcept;

class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted(int signal, const std::string& message) : std::runtime_error(message), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

}  // namespace camouflet
