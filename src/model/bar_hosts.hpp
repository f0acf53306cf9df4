#pragma once
// Where the embedded bars' nodes sit in the mesh at t = 0 (model/reinforcement.hpp: a BarSet is a
// straight line of `segments` truss segments, segments + 1 bar nodes). Every bar node of every set,
// in set order, is located in one host element of the set's host part; it moves with that
// element's nodes by their shape functions (fem/embedded_bars.hpp).
//
// Located once on the whole model: a run across ranks (parallel/rank_part.hpp) locates every bar
// node before the mesh is cut, so that each rank knows which rank's elements host which bar node,
// and which nodes of other ranks its segments reach.
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace camouflet {

struct BarHosts {
  int host_nodes = 0;                 // nodes per host element: 4 (quad4) or 8 (hex8)
  std::vector<std::int64_t> element;  // per bar node: its host element (0-based, the mesh's)
  std::vector<std::int64_t> node;     // bar node b, host node a at b * host_nodes + a (the mesh's)
  std::vector<double> weight;         // the shape function of node a at the bar node, same layout
  std::vector<double> position;       // m, bar node b at b * 3 + i, interpolated from x0 (3-D layout)
  std::size_t node_count() const { return element.size(); }
};

// Locates every bar node of `model.bars` in `model.mesh` with coordinates x0 (node-major, the
// mesh's dimension). Throws InputError naming the bar set and its key for a set with no segment,
// no positive area, no material, a hoop bar outside axisymmetric geometry, zero length or a node
// outside its host part.
BarHosts locate_bar_nodes(const Model& model, const std::vector<double>& x0);

// One rank's share of the bars in a run across ranks: every bar node located in the whole mesh, and
// per bar node whether this rank's elements host it. The rank counts the mass of the bar nodes it
// hosts and steps the segments whose first node it hosts; it holds the nodes of their second
// node's host element too (parallel/rank_part.hpp), so that each segment is stepped by one rank.
struct BarShare {
  BarHosts hosts;
  std::vector<char> hosted_here;
};

}  // namespace camouflet
