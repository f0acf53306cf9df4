#pragma once
// The part of the FEM mesh one rank owns (docs/parallel.md): its elements, the nodes they use,
// the node and face sets cut to them, and the pattern by which the ranks that share a node add
// up what each contributes to it (forces, lumped masses).
#include <cstdint>
#include <span>
#include <vector>

#include "model/model.hpp"
#include "parallel/communicator.hpp"

namespace camouflet {

struct LocalMesh {
  FemMesh mesh;                              // this rank's elements and nodes, numbered locally
  std::vector<std::int64_t> global_node;     // local node -> node of the whole mesh (ascending)
  std::vector<std::int64_t> global_element;  // local element -> element of the whole mesh (ascending)
  // Each other rank that shares nodes with this one (ascending rank), with the local nodes they
  // share in ascending global id: the order both sides send and receive in.
  struct Neighbour {
    int rank = 0;
    std::vector<std::int64_t> nodes;
    std::vector<std::int64_t> slots;  // each node's index in shared_nodes
  };
  std::vector<Neighbour> neighbours;
  // Every local node another rank holds too, ascending: what sum_shared_nodes touches (its work and
  // memory go with the cut, not with the mesh).
  std::vector<std::int64_t> shared_nodes;
  // Whether this rank owns each local node: the lowest rank holding it owns it, and only the owner
  // counts it in a global sum (kinetic energy, output), so no shared node is counted twice.
  std::vector<char> owned;
};

// Rank `rank`'s part of `global` under the partition `part` (one rank per element, 0-based).
// Node sets keep their local nodes; a face set keeps the faces of this rank's elements.
// `extra_nodes[r]` (when given, one list per rank) are nodes of the whole mesh rank r holds beside
// those of its elements (the host nodes its embedded bars reach): they are shared like any other,
// and rank r steps them from the forces and masses the other holders add up.
LocalMesh local_mesh(const FemMesh& global, std::span<const int> part, int rank,
                     std::span<const std::vector<std::int64_t>> extra_nodes = {});

// Adds up, over the ranks that hold each shared node, the `components` values per node in
// `values` (local nodes * components), in ascending rank order, so that every rank holding the
// node ends with the same bits. Nodes no other rank holds are left as they are.
void sum_shared_nodes(const Communicator& comm, const LocalMesh& local, std::span<double> values,
                      int components);

}  // namespace camouflet
