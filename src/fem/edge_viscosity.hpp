#pragma once
// Edge artificial viscosity of one element (Caramana, Shashkov and Whalen 1998,
// J. Comput. Phys. 144, 70, "Formulations of artificial viscosity for
// multi-dimensional shock wave computations"): a viscous force on every edge
// of the element whose two nodes close on each other, along their velocity
// difference, over the median-mesh surface that separates the two nodes'
// corners of the element. A scalar q acts on the element as a whole: it
// cannot tell a compression along one edge from an expansion along the next,
// and the one-point element's stress cannot resist the corner motions that
// tangle a square mesh around a point blast (docs/theory-fem.md, "Edge
// viscosity"). Per edge k from node p to node p':
//   du = v_p' - v_p, dx = x_p' - x_p; only where du . dx < 0 (closing),
//   F_k = rho (c_q^2 |du| + c_l c) A_k du   on p, and -F_k on p',
// with A_k the median area: 2-D |c - m_k| (c the element centre, m_k the
// edge's midpoint; in r-z times 2 pi r at the segment's middle), 3-D
// |(c - m_k) x (f_2 - f_1)| / 2 (f the centres of the edge's two faces). In a
// plane shock along a mesh line the two edges across it carry A = l / 2 each,
// and their forces sum to the scalar q = rho (c_q^2 |du| + c_l c) |du| over
// the element's width l: the coefficients keep the meaning of [run.viscosity].
// The forces do the work F_k . du (>= 0 where they were set), heating the
// element. Without the limiter (CSW's psi = 0) a smooth compression is heated
// as by the volumetric scalar form, and a smooth shear flow too: in a flowing
// soil the linear term then acts as a shear viscosity of order rho c_l c l.
// With it (edge_limiter below, [run.viscosity] limiter) each edge's force is
// scaled by 1 - psi, psi from the velocity differences along the edge's
// continuations into the neighbouring elements: 1 in any linear velocity
// field (no force), 0 across a jump (the full force).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/element_pack.hpp"

