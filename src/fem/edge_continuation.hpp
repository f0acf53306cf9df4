#pragma once
// The continuations of the elements' edges into their neighbours, for the edge
// viscosity's limiter (edge_viscosity.hpp, edge_limiter): for edge k = (p, q)
// of element e, the node l beyond p (so that l -> p -> q runs along one mesh
// line) and the node r beyond q. On a structured quad or hex mesh a node's
// edges pair off into lines: the continuation of (q, p) at p is the edge (p, n)
// whose n shares no element with both p and q. Where a node is irregular (a
// block junction) and several candidates remain, the one best aligned with
// q -> p at set-up wins if it lies within 60 degrees of it; otherwise, and at a
// boundary, there is none (-1). Depends on the mesh and the set-up positions
// only, so a restart finds the same continuations.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace camouflet {

// Element e, edge k: [(e * edges + k) * 2] the node beyond the edge's first node, [+1] beyond its
// second; -1 for none. connectivity: e * nodes + a; x: node positions, node * D + i.
template <int D>
std::vector<std::int64_t> edge_continuations(const std::vector<std::int64_t>& connectivity, std::size_t node_count,
                                             const double* x);

}  // namespace camouflet
