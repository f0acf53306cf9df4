#pragma once
// Element colouring for race-free, deterministic force assembly: no two
// elements of one colour share a node, so a colour's elements scatter their
// forces in parallel without atomics, and the summation order at every node
// is fixed by the colour order whatever the thread count.
#include <cstdint>
#include <vector>

namespace camouflet {

// Greedy colouring; returns the element indices of each colour, ascending.
std::vector<std::vector<std::int64_t>> colour_elements(const std::vector<std::int64_t>& connectivity,
                                                       int nodes_per_element, std::size_t node_count);

}  // namespace camouflet