namespace camouflet {

template <int D>
struct ElementEdges;

template <>
struct ElementEdges<2> {
  static constexpr int count = 4;
  static constexpr int nodes = 4;
  static constexpr int node[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
};

template <>
struct ElementEdges<3> {
  static constexpr int count = 12;
  static constexpr int nodes = 8;
  // Node order bottom face counter-clockwise, then top (shape.hpp).
  static constexpr int node[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                      {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  static constexpr int face[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                     {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  // The two faces that hold each edge.
  static constexpr int faces_of[12][2] = {{0, 2}, {0, 3}, {0, 4}, {0, 5}, {1, 2}, {1, 3},
                                          {1, 4}, {1, 5}, {2, 5}, {2, 3}, {3, 4}, {4, 5}};
};

// The median areas A_k (m^2; plane strain: m per metre of depth) of an element's edges at the
// node positions x[i][a]. T: double for one element or Pack for a pack of them (the same
// operations per lane, element_pack.hpp).
template <int D, class T>
inline void edge_median_areas(const T (&x)[D][ElementEdges<D>::nodes], bool axisymmetric,
                              T (&area)[ElementEdges<D>::count]) {
  using E = ElementEdges<D>;
  T centre[D] = {};
  for (int a = 0; a < E::nodes; ++a)
    for (int i = 0; i < D; ++i) centre[i] += x[i][a] / static_cast<double>(E::nodes);
  if constexpr (D == 2) {
    for (int k = 0; k < E::count; ++k) {
      const int p = E::node[k][0], q = E::node[k][1];
      const T mr = 0.5 * (x[0][p] + x[0][q]), mz = 0.5 * (x[1][p] + x[1][q]);
      const T length = hypot_of(centre[0] - mr, centre[1] - mz);
      // r-z: the segment sweeps a cone of radius r at its middle per radian.
      area[k] = axisymmetric ? length * std::numbers::pi * (centre[0] + mr) : length;
    }
  } else {
    T face_centre[6][3] = {};
    for (int f = 0; f < 6; ++f)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 3; ++i) face_centre[f][i] += 0.25 * x[i][E::face[f][j]];
    for (int k = 0; k < E::count; ++k) {
      const int p = E::node[k][0], q = E::node[k][1];
      const T* f1 = face_centre[E::faces_of[k][0]];
      const T* f2 = face_centre[E::faces_of[k][1]];
      T d1[3], d2[3];
      for (int i = 0; i < 3; ++i) {
        d1[i] = centre[i] - 0.5 * (x[i][p] + x[i][q]);
        d2[i] = f2[i] - f1[i];
      }
      const T cx = d1[1] * d2[2] - d1[2] * d2[1], cy = d1[2] * d2[0] - d1[0] * d2[2],
              cz = d1[0] * d2[1] - d1[1] * d2[0];
      area[k] = 0.5 * sqrt_of(cx * cx + cy * cy + cz * cz);
    }
  }
}

// The limiter psi of CSW 1998 (section 5, in its edge form) for an edge with velocity
// difference du and extent dx, and its continuations
// beyond its first node (du_l = v_p - v_l, dx_l = x_p - x_l: the edge from the node l beyond p)
// and beyond its second (du_r = v_r - v_q, dx_r = x_r - x_q); nullptr where the edge has no
// continuation (a boundary, an irregular node), and then the other side's ratio stands for both.
// The ratios compare the velocity gradients along the three edges,
//   r_l = (du_l . du) |dx| / (|du|^2 |dx_l|),  and r_r alike,
//   psi = max(0, min((r_l + r_r) / 2, 2 r_l, 2 r_r, 1)):
// 1 where the gradient is the same on both sides (a linear field: no viscosity), 0 where it
// changes sign or the edge stands alone (the full force).
template <int D>
inline double edge_limiter(const double* du, const double* dx, const double* du_l, const double* dx_l,
                           const double* du_r, const double* dx_r) {
  double du2 = 0.0, dx2 = 0.0;
  for (int i = 0; i < D; ++i) du2 += du[i] * du[i], dx2 += dx[i] * dx[i];
  if (du2 == 0.0 || (du_l == nullptr && du_r == nullptr)) return 0.0;
  const auto ratio = [&](const double* du_s, const double* dx_s) {
    double dot = 0.0, ds2 = 0.0;
    for (int i = 0; i < D; ++i) dot += du_s[i] * du[i], ds2 += dx_s[i] * dx_s[i];
    return ds2 > 0.0 ? dot * std::sqrt(dx2 / ds2) / du2 : 0.0;
  };
  const double r_l = du_l != nullptr ? ratio(du_l, dx_l) : ratio(du_r, dx_r);
  const double r_r = du_r != nullptr ? ratio(du_r, dx_r) : r_l;
  return std::max(0.0, std::min({0.5 * (r_l + r_r), 2.0 * r_l, 2.0 * r_r, 1.0}));
}

// The edge forces F (count * D: F_k on the edge's first node, -F_k on its second) of an element
// at positions x with node velocities v, density rho (kg/m^3) and sound speed c (m/s); psi: the
// limiter of each edge (edge_limiter), nullptr for none. T: double or Pack, as edge_median_areas.
template <int D, class T>
inline void edge_viscous_forces(const T (&x)[D][ElementEdges<D>::nodes],
                                const T (&v)[D][ElementEdges<D>::nodes], bool axisymmetric, T rho, T c,
                                double c_quadratic, double c_linear, T* force, const T* psi = nullptr) {
  using E = ElementEdges<D>;
  T area[E::count];
  edge_median_areas<D>(x, axisymmetric, area);
  const double cq2 = c_quadratic * c_quadratic;
  for (int k = 0; k < E::count; ++k) {
    const int p = E::node[k][0], q = E::node[k][1];
    T du[D], closing{}, du2{};
    for (int i = 0; i < D; ++i) {
      du[i] = v[i][q] - v[i][p];
      closing += du[i] * (x[i][q] - x[i][p]);
      du2 += du[i] * du[i];
    }
    const T kept = psi != nullptr ? 1.0 - psi[k] : T{} + 1.0;
    const T coefficient = closing < 0.0 ? kept * rho * (cq2 * sqrt_of(du2) + c_linear * c) * area[k] : T{};
    for (int i = 0; i < D; ++i) force[k * D + i] = coefficient * du[i];
  }
}

// The power (W) the edge forces F take from the element's nodes moving at v: sum_k F_k . du_k.
template <int D>
inline double edge_viscous_power(const double* force, const double (&v)[D][ElementEdges<D>::nodes]) {
  using E = ElementEdges<D>;
  double power = 0.0;
  for (int k = 0; k < E::count; ++k) {
    const int p = E::node[k][0], q = E::node[k][1];
    for (int i = 0; i < D; ++i) power += force[k * D + i] * (v[i][q] - v[i][p]);
  }
  return power;
}

}  // namespace camouflet
