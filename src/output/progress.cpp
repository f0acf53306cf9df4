#include "output/progress.hpp"

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cmath>

#include "model/model.hpp"

namespace camouflet {

namespace {
// A terminal line is redrawn at most this often (s): drawing every cycle of a
// fast run would cost more than the cycle itself.
constexpr double terminal_refresh_s = 0.1;
// Columns of the terminal behind `stream` (0 when unknown). A line longer than
// the terminal wraps, and '\r' then rewrites only its last row: the line is
// cut to fit instead.
std::size_t terminal_columns(std::FILE* stream) {
  winsize ws{};
  if (ioctl(fileno(stream), TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
  return 0;
}

std::string fit(std::string line, std::size_t columns) {
  if (columns > 1 && line.size() > columns - 1) line.resize(columns - 1);
  return line;
}
}  // namespace

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  if (seconds < 60.0) return fmt::format("{:.1f}s", seconds);
  const auto total = static_cast<long long>(std::llround(seconds));
  const long long h = total / 3600, m = (total % 3600) / 60, s = total % 60;
  if (h > 0) return fmt::format("{}h{:02}m{:02}s", h, m, s);
  return fmt::format("{}m{:02}s", m, s);
}

ProgressReporter::ProgressReporter(ProgressStyle style, double end_time)
    : style_(style), end_time_(end_time), log_interval_s_(OutputControl{}.log_interval_s), stream_(stderr) {
  if (style_ == ProgressStyle::automatic)
    style_ = isatty(fileno(stream_)) ? ProgressStyle::terminal : ProgressStyle::plain;
}

std::string ProgressReporter::format_line(double time, double end_time, std::int64_t cycle, double dt,
                                          const std::string& dt_reason, double energy_error,
                                          double wall_seconds, double origin_time, double origin_wall) {
  // Remaining wall time by linear extrapolation in simulated time from the origin: explicit
  // runs have a nearly constant dt, so cost is nearly proportional to time.
  std::string remaining = "?";
  if (time > origin_time && end_time > time)
    remaining = format_duration((wall_seconds - origin_wall) * (end_time - time) / (time - origin_time));
  else if (time >= end_time)
    remaining = format_duration(0.0);
  const double percent = end_time > 0.0 ? 100.0 * time / end_time : 0.0;
  // Most useful first: a narrow terminal cuts the end of the line.
  return fmt::format(
      "t = {:.4e} s ({:.1f}%)  cycle {}  elapsed {}  remaining {}  energy error {:.2e}  dt = {:.3e} s "
      "[{}]",
      time, percent, cycle, format_duration(wall_seconds), remaining, energy_error, dt,
      dt_reason.empty() ? "-" : dt_reason);
}

void ProgressReporter::update(double time, std::int64_t cycle, double dt, const std::string& dt_reason,
                              double energy_error, double wall_seconds) {
  if (style_ == ProgressStyle::none) return;
  const bool first = last_line_.empty();
  if (style_ == ProgressStyle::terminal) {
    if (!first && wall_seconds - last_terminal_wall_ < terminal_refresh_s) {
      pending_ = true;
      last_line_ = fit(format_line(time, end_time_, cycle, dt, dt_reason, energy_error, wall_seconds,
                                   origin_time_, origin_wall_),
                       terminal_columns(stream_));
      return;
    }
    last_line_ = fit(format_line(time, end_time_, cycle, dt, dt_reason, energy_error, wall_seconds,
                                 origin_time_, origin_wall_),
                     terminal_columns(stream_));
    // Pad with spaces so a shorter line fully covers the previous one.
    const std::size_t pad = last_width_ > last_line_.size() ? last_width_ - last_line_.size() : 0;
    fmt::print(stream_, "\r{}{}", last_line_, std::string(pad, ' '));
    std::fflush(stream_);
    last_width_ = last_line_.size();
    last_terminal_wall_ = wall_seconds;
    pending_ = false;
    return;
  }
  // plain
  last_line_ = format_line(time, end_time_, cycle, dt, dt_reason, energy_error, wall_seconds, origin_time_,
                           origin_wall_);
  if (first || wall_seconds - last_plain_wall_ >= log_interval_s_) {
    fmt::print(stream_, "{}\n", last_line_);
    std::fflush(stream_);
    last_plain_wall_ = wall_seconds;
    pending_ = false;
  } else {
    pending_ = true;
  }
}

void ProgressReporter::done() {
  if (style_ == ProgressStyle::none || last_line_.empty()) return;
  if (style_ == ProgressStyle::terminal) {
    if (pending_) {
      const std::size_t pad = last_width_ > last_line_.size() ? last_width_ - last_line_.size() : 0;
      fmt::print(stream_, "\r{}{}", last_line_, std::string(pad, ' '));
    }
    fmt::print(stream_, "\n");
  } else if (pending_) {
    fmt::print(stream_, "{}\n", last_line_);
  }
  std::fflush(stream_);
  pending_ = false;
  last_line_.clear();
}

}  // namespace camouflet
