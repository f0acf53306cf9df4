#pragma once
// Restarts of the history CSVs that live outside the checkpoint (rebar strains,
// energy history): the file the interrupted run left is cut back to
// the rows written before the restart time, so that the continued run, which
// re-evaluates its output schedule from the last kept row, writes exactly the
// rows of an uninterrupted run (rows are written with 17 digits, so the times
// read back are the times written).
#include <filesystem>
#include <optional>

namespace camouflet {

// Keeps the header and the complete rows with time < `restart_time` (an
// incomplete last line, from a kill, is dropped), rewritten atomically.
// Returns the time of the last kept row (-infinity when none), or nothing when
// the file is missing or has no complete header (the caller starts it anew).
std::optional<double> cut_history_before(const std::filesystem::path& path, double restart_time);

}  // namespace camouflet
