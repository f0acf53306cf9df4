#pragma once
// What the element loops of fem_elements.cpp, fem_forces.cpp and
// fem_kinematics.cpp share: an element's node values gathered one element at
// a time or as SIMD packs of elements (element_pack.hpp), and the ring weight
// of an axisymmetric element. Internal linkage, like pack_width: only the fem
// layer includes this, built for one target, and each unit inlines its own copy.
#include <cstdint>
#include <cstring>
#include <numbers>

#include "core/simd_transpose.hpp"
#include "fem/element_pack.hpp"
#include "fem/shape.hpp"

namespace camouflet {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

template <int D>
using NodeValues = double[D][Shape<D>::nodes];

template <int D>
inline void gather(const double* field, const std::int64_t* conn, NodeValues<D>& out) {
  for (int a = 0; a < Shape<D>::nodes; ++a)
    for (int i = 0; i < D; ++i) out[i][a] = field[conn[a] * D + i];
}

// Axisymmetric volume weight 2 pi r_bar (r_bar = mean nodal radius, the
// centre of the one-point element); 1 otherwise.
template <int D>
inline double ring_weight(bool axisymmetric, const NodeValues<D>& x, double& r_bar) {
  if constexpr (D == 2) {
    if (axisymmetric) {
      r_bar = 0.25 * (x[0][0] + x[0][1] + x[0][2] + x[0][3]);
      return two_pi * r_bar;
    }
  }
  r_bar = 0.0;
  return 1.0;
}

template <int D>
using PackedNodes = Pack[D][Shape<D>::nodes];

// The elements of one pack: lane l holds element at(l); lanes past `count`
// repeat the last element (computed, never scattered). Consecutive packs
// (the buffer assembly) load element arrays as whole packs; listed packs
// (one colour's elements, element_colouring.hpp) lane by lane.
struct ConsecutiveLanes {
  static constexpr bool consecutive = true;
  std::size_t first;
  int count;
  std::size_t at(int l) const { return first + static_cast<std::size_t>(l < count ? l : count - 1); }
};
struct ListedLanes {
  static constexpr bool consecutive = false;
  const std::uint32_t* element;
  int count;
  std::size_t at(int l) const { return element[l < count ? l : count - 1]; }
};

// Lane l <- element lanes.at(l). Gathers F node fields (positions,
// velocities) at once, so that each node's numbers are fetched once for all.
template <int D, int F, class Lanes>
inline void gather_packs(const double* const (&field)[F], const std::int64_t* connectivity,
                         const Lanes& lanes, PackedNodes<D>* const (&out)[F]) {
  constexpr int N = Shape<D>::nodes;
#if defined(__AVX512F__) && defined(__AVX512VL__)
  // Each lane's row of node numbers and each node's D values are read as short contiguous
  // records and turned into lanes by transposes (core/simd_transpose.hpp): the 8-lane
  // hardware gathers this replaces (per node one for its numbers and one per field and
  // component) took about half of each element kernel's time on AMD Zen 4.
  // docs/performance.md, "hex8 and quad4 kernels without hardware gathers". The same values: no
  // bits change.
  alignas(64) std::int64_t node[N][pack_width];
  if constexpr (N == 8) {
    __m512d rows[8], columns[8];
    for (int l = 0; l < 8; ++l)
      rows[l] = _mm512_loadu_pd(reinterpret_cast<const double*>(connectivity + lanes.at(l) * N));
    simd::transpose_8x8(rows, columns);
    for (int a = 0; a < N; ++a) _mm512_store_pd(reinterpret_cast<double*>(node[a]), columns[a]);
  } else {
    static_assert(N == 4, "quads and hexes");
    __m256d rows[8];
    __m512d columns[4];
    for (int l = 0; l < 8; ++l)
      rows[l] = _mm256_loadu_pd(reinterpret_cast<const double*>(connectivity + lanes.at(l) * N));
    simd::transpose_8x4(rows, columns);
    for (int a = 0; a < N; ++a) _mm512_store_pd(reinterpret_cast<double*>(node[a]), columns[a]);
  }
  for (int a = 0; a < N; ++a)
    for (int f = 0; f < F; ++f) {
      const double* values = field[f];
      if constexpr (D == 3) {
        // x y z of each lane's node; the masked fourth value is not read (it may lie past the end).
        __m256d rows[8];
        __m512d columns[4];
        for (int l = 0; l < 8; ++l) rows[l] = _mm256_maskz_loadu_pd(0x7, values + node[a][l] * D);
        simd::transpose_8x4(rows, columns);
        for (int i = 0; i < D; ++i) (*out[f])[i][a] = reinterpret_cast<Pack>(columns[i]);
      } else {
        __m128d rows[8];
        __m512d columns[2];
        for (int l = 0; l < 8; ++l) rows[l] = _mm_loadu_pd(values + node[a][l] * D);
        simd::transpose_8x2(rows, columns);
        for (int i = 0; i < D; ++i) (*out[f])[i][a] = reinterpret_cast<Pack>(columns[i]);
      }
    }
#else
  for (int f = 0; f < F; ++f) {
    alignas(sizeof(Pack)) double lanes_of[D][N][pack_width];  // the layout of PackedNodes<D>
    for (int l = 0; l < pack_width; ++l) {
      const std::int64_t* c = connectivity + lanes.at(l) * N;
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < D; ++i) lanes_of[i][a][l] = field[f][c[a] * D + i];
    }
    static_assert(sizeof lanes_of == sizeof *out[f]);
    std::memcpy(out[f], lanes_of, sizeof lanes_of);
  }
#endif
}

// An element array at the lanes' elements as a pack.
template <class Lanes>
inline Pack load_pack(const double* a, const Lanes& lanes) {
  Pack p;
  if (Lanes::consecutive && lanes.count == pack_width) {
    std::memcpy(&p, a + lanes.at(0), sizeof p);
  } else {
    for (int l = 0; l < pack_width; ++l) p[l] = a[lanes.at(l)];
  }
  return p;
}

// Lanes e0 .. e0 + count - 1 of an element array as a pack; lanes past
// `count` repeat the last element, as in gather_packs.
inline Pack load_pack(const double* a, std::size_t e0, int count) {
  return load_pack(a, ConsecutiveLanes{e0, count});
}

// All pack_width lanes of p into a[e0 ..].
inline void store_pack(double* a, std::size_t e0, const Pack& p) {
  std::memcpy(a + e0, &p, sizeof p);
}

template <int D>
inline Pack ring_weight_pack(bool axisymmetric, const PackedNodes<D>& x, Pack& r_bar) {
  if constexpr (D == 2) {
    if (axisymmetric) {
      r_bar = 0.25 * (x[0][0] + x[0][1] + x[0][2] + x[0][3]);
      return two_pi * r_bar;
    }
  }
  r_bar = Pack{};
  return broadcast(1.0);
}

}  // namespace

}  // namespace camouflet
