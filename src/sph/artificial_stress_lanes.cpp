// artificial_stress<3> of many stress tensors at once: the cyclic Jacobi
// eigen-solve of symmetric_eigen() on SIMD lanes (pair_lanes.hpp), one tensor
// per lane. Each lane does the scalar rotations in the same order and stops at
// the sweep where the scalar loop stops (lanes that have converged, or whose
// rotation is skipped, keep their values through a select), so every result
// has the scalar function's bits. After a few steps of an impact most
// particles carry some tension (if only round-off noise ahead of the wave):
// the scalar solve was ~15 % of the Taylor bar's cycle (docs/performance.md).
#include <algorithm>
#include <cstdint>

#include "sph/artificial_stress.hpp"
#include "sph/pair_lanes.hpp"

namespace camouflet::sph {

namespace {

bool any_lane(LaneMask m) {
  bool any = false;
  for (int l = 0; l < pair_lanes; ++l) any |= m[l] != 0;
  return any;
}

Lanes abs_lanes(Lanes a) {  // clears the sign bit, as std::abs
  return reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(a) & std::int64_t{0x7fffffffffffffff});
}

// symmetric_eigen() for the lanes in `running` (the others are left untouched).
void symmetric_eigen_lanes(const Lanes s[6], LaneMask running, Lanes values[3], Lanes vectors[3][3]) {
  Lanes a[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  const Lanes zero{}, one = zero + 1.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) vectors[i][j] = i == j ? one : zero;
  for (int sweep = 0; sweep < 30; ++sweep) {
    const Lanes off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const Lanes diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    running &= ~((off <= 1e-30 * diag) | (off == 0.0));
    if (!any_lane(running)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        const LaneMask rotate = running & (a[p][q] != 0.0);
        if (!any_lane(rotate)) continue;
        const Lanes theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const Lanes t = (theta >= 0.0 ? one : -one) / (abs_lanes(theta) + sqrt_lanes(theta * theta + 1.0));
        const Lanes c = 1.0 / sqrt_lanes(t * t + 1.0), sn = t * c;
        Lanes b[3][3], w[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) b[i][j] = a[i][j], w[i][j] = vectors[i][j];
        for (int k = 0; k < 3; ++k) {
          const Lanes akp = b[k][p], akq = b[k][q];
          b[k][p] = c * akp - sn * akq;
          b[k][q] = sn * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const Lanes apk = b[p][k], aqk = b[q][k];
          b[p][k] = c * apk - sn * aqk;
          b[q][k] = sn * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const Lanes vkp = w[k][p], vkq = w[k][q];
          w[k][p] = c * vkp - sn * vkq;
          w[k][q] = sn * vkp + c * vkq;
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

}  // namespace

void artificial_stress_3d(std::span<const SymTensor> sigma, std::span<const double> scale, double epsilon,
                          std::span<SymTensor> out) {
  if constexpr (pair_lanes < 4) {  // with 2 lanes the masked rotations cost more than they save (callgrind)
    for (std::size_t k = 0; k < sigma.size(); ++k) out[k] = artificial_stress<3>(sigma[k], epsilon, scale[k]);
    return;
  }
  for (std::size_t g = 0; g < sigma.size(); g += pair_lanes) {
    const std::size_t width = std::min<std::size_t>(pair_lanes, sigma.size() - g);
    LaneMask need{};
    Lanes s[6] = {};
    for (std::size_t l = 0; l < width; ++l) {
      const SymTensor& t = sigma[g + l];
      out[g + l] = {};
      if (no_tension(t)) continue;
      need[l] = -1;
      const double components[6] = {t.xx, t.yy, t.zz, t.xy, t.yz, t.zx};
      for (int c = 0; c < 6; ++c) s[c][l] = components[c];
    }
    if (!any_lane(need)) continue;
    Lanes values[3], vectors[3][3];
    symmetric_eigen_lanes(s, need, values, vectors);
    for (std::size_t l = 0; l < width; ++l) {
      if (!need[l]) continue;
      double v[3], q[3][3];
      for (int i = 0; i < 3; ++i) {
        v[i] = values[i][l];
        for (int j = 0; j < 3; ++j) q[i][j] = vectors[i][j][l];
      }
      out[g + l] = rotate_tensile_part(v, q, epsilon, scale[g + l]);
    }
  }
}

}  // namespace camouflet::sph
