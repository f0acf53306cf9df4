#pragma once
// The SPH pair loops on SIMD lanes: lane l of a `Lanes` value holds the pair
// (i, j_l) of one particle i with the l-th of a group of its neighbours, so
// the pair formulas run on whole vector registers (GCC/Clang vector
// extension; arithmetic with a scalar broadcasts it). The neighbours' data are
// gathered lane by lane from one packed record per point (PairPoint: the
// fields the pair loops read, in one or two cache lines instead of ~10
// arrays) and the reactions scattered lane by lane. Every lane does the
// scalar code's operations in the same order (no FMA: the sph layer is built
// with -ffp-contract=off), so each pair term has the scalar's bits; only the
// order in which a particle's pair terms are added differs (per lane, then
// across lanes). docs/performance.md, "SPH at 2d71b6d".
//
// Width: 8 doubles with AVX-512, 4 with AVX, 2 with SSE2 (the target of the
// sph layer, CMake option CAMOUFLET_NATIVE). Include this header only from
// the sph layer's sources: translation units built for other targets would
// see another width.
#include <cmath>
#include <cstddef>
#include <cstdint>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "core/simd_transpose.hpp"
#include "sph/pair_point.hpp"

namespace camouflet::sph {

#if defined(__AVX512F__)
inline constexpr int pair_lanes = 8;
#elif defined(__AVX__)
inline constexpr int pair_lanes = 4;
#else
inline constexpr int pair_lanes = 2;
#endif

using Lanes = double __attribute__((vector_size(pair_lanes * sizeof(double))));
using LaneMask = std::int64_t __attribute__((vector_size(pair_lanes * sizeof(double))));

// Correctly rounded lane-wise square root (the scalar std::sqrt's bits).
inline Lanes sqrt_lanes(Lanes a) {
#if defined(__AVX512F__)
  return reinterpret_cast<Lanes>(_mm512_sqrt_pd(reinterpret_cast<__m512d>(a)));
#elif defined(__AVX__)
  return reinterpret_cast<Lanes>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(a)));
#elif defined(__x86_64__)
  return reinterpret_cast<Lanes>(_mm_sqrt_pd(reinterpret_cast<__m128d>(a)));
#else
  for (int l = 0; l < pair_lanes; ++l) a[l] = std::sqrt(a[l]);
  return a;
#endif
}

// The same names on one value (double, bool) and on lanes (Lanes, LaneMask), so that a formula
// written once as a template on its value type runs on either with the same bits
// (symmetric_eigen.hpp, pair_terms.hpp).
inline bool any_of(bool m) { return m; }
inline bool any_of(LaneMask m) {
  bool any = false;
  for (int l = 0; l < pair_lanes; ++l) any |= m[l] != 0;
  return any;
}
inline bool and_not(bool a, bool b) { return a && !b; }
inline LaneMask and_not(LaneMask a, LaneMask b) { return a & ~b; }
inline double abs_of(double a) { return std::abs(a); }
inline Lanes abs_of(Lanes a) {  // clears the sign bit, as std::abs
  return reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(a) & std::int64_t{0x7fffffffffffffff});
}
inline double sqrt_of(double a) { return std::sqrt(a); }
inline Lanes sqrt_of(Lanes a) { return sqrt_lanes(a); }
inline double pow_of(double a, double b) { return std::pow(a, b); }
inline Lanes pow_of(Lanes a, double b) {
  for (int l = 0; l < pair_lanes; ++l) a[l] = std::pow(a[l], b);
  return a;
}

// As std::max(a, b) lane by lane (a unless a < b).
inline Lanes max_lanes(Lanes a, Lanes b) {
  return a < b ? b : a;
}

inline double sum_lanes(Lanes a) {
  double s = 0.0;
  for (int l = 0; l < pair_lanes; ++l) s += a[l];
  return s;
}

inline double max_of_lanes(Lanes a) {
  double s = a[0];
  for (int l = 1; l < pair_lanes; ++l) s = s < a[l] ? a[l] : s;
  return s;
}

// Field `field` of the points j[0..pair_lanes) (one scalar load per lane).
template <int D>
inline Lanes gather(const PairPoint<D>* points, const std::uint32_t* j, int field) {
  Lanes g;
  for (int l = 0; l < pair_lanes; ++l) g[l] = points[j[l]].f[field];
  return g;
}

#if defined(__AVX512F__)
using simd::transpose_8x8;  // core/simd_transpose.hpp
#endif

// Fields [0, 8 lines) of the records of points j[0..pair_lanes): fields[f][l] =
// points[j[l]].f[f]. With AVX-512 each 64-byte line of the 8 records is loaded
// whole and the 8 x 8 block transposed (8 loads and 24 shuffles a line instead
// of 64 single-lane loads); elsewhere one scalar load per lane and field. The
// same values either way: the pair terms keep their bits.
template <int D>
inline void load_lines(const PairPoint<D>* points, const std::uint32_t* j, int lines, Lanes* fields) {
  static_assert(sizeof(PairPoint<D>) == 128, "two 64-byte lines per record");
#if defined(__AVX512F__)
  for (int line = 0; line < lines; ++line) {
    __m512d r[8];  // row l: the line of record j[l]
    for (int l = 0; l < 8; ++l) r[l] = _mm512_load_pd(points[j[l]].f + 8 * line);
    transpose_8x8(r, reinterpret_cast<__m512d*>(fields + 8 * line));
  }
#else
  constexpr int size = 2 * D + 10;  // fields of the record
  for (int f = 0; f < 8 * lines && f < size; ++f) fields[f] = gather(points, j, f);
#endif
}

}  // namespace camouflet::sph
