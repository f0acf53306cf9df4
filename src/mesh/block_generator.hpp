#pragma once
// Built-in structured block mesher (parts: a FEM mesh from a built-in
// structured/graded block generator). Blocks are appended to one FemMesh;
// coincident nodes are shared, so a model is assembled from adjacent blocks.
#include <array>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace camouflet {

struct BlockSpec {
  std::string name;                        // part name, prefixes the node/face set names
  int part = 0;                            // index into Model::parts
  std::array<double, 3> origin{};          // m, min corner
  std::array<double, 3> size{};            // m
  std::array<int, 3> cells{1, 1, 1};       // cells per direction (3rd ignored in 2-D)
  std::array<double, 3> grading{1, 1, 1};  // ratio last/first cell size along each direction (1 = uniform)
};

// Appends a block of quad4 (mesh.dimension 2) or hex8 (3) elements; nodes that coincide
// (within 1e-9 of the block size) with existing mesh nodes are shared, so adjacent blocks join.
// Adds node sets and face sets "<name>.xmin", ".xmax", ".ymin", ".ymax" (and ".zmin", ".zmax" in 3-D),
// faces ordered so their outward normal points out of the block. Element nodes counter-clockwise in 2-D,
// hex8 in the usual order (bottom face counter-clockwise seen from above, then top).
void add_block(FemMesh& mesh, const BlockSpec& spec);

// Node coordinates along one direction of a graded block: n + 1 values from
// `origin` to `origin + length`, cell sizes in geometric progression with
// last/first = grading.
std::vector<double> graded_coordinates(double origin, double length, int cells, double grading);

}  // namespace camouflet
