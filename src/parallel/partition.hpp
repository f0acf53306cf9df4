#pragma once
// Elements to ranks (docs/parallel.md): METIS's multilevel k-way partition of the element graph
// (Karypis and Kumar 1998), two elements joined when they share a face (an edge of a quad, a face
// of a hex), each weighted by its cost, each part contiguous. Done once, at start-up, on one rank:
// for 10^7 hexes the face list the graph is built from takes about 2.4 GB (6 faces of 40 bytes
// each, sorted once) and the graph METIS works on about 0.5 GB, which one node holds; beyond that
// ParMETIS would be needed, which Debian does not ship in its free set. (Estimates from the data
// sizes, not measured.)
#include <cstdint>
#include <span>
#include <vector>

#include "model/model.hpp"

namespace camouflet {

// The part of each element, 0 .. parts - 1. weights: one per element (a whole number >= 1: its
// cost relative to the cheapest), or empty for all equal. METIS's seed is fixed, so the same mesh
// gives the same partition on every run and every machine with the same METIS.
std::vector<int> partition_elements(const FemMesh& mesh, int parts, std::span<const int> weights = {});

// What a partition costs a run: the heaviest part over the mean (1 = perfect balance), the faces
// cut between parts, and how many parts fall apart into more than one piece.
struct PartitionQuality {
  double imbalance = 1.0;
  std::int64_t cut_faces = 0;
  int split_parts = 0;
};
PartitionQuality measure_partition(const FemMesh& mesh, std::span<const int> part, int parts,
                                   std::span<const int> weights = {});

// The element graph: for element e its face neighbours are neighbours[offsets[e] .. offsets[e+1]).
struct ElementGraph {
  std::vector<std::int64_t> offsets, neighbours;
};
ElementGraph element_face_graph(const FemMesh& mesh);

}  // namespace camouflet
