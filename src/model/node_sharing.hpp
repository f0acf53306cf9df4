#pragma once
// A package's nodes when the mesh is cut among ranks (docs/parallel.md): what the package
// needs of the other ranks, here in `model` so that the FEM package can use it without knowing
// how the ranks talk (parallel/rank_part.hpp implements it over a Communicator).
//
// A node on the cut between ranks is held by every rank that has one of its elements; each
// holder assembles only its own elements' share of the node's force and mass, and the shares
// are added up over the holders so that every copy of the node moves alike. Only the node's
// owner counts it in a global sum (kinetic energy, the work of its constraints), so that no
// node is counted twice. Messages name nodes and elements by their ids in the whole mesh.
#include <cstdint>
#include <span>
#include <vector>

#include "model/bar_hosts.hpp"

namespace camouflet {

class NodeSharing {
 public:
  virtual ~NodeSharing() = default;
  // Adds up, over the ranks that hold each shared node, the `components` values per local node
  // in `values`, with the same bits on every holder. Every holder calls it at the same point.
  virtual void sum_shared(std::span<double> values, int components) const = 0;
  // Per local node: this rank counts it in global sums.
  virtual const std::vector<char>& owned_nodes() const = 0;
  // Local node / element (0-based) -> its index in the whole mesh, ascending.
  virtual const std::vector<std::int64_t>& global_nodes() const = 0;
  virtual const std::vector<std::int64_t>& global_elements() const = 0;
  // The embedded bars' share of this rank (model/bar_hosts.hpp); nullptr when the model has none.
  virtual const BarShare* bar_share() const { return nullptr; }
};

}  // namespace camouflet
