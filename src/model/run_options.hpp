#pragma once
// How a run is asked for: where it writes, how it reports progress, how many
// threads and which checkpoint it restarts from. A plain record, below the
// solver and the output layer that both read it.
#include <filesystem>
#include <string>

namespace camouflet {

enum class ProgressStyle { automatic, terminal, plain, none };

struct RunOptions {
  std::filesystem::path output_dir;  // created if missing; empty = write nothing (tests)
  ProgressStyle progress = ProgressStyle::automatic;
  int threads = 0;  // 0 = OpenMP default
  // Checkpoints (docs/reliability.md). `restart`: a checkpoint file,
  // or "latest" for the newest usable one in <output_dir>/checkpoints.
  std::string restart;
  // "key = value" lines of every case setting a restart must not change
  // (case/case_fingerprint.hpp); compared with the checkpoint's on restart.
  std::string case_fingerprint;
};

}  // namespace camouflet
