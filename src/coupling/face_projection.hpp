#pragma once
// A point's projection onto a contact face: shared by the particle-face contact
// (sliding_contact.cpp) and the FEM-FEM slide surface (slide_surface.cpp), and the closest point
// of a segment or triangle, which the slide surface measures its gaps to.
#include <array>
#include <cmath>

#include "core/vec.hpp"

namespace camouflet::contact_geometry {

// Projection of p onto the plane of triangle (a, b, c) along the unit normal n: barycentric
// weights w of the foot and the signed distance g along n. True when the foot lies inside the
// triangle, each weight at least -tolerance (a small tolerance keeps a point that projects
// onto the seam between two faces from slipping through it).
inline bool project_triangle(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c,
                             const Vec<3>& n, std::array<double, 3>& w, double& g, double tolerance = 0.0) {
  const Vec<3> ab = b - a, ac = c - a, ap = p - a;
  g = dot(ap, n);
  const Vec<3> q = ap - n * g;
  const double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac);
  const double d20 = dot(q, ab), d21 = dot(q, ac);
  const double det = d00 * d11 - d01 * d01;
  if (!(std::abs(det) > 0.0)) return false;
  const double wb = (d11 * d20 - d01 * d21) / det, wc = (d00 * d21 - d01 * d20) / det;
  w = {1.0 - wb - wc, wb, wc};
  return w[0] >= -tolerance && wb >= -tolerance && wc >= -tolerance;
}

// The unit normal of a quad face from its diagonals (outward for the face order of
// element_faces.hpp); false for a face collapsed to a line.
inline bool quad_normal(const Vec<3>& c0, const Vec<3>& c1, const Vec<3>& c2, const Vec<3>& c3, Vec<3>& n) {
  const Vec<3> d1 = c2 - c0, d2 = c3 - c1;
  n = Vec<3>{{d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]}};
  const double len = std::sqrt(dot(n, n));
  if (!(len > 0.0)) return false;
  n = n * (1.0 / len);
  return true;
}

// The closest point of segment (a, b) to p: the weight t of b (that of a is 1 - t), clamped to
// [0, 1].
template <int D>
inline double closest_on_segment(const Vec<D>& p, const Vec<D>& a, const Vec<D>& b) {
  const Vec<D> ab = b - a;
  const double length2 = dot(ab, ab);
  if (!(length2 > 0.0)) return 0.0;
  const double t = dot(p - a, ab) / length2;
  return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
}

// The closest point of triangle (a, b, c) to p, as barycentric weights w (each >= 0, summing to
// 1). True when it lies inside the triangle, false when on its boundary (the foot of the
// perpendicular falls outside, and the nearest of the three edges holds the closest point).
inline bool closest_on_triangle(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c,
                                std::array<double, 3>& w) {
  const Vec<3> ab = b - a, ac = c - a, ap = p - a;
  const double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac);
  const double det = d00 * d11 - d01 * d01;
  if (det > 0.0) {
    const double d20 = dot(ap, ab), d21 = dot(ap, ac);
    const double wb = (d11 * d20 - d01 * d21) / det, wc = (d00 * d21 - d01 * d20) / det;
    if (wb > 0.0 && wc > 0.0 && wb + wc < 1.0) {
      w = {1.0 - wb - wc, wb, wc};
      return true;
    }
  }
  const Vec<3>* corner[3] = {&a, &b, &c};
  double best = -1.0;
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = (e + 1) % 3;
    const double t = closest_on_segment<3>(p, *corner[i], *corner[j]);
    const Vec<3> q = *corner[i] + (*corner[j] - *corner[i]) * t;
    const double d2 = dot(p - q, p - q);
    if (best < 0.0 || d2 < best) {
      best = d2;
      w = {0.0, 0.0, 0.0};
      w[static_cast<std::size_t>(i)] = 1.0 - t;
      w[static_cast<std::size_t>(j)] = t;
    }
  }
  return false;
}

}  // namespace camouflet::contact_geometry
