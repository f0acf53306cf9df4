#pragma once
// Checkpoint files (HDF5, docs/reliability.md): one 2-D dataset [count, width]
// per state array, named as visited ("solver.nodes.position"), and two root
// attributes, `format_version` and `checksum` (CheckpointData::checksum).
// Written atomically: a temporary file, fsync, rename, fsync of the folder,
// so a kill at any moment leaves the previous checkpoint intact.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "checkpoint/checkpoint_data.hpp"

namespace camouflet {

inline constexpr int checkpoint_format_version = 1;

// Throws std::filesystem::filesystem_error (I/O failure) naming the path.
void write_checkpoint(const std::filesystem::path& path, const CheckpointData& data);

// Throws CheckpointError naming the file and the reason (unreadable,
// version, checksum).
CheckpointData read_checkpoint(const std::filesystem::path& path);

// The checkpoints of one run: <dir>/checkpoint_<cycle>.h5, the last `keep` kept.
class CheckpointSeries {
 public:
  CheckpointSeries(std::filesystem::path dir, int keep) : dir_(std::move(dir)), keep_(keep) {}
  // Writes the checkpoint of `cycle` and removes the oldest beyond `keep`.
  std::filesystem::path write(std::int64_t cycle, const CheckpointData& data) const;
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  int keep_;
};

// Checkpoint files in `dir`, newest (highest cycle) first; temporary files are ignored.
std::vector<std::filesystem::path> list_checkpoints(const std::filesystem::path& dir);

}  // namespace camouflet
