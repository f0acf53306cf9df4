#pragma once
// Eigen-decomposition of a symmetric 3x3 tensor by cyclic Jacobi rotations
// (Golub & Van Loan, the symmetric Schur decomposition), written once for one
// tensor (T = double, M = bool) and for one tensor per SIMD lane (T = Lanes,
// M = LaneMask, pair_lanes.hpp). A lane rotates only while it is `running` and
// its off-diagonal entry is non-zero, and stops at the sweep where a lone
// tensor would stop (a lane that has converged keeps its values through the
// select), so each lane has the bits of the scalar solve.
#include "sph/pair_lanes.hpp"

namespace camouflet::sph {

// s: the components xx yy zz xy yz zx; the lanes not `running` are left as they are. values[k]
// with unit eigenvector vectors[.][k] (column k).
template <class T, class M>
void symmetric_eigen_of(const T s[6], M running, T values[3], T vectors[3][3]) {
  T a[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  const T zero{}, one = zero + 1.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) vectors[i][j] = i == j ? one : zero;
  for (int sweep = 0; sweep < 30; ++sweep) {
    const T off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const T diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    const M converged = (off <= 1e-30 * diag) | (off == 0.0);
    running = and_not(running, converged);
    if (!any_of(running)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        const M rotate = and_not(running, a[p][q] == 0.0);
        if (!any_of(rotate)) continue;
        // The rotation that zeroes a[p][q].
        const T theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const T t = (theta >= 0.0 ? one : -one) / (abs_of(theta) + sqrt_of(theta * theta + 1.0));
        const T c = 1.0 / sqrt_of(t * t + 1.0), sn = t * c;
        T b[3][3], w[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) b[i][j] = a[i][j], w[i][j] = vectors[i][j];
        for (int k = 0; k < 3; ++k) {
          const T bkp = b[k][p], bkq = b[k][q];
          b[k][p] = c * bkp - sn * bkq;
          b[k][q] = sn * bkp + c * bkq;
        }
        for (int k = 0; k < 3; ++k) {
          const T bpk = b[p][k], bqk = b[q][k];
          b[p][k] = c * bpk - sn * bqk;
          b[q][k] = sn * bpk + c * bqk;
        }
        for (int k = 0; k < 3; ++k) {
          const T wkp = w[k][p], wkq = w[k][q];
          w[k][p] = c * wkp - sn * wkq;
          w[k][q] = sn * wkp + c * wkq;
        }
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            a[i][j] = rotate ? b[i][j] : a[i][j];
            vectors[i][j] = rotate ? w[i][j] : vectors[i][j];
          }
      }
  }
  for (int k = 0; k < 3; ++k) values[k] = a[k][k];
}

}  // namespace camouflet::sph
