#pragma once
// A symmetric tensor acting on a D-vector: the in-plane block (D = 2, the
// third direction being out-of-plane or hoop) or the full tensor (D = 3).
// Used by the SPH stress sums, the kernel-gradient correction and the join.
#include "core/sym_tensor.hpp"
#include "core/vec.hpp"

namespace camouflet {

template <int D>
inline Vec<D> apply(const SymTensor& s, const Vec<D>& g) {
  Vec<D> out;
  if constexpr (D == 2) {
    out[0] = s.xx * g[0] + s.xy * g[1];
    out[1] = s.xy * g[0] + s.yy * g[1];
  } else {
    out[0] = s.xx * g[0] + s.xy * g[1] + s.zx * g[2];
    out[1] = s.xy * g[0] + s.yy * g[1] + s.yz * g[2];
    out[2] = s.zx * g[0] + s.yz * g[1] + s.zz * g[2];
  }
  return out;
}

}  // namespace camouflet
