#pragma once
// Reads a part of a FEM mesh from a Gmsh .msh file through the Gmsh library
// for the parts of a case file. The elements of one named
// physical group become a part: 4-node quadrilaterals in 2-D, 8-node
// hexahedra in 3-D (any other element type in the group is refused). Physical
// groups one dimension lower (lines in 2-D, surfaces in 3-D) become node sets
// and face sets under their own names; physical groups of points become node
// sets. Nodes coinciding exactly with nodes already in the mesh are shared, so
// several parts read from one file join where the file joins them.
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "mesh/simplex_region.hpp"
#include "model/model.hpp"

namespace camouflet {

struct GmshPartRequest {
  std::filesystem::path file;     // .msh (any format version Gmsh reads)
  std::string physical;           // name of the physical group to take as the part
  int part = 0;                   // index into Model::parts
  SourceLocation file_where;      // the `gmsh` key, for errors about the file
  SourceLocation physical_where;  // the `physical` key, for errors about the group
};

// Appends the part's nodes, elements and the file's boundary sets to `mesh`
// (mesh.dimension decides quads or hexes). Elements are reordered where the
// file has them clockwise (2-D) or left-handed (3-D), and faces are oriented
// with their normal pointing out of the element they bound. Throws InputError.
void import_gmsh_part(FemMesh& mesh, const GmshPartRequest& request);

}  // namespace camouflet

namespace camouflet {

// The region covered by the elements of one physical group of dimension
// `dimension` (a surface in 2-D, a volume in 3-D), cut into simplices, for
// filling an SPH part with particles (mesh/particle_fill.hpp). Linear element
// types only: triangles and quadrilaterals (2-D); tetrahedra, hexahedra,
// prisms and pyramids (3-D); quadrilateral and hexahedron faces are assumed
// planar (cut along a diagonal). Throws InputError naming the keys.
SimplexRegion import_gmsh_region(int dimension, const std::filesystem::path& file,
                                 const std::string& physical, const SourceLocation& file_where,
                                 const SourceLocation& physical_where);

}  // namespace camouflet
