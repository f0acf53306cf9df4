#pragma once
// Element colouring for race-free force assembly on threads (issue 10): the
// elements are split into colours such that no two elements of one colour
// share a node, so the elements of a colour can scatter their nodal forces
// straight into the global force array from any number of threads at once.
// Each node then receives at most one element's contribution per colour, and
// in colour order, so its force sum does not depend on the thread count.
// Computed once at set-up (the connectivity never changes; an eroded element
// keeps its colour and scatters nothing). docs/performance.md, "Session 6".
#include <cstddef>
#include <cstdint>
#include <vector>

namespace camouflet {

struct ElementColouring {
  // Element indices (0-based), colour by colour, ascending within a colour.
  std::vector<std::uint32_t> elements;
  // colours() + 1 offsets: colour c holds elements[begin[c] .. begin[c + 1]).
  std::vector<std::size_t> begin{0};

  std::size_t colours() const { return begin.size() - 1; }
};

// Greedy colouring in element order: each element takes the smallest colour
// that no element sharing one of its nodes has taken (a structured hex block
// needs 8 colours, a quad block 4). connectivity: nodes_per_element entries
// per element, node numbers in [0, node_count).
ElementColouring colour_elements(const std::vector<std::int64_t>& connectivity, int nodes_per_element,
                                 std::size_t node_count);

}  // namespace camouflet
