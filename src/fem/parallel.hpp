#pragma once
// Loops shorter than this run on one thread: below it the cost of waking a
// team (worse on a loaded machine) exceeds the work.
#include <cstdint>

namespace camouflet {
inline constexpr std::int64_t parallel_threshold = 2048;
}  // namespace camouflet
