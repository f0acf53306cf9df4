#pragma once
// Detaching a group of FEM parts from the rest of the mesh, so that a slide surface can carry the
// contact between them (coupling/slide_surface.hpp). Blocks and Gmsh volumes that touch share
// their nodes (a fused interface); here every node used by an element of the group and by an
// element outside it gets a copy, which the outside elements take. The group keeps the original
// nodes, so node numbers and the group's connectivity do not change; the copies are appended.
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace camouflet {

// A face of the mesh as its element and the element's local face (quad edges counter-clockwise
// {0,1}, {1,2}, {2,3}, {3,0}; hex faces as their outward normal turns, the tables of
// element_face_nodes): valid while the mesh's connectivity changes by node renumbering.
struct ElementFace {
  std::int64_t element = 0;  // 0-based
  int face = 0;
};

// The nodes of element faces, 2 (2-D) or 4 (3-D) each, in their outward order.
std::vector<std::int64_t> element_face_nodes(const FemMesh& mesh, const std::vector<ElementFace>& faces);

struct DetachedInterface {
  // The faces the group shared with the rest, once from side A (the group's elements, original
  // nodes) and once from side B (the elements outside, their copied nodes), pair by pair.
  std::vector<ElementFace> a, b;
  std::size_t doubled_nodes = 0;
};

// in_group: per part of the mesh (Model::parts), 1 for the parts of side A. Node sets that hold a
// doubled node hold both its copies afterwards (a symmetry plane or an axis acts on both sides);
// a face of a face set moves to the copies when the element it bounds is outside the group.
// Returns an empty interface (and changes nothing) when the group shares no node with the rest.
DetachedInterface detach_parts(FemMesh& mesh, const std::vector<char>& in_group);

}  // namespace camouflet
