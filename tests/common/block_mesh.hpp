#pragma once
// A structured block of quads (dimension 2) or hexes (3), `cells` along each axis over `size`
// metres from the origin: the meshes the partition and the rank tests cut.
#include <array>

#include "mesh/block_generator.hpp"

namespace camouflet::test {

inline FemMesh block_mesh(int dimension, std::array<double, 3> size, std::array<int, 3> cells) {
  FemMesh mesh;
  mesh.dimension = dimension;
  mesh.nodes_per_element = dimension == 3 ? 8 : 4;
  BlockSpec spec;
  spec.name = "b";
  spec.size = size;
  spec.cells = cells;
  add_block(mesh, spec);
  return mesh;
}

}  // namespace camouflet::test
