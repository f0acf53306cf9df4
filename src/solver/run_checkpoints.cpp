#include "solver/run_checkpoints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>

#include "checkpoint/checkpoint_file.hpp"

namespace camouflet {

namespace fs = std::filesystem;

namespace {

bool on_ranks(const Communicator* ranks) { return ranks && ranks->size() > 1; }

std::string rank_folder(int rank, int size) { return fmt::format("rank_{}_of_{}", rank, size); }

// The cycle in a checkpoint's name (checkpoint_<cycle>.h5).
std::int64_t cycle_of(const fs::path& path) {
  std::int64_t cycle = -1;
  std::istringstream(path.stem().string().substr(std::string("checkpoint_").size())) >> cycle;
  return cycle;
}

}  // namespace

RunCheckpoints::RunCheckpoints(const Model& model, const RunOptions& options,
                               std::function<void(StateVisitor&)> visit_all, const Communicator* ranks)
    : model_(model),
      options_(options),
      visit_all_(std::move(visit_all)),
      ranks_(on_ranks(ranks) ? ranks : nullptr),
      dir_(options.output_dir.empty() ? fs::path()
           : ranks_                   ? options.output_dir / "checkpoints" / rank_folder(ranks_->rank(), ranks_->size())
                                      : options.output_dir / "checkpoints"),
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
  set_meta(data, "ranks", std::to_string(ranks_ ? ranks_->size() : 1));
  if (ranks_) set_meta(data, "rank", std::to_string(ranks_->rank()));
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
    write_checkpoint(options_.output_dir / (ranks_ ? "failure_" + rank_folder(ranks_->rank(), ranks_->size()) + ".h5"
                                                  : std::string("failure.h5")),
                     collect(cycle, time));
  } catch (const std::exception& e) {
    std::cerr << "camouflet: the failure checkpoint could not be written: " << e.what() << '\n';
  }
}

std::string RunCheckpoints::other_rank_count() const {
  const fs::path top = options_.output_dir / "checkpoints";
  const int here = ranks_ ? ranks_->size() : 1;
  std::error_code ec;
  if (here != 1 && !list_checkpoints(top).empty()) return "one rank";
  if (!fs::is_directory(top, ec)) return {};
  for (const auto& entry : fs::directory_iterator(top, ec)) {
    const std::string name = entry.path().filename().string();
    const auto of = name.find("_of_");
    if (name.rfind("rank_", 0) != 0 || of == std::string::npos) continue;
    const int count = std::atoi(name.c_str() + of + 4);
    if (count != here && !list_checkpoints(entry.path()).empty()) return fmt::format("{} ranks", count);
  }
  return {};
}

void RunCheckpoints::load(const fs::path& path, const CheckpointData& data, SourceLocation& where) {
  where.file = path.string();
  const std::string changed = first_changed_key(get_meta(data, "case_fingerprint"), options_.case_fingerprint);
  if (!changed.empty())
    throw InputError(where,
                     "the case differs from the run that wrote this checkpoint: " + changed +
                         " (only end_time, max_cycles, [output] and [checkpoint] may change on restart)");
  const std::string ranks_meta = get_meta(data, "ranks");  // absent before runs across ranks: one
  const int written_on = ranks_meta.empty() ? 1 : std::atoi(ranks_meta.c_str());
  const int here = ranks_ ? ranks_->size() : 1;
  if (written_on != here)
    throw InputError(where, fmt::format("this checkpoint was written on {} MPI rank{}; restart it on as many "
                                        "(this run has {})",
                                        written_on, written_on == 1 ? "" : "s", here));
  StateLoader loader(data);
  try {
    visit_all_(loader);
    loader.finish();
  } catch (const std::exception& e) {
    throw InputError(where, fmt::format("checkpoint does not fit this model: {}", e.what()));
  }
  std::int64_t cycle = 0;
  std::istringstream(get_meta(data, "cycle")) >> cycle;
  last_cycle_ = cycle;
}

void RunCheckpoints::restart() {
  if (ranks_) return restart_on_ranks();
  SourceLocation where;
  where.file = options_.restart;
  std::vector<fs::path> candidates;
  if (options_.restart == "latest") {
    where.file = dir_.string();
    candidates = list_checkpoints(dir_);
    if (candidates.empty()) {
      const std::string other = other_rank_count();
      throw InputError(where, other.empty() ? "--restart latest: no checkpoint in this folder (is -o the folder of "
                                              "the first run?)"
                                            : "--restart latest: the checkpoints in this folder were written on " +
                                                  other + "; restart on as many (mpirun -np N)");
    }
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
    load(path, data, where);
    return;
  }
  throw InputError(where, "no usable checkpoint (each one was refused, see above)");
}

void RunCheckpoints::restart_on_ranks() {
  const Communicator& comm = *ranks_;
  SourceLocation where;
  where.file = dir_.string();
  if (options_.restart != "latest")
    throw InputError(SourceLocation{options_.restart, 0, 0, ""},
                     "a run across MPI ranks restarts from --restart latest (each rank reads its own folder, "
                     "checkpoints/rank_<r>_of_<n>)");
  // Every rank's checkpoints, newest first: the cycles all of them have, tried newest first, each
  // rank reading its own file; one that cannot be read on any rank sends all to the previous one.
  constexpr std::size_t listed = 32;
  std::vector<std::int64_t> mine(listed, -1);
  const std::vector<fs::path> own = list_checkpoints(dir_);
  for (std::size_t k = 0; k < std::min(listed, own.size()); ++k) mine[k] = cycle_of(own[k]);
  const std::vector<std::int64_t> all = comm.all_gather(std::span<const std::int64_t>(mine));
  std::vector<std::int64_t> common;
  for (const std::int64_t cycle : mine) {
    if (cycle < 0) break;
    bool everywhere = true;
    for (int r = 0; r < comm.size() && everywhere; ++r) {
      const auto begin = all.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(r) * listed);
      everywhere = std::find(begin, begin + static_cast<std::ptrdiff_t>(listed), cycle) != begin + listed;
    }
    if (everywhere) common.push_back(cycle);
  }
  if (common.empty()) {
    const std::string other = other_rank_count();
    throw InputError(where, other.empty()
                                ? "--restart latest: no checkpoint that every rank has in this folder (is -o the "
                                  "folder of the first run?)"
                                : "--restart latest: the checkpoints in this folder were written on " + other +
                                      "; restart on as many");
  }
  // `common` is the same list on every rank (this rank's list filtered by all of them).
  for (const std::int64_t cycle : common) {
    const fs::path path = dir_ / fmt::format("checkpoint_{:012}.h5", cycle);
    CheckpointData data;
    bool read = true;
    try {
      data = read_checkpoint(path);
    } catch (const CheckpointError& e) {
      std::cerr << "camouflet: rank " << comm.rank() << ": " << e.what() << "; trying the previous one\n";
      read = false;
    }
    if (comm.any(!read)) continue;
    load(path, data, where);
    return;
  }
  throw InputError(where, "no usable checkpoint that every rank has (each one was refused, see above)");
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
