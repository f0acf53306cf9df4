// Interface faces of the SPH-FEM join at its corners.
//
// A coupling point sends the reactions of its pairs to the interface face
// nearest to it. Along a straight interface that is right: the particles
// around the point lie on one side, their pair forces sum to the traction
// sigma . n of the face. Within a kernel reach of a corner of the interface
// (the bottom outer corner of the buried-structure case's SPH zone, where a
// bottom face meets a side face) it is not: a point under the bottom face
// next to the corner has particles above and on its inner side but none on
// its outer side (there lie the coupling points of the side band, which take
// part in the particle sums but exchange no forces with the point), so its
// pairs' reactions hold a share of the particles' sigma_rr that belongs to the
// side face. Put on the bottom face, it drove the bottom face's last nodes
// outwards and the side face's lowest node down (0.7 m by 10 ms against
// 0.1 m for the particles beside them in the cut-down case), until elements
// there tangled (docs/theory/coupling.md).
//
// So within reach of faces of another orientation, a point's reaction R is
// split along the faces' normals, R = sum_g c_g n_g (a D x D solve; in 3-D
// with two orientations the part along their common edge is shared equally),
// and each part goes to the face of its orientation nearest to the point's
// own face: the part normal to the side face onto the side face. For a uniform
// stress this sends sigma_rr across the side face and sigma_zz across the
// bottom face, the tractions each face carries; elsewhere nothing changes.
#include <algorithm>
#include <cmath>

#include "coupling/sph_fem_join.hpp"

namespace camouflet {
namespace {

// Solves A c = b for a D x D matrix given by its columns (Gaussian elimination with partial
// pivoting). False when A is (nearly) singular: faces (nearly) parallel.
template <int D>
bool solve_columns(const std::array<Vec<D>, D>& columns, const Vec<D>& b, std::array<double, D>& c) {
  double a[D][D + 1];
  for (int r = 0; r < D; ++r) {
    for (int k = 0; k < D; ++k) a[r][k] = columns[static_cast<std::size_t>(k)][r];
    a[r][D] = b[r];
  }
  for (int k = 0; k < D; ++k) {
    int pivot = k;
    for (int r = k + 1; r < D; ++r)
      if (std::abs(a[r][k]) > std::abs(a[pivot][k])) pivot = r;
    if (std::abs(a[pivot][k]) < 0.2) return false;  // unit columns: |det| small
    if (pivot != k)
      for (int m = 0; m <= D; ++m) std::swap(a[k][m], a[pivot][m]);
    for (int r = k + 1; r < D; ++r) {
      const double factor = a[r][k] / a[k][k];
      for (int m = k; m <= D; ++m) a[r][m] -= factor * a[k][m];
    }
  }
  for (int k = D - 1; k >= 0; --k) {
    double sum = a[k][D];
    for (int m = k + 1; m < D; ++m) sum -= a[k][m] * c[static_cast<std::size_t>(m)];
    c[static_cast<std::size_t>(k)] = sum / a[k][k];
  }
  return true;
}

template <int D>
Vec<D> unit(Vec<D> v) {
  const double length = std::sqrt(dot(v, v));
  return length > 0.0 ? v * (1.0 / length) : v;
}

}  // namespace

template <int D>
void SphFemJoin<D>::update_face_geometry(const double* xn) {
  face_centre_.assign(faces_.size(), Vec<D>{});
  face_normal_.assign(faces_.size(), Vec<D>{});
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& q = faces_[f];
    Vec<D> x[face_nodes];
    for (int a = 0; a < face_nodes; ++a)
      for (int d = 0; d < D; ++d) x[a][d] = xn[q[static_cast<std::size_t>(a)] * D + d];
    Vec<D> centre{};
    for (int a = 0; a < face_nodes; ++a) centre = centre + x[a] * (1.0 / face_nodes);
    Vec<D> n{};
    if constexpr (D == 2) {
      n[0] = x[1][1] - x[0][1];
      n[1] = x[0][0] - x[1][0];
    } else {  // the cross product of the diagonals
      const Vec<D> p = x[2] - x[0], r = x[3] - x[1];
      n[0] = p[1] * r[2] - p[2] * r[1];
      n[1] = p[2] * r[0] - p[0] * r[2];
      n[2] = p[0] * r[1] - p[1] * r[0];
    }
    // Oriented out of its element, towards the particles.
    if (dot(n, centre - element_centre(static_cast<std::size_t>(face_element_[f]), xn)) < 0.0) n = n * -1.0;
    face_centre_[f] = centre;
    face_normal_[f] = unit(n);
  }
}

