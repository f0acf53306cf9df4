#pragma once
// Element colouring for race-free force assembly on threads: the
// elements are split into colours such that no two elements of one colour
// share a node, so the elements of a colour can scatter their nodal forces
// straight into the global force array from any number of threads at once.
// Each node then receives its contributions colour by colour, and within a
// colour from one element (or one block, below) only, so its force sum does
// not depend on the thread count. Computed once at set-up (the connectivity
// never changes; an eroded element keeps its colour and scatters nothing).
//
// The coloured unit is a block of `block` consecutive elements (1: single
// elements). Two blocks of one colour share no node; the elements inside a
// block are scattered one after the other by one thread, so they may. Blocks
// keep the memory locality of the element order (consecutive elements share
// nodes) that single-element colours lose. docs/performance.md, "Colouring
// against per-thread buffers".
#include <cstddef>
#include <cstdint>
#include <vector>

namespace camouflet {

struct ElementColouring {
  std::size_t block = 1;  // elements per block: block b is elements [b block, min((b + 1) block, n))
  // Block indices (0-based), colour by colour, ascending within a colour.
  std::vector<std::uint32_t> blocks;
  // colours() + 1 offsets: colour c holds blocks[begin[c] .. begin[c + 1]).
  std::vector<std::size_t> begin{0};

  std::size_t colours() const { return begin.size() - 1; }
};

// Greedy colouring in block order: each block takes the smallest colour that
// no block sharing one of its nodes has taken (single elements of a
// structured hex block need 8 colours, of a quad block 4). connectivity:
// nodes_per_element entries per element, node numbers in [0, node_count).
ElementColouring colour_elements(const std::vector<std::int64_t>& connectivity, int nodes_per_element,
                                 std::size_t node_count, std::size_t block = 1);

}  // namespace camouflet
