#pragma once
// The checkpoint side of run_model() (docs/reliability.md): when to
// write, where, and finding and checking the checkpoint a restart starts from.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "checkpoint/checkpoint_data.hpp"
#include "model/model.hpp"
#include "parallel/communicator.hpp"
#include "solver/run.hpp"

namespace camouflet {

class RunCheckpoints {
 public:
  // `visit_all` visits the whole run state (solver, then output). On MPI ranks (`ranks` of more
  // than one; docs/parallel.md) each rank writes its own state in a folder of its own,
  // checkpoints/rank_<r>_of_<n>/, and a restart takes the newest cycle every rank has.
  RunCheckpoints(const Model& model, const RunOptions& options, std::function<void(StateVisitor&)> visit_all,
                 const Communicator* ranks = nullptr);

  // True when the case's cycle or wall interval has elapsed since the last write.
  bool due(std::int64_t cycle) const;
  // Writes <output>/checkpoints/checkpoint_<cycle>.h5 (keeping the last N); nothing without an output folder.
  void write(std::int64_t cycle, double time);
  // Writes <output>/failure.h5 (on ranks failure_rank_<r>_of_<n>.h5) for inspection after a
  // numerical failure; never throws (reports on stderr).
  void write_failure(std::int64_t cycle, double time) noexcept;
  // A last attempt after an I/O failure: never throws.
  void try_write(std::int64_t cycle, double time) noexcept;

  // Reads the checkpoint named by options.restart ("latest": the newest
  // usable one, a refused one is reported and the previous one tried),
  // checks it against the case fingerprint and loads it through visit_all.
  // Throws InputError when there is none usable or the case changed a key
  // that must not change (naming the key), and when the checkpoints were written on another
  // number of ranks (naming it). On ranks only "latest" is taken.
  void restart();

  const std::filesystem::path& dir() const { return dir_; }

 private:
  CheckpointData collect(std::int64_t cycle, double time) const;
  void load(const std::filesystem::path& path, const CheckpointData& data, SourceLocation& where);
  void restart_on_ranks();
  // The checkpoints in `dir_`'s parent written on another number of ranks: "3 ranks", "one rank"
  // or empty.
  std::string other_rank_count() const;

  const Model& model_;
  const RunOptions& options_;
  std::function<void(StateVisitor&)> visit_all_;
  const Communicator* ranks_;  // null or one rank: the serial layout
  std::filesystem::path dir_;
  std::int64_t last_cycle_ = 0;
  std::chrono::steady_clock::time_point last_wall_;
};

// The first key whose "key = value" line differs between two fingerprints
// (case/case_fingerprint.hpp), with both values; empty when they agree.
std::string first_changed_key(const std::string& before, const std::string& after);

}  // namespace camouflet
