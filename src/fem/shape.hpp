#pragma once
// Geometry of the one-point elements: uniform-gradient vectors b_a = dN_a/dx
// (Flanagan & Belytschko 1981, IJNME 17, 679), the element measure, the
// hourglass base vectors and the characteristic length for the time step.
// Shape<2> is the 4-node quadrilateral, Shape<3> the 8-node hexahedron.
// Coordinates come as x[i][a]: component i of node a; T is double for one
// element or a Pack of elements (element_pack.hpp), with the same arithmetic.
#include <utility>

#include "fem/element_pack.hpp"

namespace camouflet {

template <int D>
struct Shape;

template <>
struct Shape<2> {
  static constexpr int nodes = 4;
  static constexpr int modes = 1;
  // Hourglass base vector of the quadrilateral (FB 1981, eq. 47).
  static constexpr double base[1][4] = {{1.0, -1.0, 1.0, -1.0}};

  // b[i][a] = dN_a/dx_i at the centre, which for the bilinear quad equals the
  // area average (FB 1981, eq. 15); returns the area (m^2).
  template <class T>
  static T gradients(const T (&x)[2][4], T (&b)[2][4]) {
    const T x13 = x[0][2] - x[0][0], x24 = x[0][3] - x[0][1];
    const T y13 = x[1][2] - x[1][0], y24 = x[1][3] - x[1][1];
    const T area = 0.5 * (x13 * y24 - x24 * y13);
    const T s = 0.5 / area;
    b[0][0] = -y24 * s;
    b[0][1] = y13 * s;
    b[0][2] = y24 * s;
    b[0][3] = -y13 * s;
    b[1][0] = x24 * s;
    b[1][1] = -x13 * s;
    b[1][2] = -x24 * s;
    b[1][3] = x13 * s;
    return area;
  }

  // Area (m^2) alone.
  template <class T>
  static T measure(const T (&x)[2][4]) {
    return 0.5 * ((x[0][2] - x[0][0]) * (x[1][3] - x[1][1]) - (x[0][3] - x[0][1]) * (x[1][2] - x[1][0]));
  }

  // Area / longest side: the shortest crossing distance of the element.
  template <class T>
  static T length(const T (&x)[2][4], const T& area) {
    T longest{};
    for (int a = 0; a < 4; ++a) {
      const int c = (a + 1) % 4;
      const T dx = x[0][c] - x[0][a], dy = x[1][c] - x[1][a];
      longest = max_of(longest, dx * dx + dy * dy);
    }
    return area / sqrt_of(longest);
  }
};

template <>
struct Shape<3> {
  static constexpr int nodes = 8;
  static constexpr int modes = 4;
  // Hourglass base vectors of the hexahedron (FB 1981, Table 1), node order
  // bottom face counter-clockwise, then top.
  static constexpr double base[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                        {1, -1, -1, 1, -1, 1, 1, -1},
                                        {1, -1, 1, -1, 1, -1, 1, -1},
                                        {-1, 1, -1, 1, 1, -1, 1, -1}};

  // Node a's view of the element: the node order that maps node 0's formula onto node a.
  static constexpr int permutation[8][8] = {
      {0, 1, 2, 3, 4, 5, 6, 7}, {1, 2, 3, 0, 5, 6, 7, 4}, {2, 3, 0, 1, 6, 7, 4, 5}, {3, 0, 1, 2, 7, 4, 5, 6},
      {4, 7, 6, 5, 0, 3, 2, 1}, {5, 4, 7, 6, 1, 0, 3, 2}, {6, 5, 4, 7, 2, 1, 0, 3}, {7, 6, 5, 4, 3, 2, 1, 0}};

  // One row of FB 1981 eq. (79) without its 1/12: 12 dV/dx_a for node A from
  // the other two coordinate components (y, z) -> x, via node A's permutation.
  // A is a template argument so that every index folds to a constant. The
  // 1/12 is applied once, to the volume (gradients, measure), instead of 24
  // divisions per element.
  template <int A, class T>
  static T volume_derivative(const T* y, const T* z) {
    constexpr const int* p = permutation[A];
    const auto Y = [&](int k) { return y[p[k - 1]]; };
    const auto Z = [&](int k) { return z[p[k - 1]]; };
    return (Y(2) * ((Z(6) - Z(3)) - (Z(4) - Z(5))) + Y(3) * (Z(2) - Z(4)) +
            Y(4) * ((Z(3) - Z(8)) - (Z(5) - Z(2))) + Y(5) * ((Z(8) - Z(6)) - (Z(2) - Z(4))) +
            Y(6) * (Z(5) - Z(2)) + Y(8) * (Z(4) - Z(5)));
  }

  template <class T, std::size_t... A>
  static void volume_derivatives(const T (&x)[3][8], T (&b)[3][8], std::index_sequence<A...>) {
    ((b[0][A] = volume_derivative<A>(x[1], x[2]), b[1][A] = volume_derivative<A>(x[2], x[0]),
      b[2][A] = volume_derivative<A>(x[0], x[1])),
     ...);
  }

  template <class T, std::size_t... A>
  static T volume_only(const T (&x)[3][8], std::index_sequence<A...>) {
    return ((x[0][A] * volume_derivative<A>(x[1], x[2])) + ...);
  }

  // b[i][a] = (1/V) dV/dx_ia, the uniform-strain gradient vectors that make
  // the one-point hexahedron pass the patch test (FB 1981, eqs. 16, 79);
  // returns the exact trilinear volume (m^3).
  // b = (12 dV/dx) / (12 V): the 1/12 cancels.
  template <class T>
  static T gradients(const T (&x)[3][8], T (&b)[3][8]) {
    volume_derivatives(x, b, std::make_index_sequence<8>{});
    T volume12{};
    for (int a = 0; a < 8; ++a) volume12 += x[0][a] * b[0][a];
    const T s = 1.0 / volume12;
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 8; ++a) b[i][a] *= s;
    return volume12 / 12.0;
  }

  // Exact volume (m^3) alone: sum_a x_a dV/dx_a, a third of the work of gradients().
  template <class T>
  static T measure(const T (&x)[3][8]) {
    return volume_only(x, std::make_index_sequence<8>{}) / 12.0;
  }

  // Volume / largest face area: the shortest crossing distance of the element.
  template <class T>
  static T length(const T (&x)[3][8], const T& volume) {
    static constexpr int face[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    T largest{};
    for (const auto& f : face) {
      T d1[3], d2[3];
      for (int i = 0; i < 3; ++i) {
        d1[i] = x[i][f[2]] - x[i][f[0]];
        d2[i] = x[i][f[3]] - x[i][f[1]];
      }
      const T n0 = d1[1] * d2[2] - d1[2] * d2[1], n1 = d1[2] * d2[0] - d1[0] * d2[2],
              n2 = d1[0] * d2[1] - d1[1] * d2[0];
      largest = max_of(largest, n0 * n0 + n1 * n1 + n2 * n2);
    }
    return volume / (0.5 * sqrt_of(largest));
  }
};

}  // namespace camouflet
