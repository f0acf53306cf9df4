#pragma once
// Subzonal pressures of one element (Caramana and Shashkov 1998, J. Comput. Phys.
// 142, 521, "Elimination of artificial grid distortion and hourglass-type motions
// by means of Lagrangian subzonal masses and pressures"). The median mesh cuts
// each element into one corner subzone per node (2-D: the node, its two edge
// midpoints and the centre; 3-D: the node, three edge midpoints, three face
// centres and the centre). Each subzone keeps the mass it starts with; when the
// nodes move so that a corner is crushed while the element's volume is not (the
// hourglass and bow-tie motions that the one-point stress cannot see), the
// corner's density rises above the element's and its pressure with it:
//   dp_s = kappa c^2 (rho_s - rho_z),  rho_s = m_s / V_s,  rho_z = sum m_s / sum V_s,
// acting on the subzone's faces inside the element: f_a = sum_s dp_s dV_s/dx_a.
// A uniform compression leaves every dp_s zero. The forces' work -sum dp_s dV_s
// goes into the element's internal energy, so energy is conserved.
//
// The subzone volumes here are those of the element's own measure: plane strain
// the area, r-z the ring volume 2 pi r_bar A with r_bar the mean corner radius
// (as the element's, fem_elements.hpp), 3-D the trilinear hexahedron's volume.
// Every subzone corner is a fixed average of the element's nodes, so the
// subzone is a quad (hex) whose gradients (shape.hpp) give dV_s/dx by the chain rule.
#include <array>
#include <initializer_list>
#include <numbers>

#include "fem/shape.hpp"

namespace camouflet {

template <int D>
struct Subzones {
  static constexpr int nodes = Shape<D>::nodes;
  // corner[s][k][j]: the weight of element node j in corner k of node s's subzone.
  using Table = std::array<std::array<std::array<double, nodes>, nodes>, nodes>;
  static const Table& corners() {
    static const Table table = make();
    return table;
  }

 private:
  static Table make() {
    Table t{};
    if constexpr (D == 2) {
      // Node s, the midpoint towards s + 1, the centre, the midpoint towards s - 1 (counter-clockwise).
      for (int s = 0; s < 4; ++s) {
        const int next = (s + 1) % 4, prev = (s + 3) % 4;
        t[s][0][s] = 1.0;
        t[s][1][s] = t[s][1][next] = 0.5;
        for (int j = 0; j < 4; ++j) t[s][2][j] = 0.25;
        t[s][3][s] = t[s][3][prev] = 0.5;
      }
    } else {
      // Node s seen through its permutation p (shape.hpp: p[0] = s, p[1], p[3] its neighbours on
      // its own face in counter-clockwise order, p[4] the neighbour across): the subzone hex
      // s, m(s,p1), f(p0 p1 p2 p3), m(s,p3) below; m(s,p4), f(p0 p1 p5 p4), centre, f(p3 p0 p4 p7) above.
      for (int s = 0; s < 8; ++s) {
        const int* p = Shape<3>::permutation[s];
        auto add = [&](int k, std::initializer_list<int> of) {
          for (const int j : of) t[s][k][p[j]] += 1.0 / static_cast<double>(of.size());
        };
        add(0, {0});
        add(1, {0, 1});
        add(2, {0, 1, 2, 3});
        add(3, {0, 3});
        add(4, {0, 4});
        add(5, {0, 1, 5, 4});
        for (int j = 0; j < 8; ++j) t[s][6][j] = 0.125;
        add(7, {3, 0, 4, 7});
      }
    }
    return t;
  }
};

// The volumes V_s (m^3; plane strain m^2 per metre) of an element's subzones at node positions
// x[i][a], and when `gradient` is not null their derivatives gradient[s][i][a] = dV_s/dx_ia. T is
// double for one element or a pack of elements (element_pack.hpp: each lane does the same
// operations in the same order, so a lane has the bits of the element alone).
template <int D, class T>
inline void subzone_volumes(const T (&x)[D][Shape<D>::nodes], bool axisymmetric, T (&volume)[Shape<D>::nodes],
                            T (*gradient)[D][Shape<D>::nodes] = nullptr) {
  constexpr int N = Shape<D>::nodes;
  const typename Subzones<D>::Table& w = Subzones<D>::corners();
  for (int s = 0; s < N; ++s) {
    T corner[D][N] = {}, b[D][N];
    for (int k = 0; k < N; ++k)
      for (int j = 0; j < N; ++j)
        if (w[s][k][j] != 0.0)
          for (int i = 0; i < D; ++i) corner[i][k] += w[s][k][j] * x[i][j];
    const T measure = Shape<D>::gradients(corner, b);
    T ring = T{} + 1.0, r_bar{};
    if constexpr (D == 2) {
      if (axisymmetric) {
        r_bar = 0.25 * (corner[0][0] + corner[0][1] + corner[0][2] + corner[0][3]);
        ring = 2.0 * std::numbers::pi * r_bar;
      }
    }
    volume[s] = measure * ring;
    if (!gradient) continue;
    // dV_s/dcorner_k = ring dA/dcorner_k (+ 2 pi A / 4 along r in r-z), then onto the nodes.
    T d_corner[D][N];
    for (int k = 0; k < N; ++k)
      for (int i = 0; i < D; ++i) d_corner[i][k] = ring * measure * b[i][k];
    if constexpr (D == 2) {
      if (axisymmetric)
        for (int k = 0; k < N; ++k) d_corner[0][k] += 2.0 * std::numbers::pi * measure * 0.25;
    }
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < N; ++j) {
        T g{};
        for (int k = 0; k < N; ++k) g += w[s][k][j] * d_corner[i][k];
        gradient[s][i][j] = g;
      }
  }
}

}  // namespace camouflet
