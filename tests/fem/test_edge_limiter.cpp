// The edge viscosity's limiter (fem/edge_viscosity.hpp, edge_limiter; Caramana, Shashkov and
// Whalen 1998) and the edges' continuations it reads (fem/edge_continuation.hpp): psi is 1 where
// the velocity gradient along an edge is the same on both sides (no force in a linear field), 0
// where it turns back or the edge stands alone; on a block mesh every edge not on the boundary
// continues into its neighbours along its own mesh line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fem/edge_continuation.hpp"
#include "fem/edge_viscosity.hpp"
#include "mesh/block_generator.hpp"
#include "model/model.hpp"

using namespace camouflet;

TEST(EdgeLimiter, OneInALinearFieldZeroAcrossAJumpOrAlone) {
  // Edge along x of length 0.1, closing at 2 m/s; its neighbours of length 0.2 and 0.05.
  const double du[2] = {-0.2, 0.05}, dx[2] = {0.1, 0.0};
  const double dx_l[2] = {0.2, 0.0}, dx_r[2] = {0.05, 0.0};
  // The same gradient on both sides: du scales with the length.
  const double du_l[2] = {-0.4, 0.1}, du_r[2] = {-0.1, 0.025};
  EXPECT_NEAR(edge_limiter<2>(du, dx, du_l, dx_l, du_r, dx_r), 1.0, 1e-15);
  // Half the gradient on the left: r_l = 0.5, r_r = 1 -> min(0.75, 1, 2, 1).
  const double du_half[2] = {-0.2, 0.05};
  EXPECT_NEAR(edge_limiter<2>(du, dx, du_half, dx_l, du_r, dx_r), 0.75, 1e-15);
  // The gradient turns back on the right (a compression peak): psi = 0.
  const double du_back[2] = {0.1, -0.025};
  EXPECT_EQ(edge_limiter<2>(du, dx, du_l, dx_l, du_back, dx_r), 0.0);
  // A jump: the neighbours at rest.
  const double still[2] = {0.0, 0.0};
  EXPECT_EQ(edge_limiter<2>(du, dx, still, dx_l, still, dx_r), 0.0);
  // One side missing: the other's ratio stands for both; none: the full force.
  EXPECT_NEAR(edge_limiter<2>(du, dx, nullptr, nullptr, du_r, dx_r), 1.0, 1e-15);
  EXPECT_NEAR(edge_limiter<2>(du, dx, du_half, dx_l, nullptr, nullptr), 0.5, 1e-15);
  EXPECT_EQ(edge_limiter<2>(du, dx, nullptr, nullptr, nullptr, nullptr), 0.0);
  // Steeper on both sides: capped at 1.
  const double du_steep[2] = {-1.2, 0.3};
  EXPECT_EQ(edge_limiter<2>(du, dx, du_steep, dx_l, du_steep, dx_r), 1.0);
}

TEST(EdgeLimiter, ForcesScaledByOneMinusPsi) {
  const double x[2][4] = {{0, 1, 1, 0}, {0, 0, 1, 1}};
  const double v[2][4] = {{0.5, -0.5, -0.5, 0.5}, {0, 0, 0, 0}};  // edges 0 and 2 close
  double full[8], limited[8];
  const double psi[4] = {0.25, 0.0, 1.0, 0.0};
  edge_viscous_forces<2>(x, v, false, 2.0, 100.0, 1.5, 0.06, full);
  edge_viscous_forces<2>(x, v, false, 2.0, 100.0, 1.5, 0.06, limited, psi);
  EXPECT_GT(std::abs(full[0]), 0.0);
  EXPECT_DOUBLE_EQ(limited[0], 0.75 * full[0]);
  EXPECT_EQ(limited[4], 0.0);  // edge 2, psi = 1
  EXPECT_GT(std::abs(full[4]), 0.0);
}

namespace {

// Counts the edge ends with a continuation, and checks each continuation lies on the edge's line.
template <int D>
int continued_ends(const FemMesh& mesh, std::size_t element, int* off_line) {
  using E = ElementEdges<D>;
  const auto beyond = edge_continuations<D>(mesh.connectivity, mesh.coordinates.size() / D, mesh.coordinates.data());
  int count = 0;
  *off_line = 0;
  for (int k = 0; k < E::count; ++k) {
    const std::int64_t p = mesh.connectivity[element * E::nodes + E::node[k][0]];
    const std::int64_t q = mesh.connectivity[element * E::nodes + E::node[k][1]];
    for (int end = 0; end < 2; ++end) {
      const std::int64_t n = beyond[(element * E::count + k) * 2 + end];
      if (n < 0) continue;
      ++count;
      // n, p, q collinear on a block mesh: (x_n - x_p) x (x_q - x_p) = 0.
      const std::int64_t from = end == 0 ? p : q, to = end == 0 ? q : p;
      double a[3] = {}, b[3] = {};
      for (int i = 0; i < D; ++i)
        a[i] = mesh.coordinates[n * D + i] - mesh.coordinates[from * D + i],
        b[i] = mesh.coordinates[to * D + i] - mesh.coordinates[from * D + i];
      const double cross = std::hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
      const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      if (cross > 1e-12 || dot >= 0.0) ++*off_line;  // on the line, on the far side of `from`
    }
  }
  return count;
}

}  // namespace

TEST(EdgeLimiter, EveryInteriorEdgeContinuesAlongItsLine) {
  FemMesh quads;
  quads.dimension = 2;
  add_block(quads, {"b", 0, {0, 0, 0}, {3.0, 3.0, 0}, {3, 3, 1}, {1.5, 1.0, 1}});  // graded along x
  int off = 0;
  EXPECT_EQ(continued_ends<2>(quads, 4, &off), 8);  // the middle element: every end continues
  EXPECT_EQ(off, 0);
  EXPECT_EQ(continued_ends<2>(quads, 0, &off), 4);  // a corner: its two outer ends of each edge do not
  EXPECT_EQ(off, 0);
  FemMesh hexes;
  hexes.dimension = 3;
  add_block(hexes, {"b", 0, {0, 0, 0}, {3.0, 3.0, 3.0}, {3, 3, 3}});
  EXPECT_EQ(continued_ends<3>(hexes, 13, &off), 24);  // the middle hex
  EXPECT_EQ(off, 0);
  EXPECT_EQ(continued_ends<3>(hexes, 0, &off), 12);  // a corner hex: each edge continues inwards only
  EXPECT_EQ(off, 0);
}
