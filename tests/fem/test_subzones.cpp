// The geometry behind the subzonal pressures and the edge viscosity
// (fem/subzonal_pressure.hpp, fem/edge_viscosity.hpp): the corner subzones
// tile the element, their volume derivatives are those of their volumes, and
// the median areas of a square are half its side.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "fem/edge_viscosity.hpp"
#include "fem/subzonal_pressure.hpp"

using namespace camouflet;

namespace {

template <int D>
void distorted_unit_cell(double (&x)[D][Shape<D>::nodes], double offset_r, unsigned seed) {
  static constexpr double unit2[2][4] = {{0, 1, 1, 0}, {0, 0, 1, 1}};
  static constexpr double unit3[3][8] = {
      {0, 1, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (int i = 0; i < D; ++i)
    for (int a = 0; a < Shape<D>::nodes; ++a)
      x[i][a] = (D == 2 ? unit2[i][a] : unit3[i][a]) + u(rng) + (i == 0 ? offset_r : 0.0);
}

template <int D>
void check_tiling_and_gradients(bool axisymmetric, double offset_r) {
  constexpr int N = Shape<D>::nodes;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    double x[D][N], b[D][N];
    distorted_unit_cell<D>(x, offset_r, seed);
    double volume[N], gradient[N][D][N];
    subzone_volumes<D>(x, axisymmetric, volume, gradient);
    double total = 0.0;
    for (int s = 0; s < N; ++s) {
      EXPECT_GT(volume[s], 0.0) << "subzone " << s;
      total += volume[s];
    }
    // The subzones tile the element: planar and 3-D exactly; r-z with each subzone's own mean
    // radius, exactly for the sum of ring volumes of the parallelogram subzones of a rectangle,
    // to the distortion's second order otherwise (the element's own 2 pi r_bar A is the same
    // one-point rule).
    double element = Shape<D>::gradients(x, b);
    if (D == 2 && axisymmetric) element *= 2.0 * std::numbers::pi * 0.25 * (x[0][0] + x[0][1] + x[0][2] + x[0][3]);
    EXPECT_NEAR(total / element, 1.0, axisymmetric ? 2e-2 : 1e-12) << "seed " << seed;
    // dV_s/dx against central differences.
    for (int s = 0; s < N; ++s)
      for (int i = 0; i < D; ++i)
        for (int a = 0; a < N; ++a) {
          const double h = 1e-6;
          double xp[D][N], xm[D][N], vp[N], vm[N];
          for (int k = 0; k < D; ++k)
            for (int c = 0; c < N; ++c) xp[k][c] = xm[k][c] = x[k][c];
          xp[i][a] += h;
          xm[i][a] -= h;
          subzone_volumes<D>(xp, axisymmetric, vp);
          subzone_volumes<D>(xm, axisymmetric, vm);
          EXPECT_NEAR(gradient[s][i][a], (vp[s] - vm[s]) / (2 * h), 1e-7)
              << "subzone " << s << " component " << i << " node " << a;
        }
  }
}

}  // namespace

TEST(Subzones, TileTheQuadAndDifferentiateRight) { check_tiling_and_gradients<2>(false, 0.0); }
TEST(Subzones, TileTheRingAndDifferentiateRight) { check_tiling_and_gradients<2>(true, 2.0); }
TEST(Subzones, TileTheHexAndDifferentiateRight) { check_tiling_and_gradients<3>(false, 0.0); }

TEST(Subzones, EachCornerOfTheUnitSquareAndCubeIsAQuarterAndAnEighth) {
  double x2[2][4] = {{0, 1, 1, 0}, {0, 0, 1, 1}}, v2[4];
  subzone_volumes<2>(x2, false, v2);
  for (const double v : v2) EXPECT_NEAR(v, 0.25, 1e-15);
  double x3[3][8] = {{0, 1, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}}, v3[8];
  subzone_volumes<3>(x3, false, v3);
  for (const double v : v3) EXPECT_NEAR(v, 0.125, 1e-15);
}

TEST(EdgeViscosity, MedianAreasOfTheUnitSquareAndCube) {
  double x2[2][4] = {{0, 1, 1, 0}, {0, 0, 1, 1}}, a2[4];
  edge_median_areas<2>(x2, false, a2);
  for (const double a : a2) EXPECT_NEAR(a, 0.5, 1e-15);  // centre to edge midpoint
  double x3[3][8] = {{0, 1, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}}, a3[12];
  edge_median_areas<3>(x3, false, a3);
  for (const double a : a3) EXPECT_NEAR(a, 0.25, 1e-15);  // a half by half square
}

// The element kernels run these formulas on packs of elements (element_pack.hpp) and rely on
// each lane having the bits of its element computed alone: compared here exactly, lane by lane.
template <int D>
void check_packs_match_elements(bool axisymmetric) {
  constexpr int N = Shape<D>::nodes, K = ElementEdges<D>::count;
  Pack x[D][N], v[D][N], rho, c, psi[K];
  double xs[pack_width][D][N], vs[pack_width][D][N];
  std::mt19937 rng(20261208);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int l = 0; l < pack_width; ++l) {
    distorted_unit_cell<D>(xs[l], axisymmetric ? 0.5 + l : 0.0, 7u + static_cast<unsigned>(l));
    for (int i = 0; i < D; ++i)
      for (int a = 0; a < N; ++a) {
        x[i][a][l] = xs[l][i][a];
        vs[l][i][a] = v[i][a][l] = 100.0 * u(rng);
      }
    rho[l] = 1800.0 + 10.0 * l;
    c[l] = 400.0 + l;
    for (int k = 0; k < K; ++k) psi[k][l] = 0.5 * (1.0 + u(rng));
  }
  Pack volume[N], gradient[N][D][N], force[K * D];
  subzone_volumes<D>(x, axisymmetric, volume, gradient);
  edge_viscous_forces<D>(x, v, axisymmetric, rho, c, 1.5, 0.06, force, psi);
  for (int l = 0; l < pack_width; ++l) {
    double volume_l[N], gradient_l[N][D][N], force_l[K * D], psi_l[K];
    for (int k = 0; k < K; ++k) psi_l[k] = psi[k][l];
    subzone_volumes<D>(xs[l], axisymmetric, volume_l, gradient_l);
    edge_viscous_forces<D>(xs[l], vs[l], axisymmetric, rho[l], c[l], 1.5, 0.06, force_l, psi_l);
    int closing = 0;
    for (int s = 0; s < N; ++s) {
      EXPECT_EQ(volume[s][l], volume_l[s]);
      for (int i = 0; i < D; ++i)
        for (int a = 0; a < N; ++a) EXPECT_EQ(gradient[s][i][a][l], gradient_l[s][i][a]);
    }
    for (int k = 0; k < K * D; ++k) {
      EXPECT_EQ(force[k][l], force_l[k]);
      closing += force_l[k] != 0.0;
    }
    EXPECT_GT(closing, 0) << "lane " << l << ": no edge closing, the force formula not exercised";
  }
}

TEST(Subzones, PacksOfQuadsHaveTheBitsOfEachQuad) {
  check_packs_match_elements<2>(false);
}
TEST(Subzones, PacksOfRingsHaveTheBitsOfEachRing) {
  check_packs_match_elements<2>(true);
}
TEST(Subzones, PacksOfHexesHaveTheBitsOfEachHex) {
  check_packs_match_elements<3>(false);
}