template <int D>
void SphFemJoin<D>::find_corner_faces(const double* x) {
  // Faces within reach of a point whose normal differs from its own face's by more than ~25
  // degrees, grouped by orientation (at most D groups, the point's face's first).
  corner_faces_.clear();
  corner_group_.clear();
  for (Point& pt : points_) {
    const Vec<D> c = interpolate(x, pt);
    std::vector<Vec<D>> groups{face_normal_[pt.face]};
    const std::size_t first = corner_faces_.size();
    corner_faces_.push_back(pt.face);
    corner_group_.push_back(0);
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      const Vec<D> d = face_centre_[f] - c;
      if (f == pt.face || dot(d, d) >= reach_ * reach_) continue;
      std::size_t g = 0;
      while (g < groups.size() && dot(groups[g], face_normal_[f]) < 0.9) ++g;
      if (g == groups.size()) {
        if (groups.size() == static_cast<std::size_t>(D)) continue;
        groups.push_back(face_normal_[f]);
      }
      corner_faces_.push_back(f);
      corner_group_.push_back(static_cast<std::uint8_t>(g));
    }
    if (groups.size() == 1) corner_faces_.resize(first), corner_group_.resize(first);
    pt.corner_begin = static_cast<std::uint32_t>(first);
    pt.corner_end = static_cast<std::uint32_t>(corner_faces_.size());
  }
}

template <int D>
typename SphFemJoin<D>::ReactionParts SphFemJoin<D>::split_reaction(const Point& point,
                                                                    const Vec<D>& reaction) const {
  ReactionParts parts;
  parts.count = 1;
  parts.force[0] = reaction;
  parts.face[0] = point.face;
  if (point.corner_begin == point.corner_end) return parts;
  // The face of each orientation group nearest to the point's face (its own face for its group).
  // (Taking the face nearest to each pair's middle instead spreads a point's reaction along its
  // own face, unlike the points just outside a corner's reach: the node at that edge of the reach
  // was overloaded and ran down, 0.35 m against 0.09 m for the particles beside it.)
  const Vec<D>& where = face_centre_[point.face];
  std::array<std::size_t, D> nearest{};
  std::array<double, D> distance;
  distance.fill(1e300);
  int groups = 0;
  for (std::uint32_t k = point.corner_begin; k < point.corner_end; ++k) {
    const std::size_t f = corner_faces_[k];
    const int g = corner_group_[k];
    const Vec<D> d = face_centre_[f] - where;
    if (dot(d, d) < distance[static_cast<std::size_t>(g)])
      distance[static_cast<std::size_t>(g)] = dot(d, d), nearest[static_cast<std::size_t>(g)] = f;
    groups = std::max(groups, g + 1);
  }
  std::array<Vec<D>, D> columns{};
  for (int g = 0; g < groups; ++g)
    columns[static_cast<std::size_t>(g)] = face_normal_[nearest[static_cast<std::size_t>(g)]];
  if constexpr (D == 3) {
    if (groups == 2) {  // the edge direction completes the basis; its part is shared
      const Vec<D>& a = columns[0];
      const Vec<D>& b = columns[1];
      columns[2] =
          unit(Vec<D>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]});
    }
  }
  std::array<double, D> c{};
  if (!solve_columns<D>(columns, reaction, c)) return parts;  // faces nearly parallel: the point's face
  parts.count = groups;
  for (int g = 0; g < groups; ++g) {
    parts.force[static_cast<std::size_t>(g)] =
        columns[static_cast<std::size_t>(g)] * c[static_cast<std::size_t>(g)];
    parts.face[static_cast<std::size_t>(g)] = nearest[static_cast<std::size_t>(g)];
  }
  if (D == 3 && groups == 2)
    for (int g = 0; g < 2; ++g)
      parts.force[static_cast<std::size_t>(g)] =
          parts.force[static_cast<std::size_t>(g)] +
          columns[static_cast<std::size_t>(D - 1)] * (0.5 * c[static_cast<std::size_t>(D - 1)]);
  return parts;
}

template void SphFemJoin<2>::update_face_geometry(const double*);
template void SphFemJoin<3>::update_face_geometry(const double*);
template void SphFemJoin<2>::find_corner_faces(const double*);
template void SphFemJoin<3>::find_corner_faces(const double*);
template SphFemJoin<2>::ReactionParts SphFemJoin<2>::split_reaction(const Point&, const Vec<2>&) const;
template SphFemJoin<3>::ReactionParts SphFemJoin<3>::split_reaction(const Point&, const Vec<3>&) const;

}  // namespace camouflet
