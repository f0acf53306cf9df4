#pragma once
// Loops shorter than these run on one thread: below them the cost of waking a
// team (much worse on a loaded machine) exceeds the work. Node loops do a few
// flops per item, element loops a few hundred.
#include <cstdint>

namespace camouflet {
inline constexpr std::int64_t parallel_threshold = 2048;         // elements
inline constexpr std::int64_t parallel_threshold_nodes = 32768;  // nodes (or node values)
}  // namespace camouflet
