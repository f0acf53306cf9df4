// artificial_stress<3> of many stress tensors at once: the cyclic Jacobi
// eigen-solve (symmetric_eigen.hpp, the source the scalar symmetric_eigen()
// runs too) on SIMD lanes (pair_lanes.hpp), one tensor per lane, so every
// result has the scalar function's bits. After a few steps of an impact most
// particles carry some tension (if only round-off noise ahead of the wave):
// the scalar solve was ~15 % of the Taylor bar's cycle (docs/performance.md).
#include <algorithm>
#include <cstdint>

#include "sph/artificial_stress.hpp"
#include "sph/pair_lanes.hpp"
#include "sph/symmetric_eigen.hpp"

namespace camouflet::sph {

void artificial_stress_3d(std::span<const SymTensor> sigma, std::span<const double> scale, double epsilon,
                          std::span<SymTensor> out) {
  if constexpr (pair_lanes < 4) {  // with 2 lanes the masked rotations cost more than they save (callgrind)
    for (std::size_t k = 0; k < sigma.size(); ++k) out[k] = artificial_stress<3>(sigma[k], epsilon, scale[k]);
    return;
  }
  // The tensors with tension are packed into full lanes in order (about half of an impact's
  // particles have some): lanes by position left most of each solve idle. Each lane still does
  // the scalar solve's operations, so the packing changes no bits.
  std::size_t pending[pair_lanes];
  int filled = 0;
  const auto solve = [&] {
    LaneMask need{};
    Lanes s[6] = {};
    for (int l = 0; l < filled; ++l) {
      const SymTensor& t = sigma[pending[l]];
      need[l] = -1;
      const double components[6] = {t.xx, t.yy, t.zz, t.xy, t.yz, t.zx};
      for (int c = 0; c < 6; ++c) s[c][l] = components[c];
    }
    Lanes values[3], vectors[3][3];
    symmetric_eigen_of(s, need, values, vectors);
    for (int l = 0; l < filled; ++l) {
      double v[3], q[3][3];
      for (int i = 0; i < 3; ++i) {
        v[i] = values[i][l];
        for (int j = 0; j < 3; ++j) q[i][j] = vectors[i][j][l];
      }
      out[pending[l]] = rotate_tensile_part(v, q, epsilon, scale[pending[l]]);
    }
    filled = 0;
  };
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    out[k] = {};
    if (no_tension(sigma[k])) continue;
    pending[filled++] = k;
    if (filled == pair_lanes) solve();
  }
  if (filled > 0) solve();
}

}  // namespace camouflet::sph
