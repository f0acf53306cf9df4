#include "solver/run_checkpoints.hpp"

#include <fmt/format.h>

#include <iostream>
#include <map>
#include <sstream>

#include "checkpoint/checkpoint_file.hpp"

namespace camouflet {

namespace fs = std::filesystem;

RunCheckpoints::RunCheckpoints(const Model& model, const RunOptions& options,
                               std::function<void(StateVisitor&)> visit_all)
    : model_(model),
      options_(options),
      visit_all_(std::move(visit_all)),
      dir_(options.output_dir.empty() ? fs::path() : options.output_dir / "checkpoints"),
      last_wall_(std::chrono::steady_clock::now()) {}

bool RunCheckpoints::due(std::int64_t cycle) const {
  const CheckpointControl& c = model_.checkpoint;
  if (dir_.empty()) return false;
  if (c.interval_cycles > 0 && cycle - last_cycle_ >= c.interval_cycles) return true;
  return c.interval_wall_s > 0.0 &&
         std::chrono::duration<double>(std::chrono::steady_clock::now() - last_wall_).count() >=
             c.interval_wall_s;
}

CheckpointData RunCheckpoints::collect(std::int64_t cycle, double time) const {
  CheckpointData data;
  StateRecorder recorder(data);
  visit_all_(recorder);
  set_meta(data, "case_fingerprint", options_.case_fingerprint);
  set_meta(data, "case_file", model_.case_file);
  set_meta(data, "cycle", std::to_string(cycle));
  set_meta(data, "time", fmt::format("{:.17g}", time));
  return data;
}

void RunCheckpoints::write(std::int64_t cycle, double time) {
  last_cycle_ = cycle;
  last_wall_ = std::chrono::steady_clock::now();
  if (dir_.empty()) return;
  CheckpointSeries(dir_, model_.checkpoint.keep).write(cycle, collect(cycle, time));
}

void RunCheckpoints::try_write(std::int64_t cycle, double time) noexcept {
  try {
    write(cycle, time);
  } catch (const std::exception& e) {
    std::cerr << "camouflet: the last checkpoint could not be written either: " << e.what() << '\n';
  }
}

void RunCheckpoints::write_failure(std::int64_t cycle, double time) noexcept {
  if (options_.output_dir.empty()) return;
  try {
    write_checkpoint(options_.output_dir / "failure.h5", collect(cycle, time));
  } catch (const std::exception& e) {
    std::cerr << "camouflet: the failure checkpoint could not be written: " << e.what() << '\n';
  }
}

void RunCheckpoints::restart() {
  SourceLocation where;
  where.file = options_.restart;
  std::vector<fs::path> candidates;
  if (options_.restart == "latest") {
    where.file = dir_.string();
    candidates = list_checkpoints(dir_);
    if (candidates.empty())
      throw InputError(where,
                       "--restart latest: no checkpoint in this folder (is -o the folder of the first run?)");
  } else {
    candidates.push_back(options_.restart);
  }
  for (const fs::path& path : candidates) {
    CheckpointData data;
    try {
      data = read_checkpoint(path);
    } catch (const CheckpointError& e) {
      std::cerr << "camouflet: " << e.what() << (candidates.size() > 1 ? "; trying the previous one" : "")
                << '\n';
      continue;
    }
    where.file = path.string();
    const std::string changed =
        first_changed_key(get_meta(data, "case_fingerprint"), options_.case_fingerprint);
    if (!changed.empty())
      throw InputError(where,
                       "the case differs from the run that wrote this checkpoint: " + changed +
                           " (only end_time, max_cycles, [output] and [checkpoint] may change on restart)");
    StateLoader loader(data);
    try {
      visit_all_(loader);
      loader.finish();
    } catch (const std::exception& e) {
      throw InputError(where, fmt::format("checkpoint does not fit this model: {}", e.what()));
    }
    last_cycle_ = 0;
    std::int64_t cycle = 0;
    std::istringstream(get_meta(data, "cycle")) >> cycle;
    last_cycle_ = cycle;
    return;
  }
  throw InputError(where, "no usable checkpoint (each one was refused, see above)");
}

std::string first_changed_key(const std::string& before, const std::string& after) {
  const auto parse = [](const std::string& text) {
    std::map<std::string, std::string> m;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      const auto eq = line.find(" = ");
      if (eq != std::string::npos) m[line.substr(0, eq)] = line.substr(eq + 3);
    }
    return m;
  };
  const auto a = parse(before), b = parse(after);
  for (const auto& [key, value] : a) {
    const auto it = b.find(key);
    if (it == b.end()) return fmt::format("key '{}' (was {}) is missing", key, value);
    if (it->second != value) return fmt::format("key '{}' changed from {} to {}", key, value, it->second);
  }
  for (const auto& [key, value] : b)
    if (!a.count(key)) return fmt::format("key '{}' = {} was added", key, value);
  return {};
}

}  // namespace camouflet
