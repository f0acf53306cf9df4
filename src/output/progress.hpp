#pragma once
// The progress line of a run (command line): on a terminal one line
// rewritten in place with '\r'; otherwise a plain log line every
// OutputControl::log_interval_s wall seconds (so CI logs and `nohup` files stay
// readable); nothing with --quiet. The solver calls update() after each cycle
// and done() once at the end. Output goes to stderr, results go to files.
#include <cstdint>
#include <cstdio>
#include <string>

#include "model/run_options.hpp"

namespace camouflet {

class ProgressReporter {
 public:
  // `automatic` becomes `terminal` when stderr is a terminal, else `plain`.
  ProgressReporter(ProgressStyle style, double end_time);
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // time (s), cycle, dt (s) with the reason that limited it, the relative
  // energy error and the wall seconds since the run started.
  void update(double time, std::int64_t cycle, double dt, const std::string& dt_reason, double energy_error,
              double wall_seconds);
  // Ends the terminal line (or prints a final plain line).
  void done();

  // Where the transient's own cost starts: the simulated time and wall seconds at which the
  // cycle to end_time begins (after a dynamic relaxation, or at a restart's time). The
  // remaining time is extrapolated from the cost since then, not from the set-up's.
  void set_origin(double time, double wall_seconds) {
    origin_time_ = time;
    origin_wall_ = wall_seconds;
  }
  // Wall seconds between plain log lines (default OutputControl::log_interval_s).
  void set_log_interval(double seconds) { log_interval_s_ = seconds; }
  ProgressStyle style() const { return style_; }

  // The text of one progress report, without line ending (shared by both styles); the
  // remaining time is extrapolated from (origin_time, origin_wall) on.
  static std::string format_line(double time, double end_time, std::int64_t cycle, double dt,
                                 const std::string& dt_reason, double energy_error, double wall_seconds,
                                 double origin_time = 0.0, double origin_wall = 0.0);

 private:
  ProgressStyle style_;
  double end_time_;
  double log_interval_s_;
  double origin_time_ = 0.0, origin_wall_ = 0.0;  // s (simulated), s (wall): see set_origin
  double last_plain_wall_ = -1.0;
  double last_terminal_wall_ = -1.0;
  std::size_t last_width_ = 0;
  bool pending_ = false;  // something was reported that the last printed line does not show
  std::string last_line_;
  std::FILE* stream_;
};

// Wall time as "1h02m03s", "4m05s" or "6.7s".
std::string format_duration(double seconds);

}  // namespace camouflet
