#pragma once
// Filling a region with SPH particles (particle parts of a case file).
//
// Every particle is the centre of a cell of a space-filling tiling, and its
// volume is that cell's volume, so the particle volumes of a box add up to the
// box volume exactly (other shapes: within the cells cut by the boundary,
// since a cell is kept when its centre lies inside the region).
//
// * uniform spacing s: a lattice aligned with the region's bounding box; for a
//   box the cell count per axis is round(L / s) and the spacing is adjusted to
//   L / count (reported back in ParticleSet::spacing, never silently).
// * graded spacing: square (2-D) / cubic (3-D) shells around the grading
//   point, shell k of width s_k = min(s0 ratio^k, s_max); each side strip of a
//   shell is cut into near-square cells of edge ~s_k. The grading point is a
//   lattice vertex, so on the axis of an axisymmetric model no cell straddles r = 0.
//
// Axisymmetric (r-z, r = x >= 0): the volume is the ring volume 2 pi r_c A of
// the cell (exact for a rectangle, r_c its centroid radius). Mass is set by the
// SPH set-up as reference density x volume. The initial smoothing length is
// smoothing_factor x spacing (sph/particles.hpp); spacing here is the cell
// edge (its area^(1/2) or volume^(1/3)).
#include <array>
#include <memory>
#include <vector>

#include "core/error.hpp"
#include "mesh/simplex_region.hpp"
#include "model/model.hpp"

namespace camouflet {

struct ParticleRegion {
  enum class Shape { box, sphere, cylinder, polygon, mesh };
  Shape shape = Shape::box;
  std::array<double, 3> min{}, max{};          // box corners, m
  std::array<double, 3> centre{};              // sphere (circle in 2-D) / cylinder base centre, m
  double radius = 0.0;                         // m
  std::array<double, 3> axis{0, 0, 1};         // cylinder axis (3-D), unit length not required
  double length = 0.0;                         // cylinder length along axis, m
  std::vector<std::array<double, 2>> polygon;  // 2-D vertices, either orientation
  std::shared_ptr<const SimplexRegion> mesh;   // Gmsh physical surface (2-D) / volume (3-D)

  bool contains(const double* x, int dimension) const;
  // Axis-aligned bounding box (lo, hi).
  std::pair<std::array<double, 3>, std::array<double, 3>> bounds(int dimension) const;
};

struct ParticleFillSpec {
  int part = 0;  // index into Model::parts
  ParticleRegion region;
  double spacing = 0.0;  // m; uniform spacing, or the smallest spacing when graded
  bool graded = false;
  std::array<double, 3> grading_point{};  // m, where the spacing is smallest
  double grading_ratio = 1.0;             // > 1: growth of the spacing from shell to shell
  double max_spacing = 0.0;               // m, upper bound of the graded spacing
  // Regions left out (another SPH part nested inside this one, e.g. the
  // charge in the soil zone): a cell whose centre lies in one is not filled.
  std::vector<ParticleRegion> exclude;
  SourceLocation where;  // the part's block, for messages
};

// Appends the particles of one region to `particles`. Throws InputError
// (naming spacing / grading keys, or the region when it holds no particle).
void fill_particles(ParticleSet& particles, const ParticleFillSpec& spec, GeometryMode mode);

}  // namespace camouflet
