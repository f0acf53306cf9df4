#pragma once
// Symmetry planes, rigid walls and the axis of revolution for particles, by
// mirror (ghost) particles (Libersky, Petschek et al. 1993, JCP 109, section
// 4; Randles & Libersky 1996, CMAME 139, section 5).
//
// Every particle closer to an axis-aligned plane than the largest interaction
// radius gets a ghost: its mirror image, with the same mass, density,
// smoothing length, sound speed and mirrored stress (the components with one
// index normal to the plane change sign). The ghost velocity is
//   symmetry plane (free slip): normal component reversed, tangential kept;
//   rigid wall (no slip):       whole velocity reversed.
// so the plane sees zero normal velocity and no mass flux, and a particle near
// it has a full kernel support. Planes are processed in turn and ghosts are
// themselves mirrored by later planes, which fills corners.
//
// The axis r = 0 of an axisymmetric model is a symmetry plane x = 0
// (PlaneKind::axis): the reflected-particle treatment of Petschek & Libersky
// 1993 (JCP 109, 76, "Cylindrical smoothed particle hydrodynamics") and of
// Garcia-Senz et al. 2009 (MNRAS 392, 346), section 2.3. Its images stand at
// r < 0, where the ring weight 2 pi r is negative: in the volume form they
// carry their stress terms negated (SphSystem::refresh_ghosts, SphFemJoin::fill;
// docs/theory/sph.md, "The first columns next to the axis").
#include <cstdint>
#include <vector>

#include "core/sym_tensor.hpp"
#include "core/vec.hpp"
#include "model/model.hpp"

namespace camouflet::sph {

enum class PlaneKind { symmetry, wall, axis };  // axis: a symmetry plane at r = 0 (r-z)

struct MirrorPlane {
  int axis = 0;           // normal direction: 0 = x (r), 1 = y (z), 2 = z
  double position = 0.0;  // m, plane x_axis = position
  PlaneKind kind = PlaneKind::symmetry;
};

// One ghost: the point it mirrors (a particle or an earlier ghost, index into
// the combined real + ghost arrays) and the plane.
struct Ghost {
  std::uint32_t source = 0;
  std::uint32_t plane = 0;
};

template <int D>
inline Vec<D> mirror_position(const Vec<D>& x, const MirrorPlane& p) {
  Vec<D> g = x;
  g[p.axis] = 2.0 * p.position - x[p.axis];
  return g;
}

template <int D>
inline Vec<D> mirror_velocity(const Vec<D>& v, const MirrorPlane& p) {
  Vec<D> g = v;
  if (p.kind == PlaneKind::wall) return v * -1.0;
  g[p.axis] = -v[p.axis];
  return g;
}

// Reflection R s R with R = I - 2 n n, n the plane normal.
inline SymTensor mirror_tensor(SymTensor s, int axis) {
  if (axis == 0) s.xy = -s.xy, s.zx = -s.zx;
  if (axis == 1) s.xy = -s.xy, s.yz = -s.yz;
  if (axis == 2) s.yz = -s.yz, s.zx = -s.zx;
  return s;
}

// The particles' side of the model's symmetry boundaries: each symmetry condition whose normal
// is a coordinate axis and whose node set lies on one plane constrains its nodes
// (boundary_conditions.hpp) and mirrors the particles in that plane. Each plane once, however
// many sets it is split into. The axis of an r-z model is not among them.
std::vector<MirrorPlane> symmetry_mirror_planes(const Model& model);

// The planes of the geometry alone: the axis r = 0 of an r-z model (PlaneKind::axis), none
// otherwise.
std::vector<MirrorPlane> axis_mirror_planes(GeometryMode mode);

// Every plane the model's boundaries mirror particles in, in the order their images are made:
// axis_mirror_planes first, then symmetry_mirror_planes (boundaries.hpp).
std::vector<MirrorPlane> particle_mirror_planes(const Model& model);

// Ghost list for points x (the first n_real are particles): every point whose
// distance to a plane is below `reach` (m) is mirrored, planes in order.
// The ghost positions are appended to x.
template <int D>
std::vector<Ghost> make_ghosts(std::vector<Vec<D>>& x, std::size_t n_real,
                               const std::vector<MirrorPlane>& planes, double reach);

}  // namespace camouflet::sph
