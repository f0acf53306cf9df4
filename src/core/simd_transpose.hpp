#pragma once
// Transposes of 8 rows of doubles into SIMD columns and back, with AVX-512:
// what turns "one short record per lane" (a node's x y z, a particle's
// record, an element's node numbers) into "one register per field" without
// an 8-lane gather, and lane sums back into per-lane records without inserts.
// They only move 64-bit values (integers pass through as their bit
// patterns): no bits change. Inline, and only for translation units built
// for AVX-512 (the fem and sph layers with CAMOUFLET_NATIVE on such a CPU);
// elsewhere nothing is declared and callers take their lane loops.
#if defined(__AVX512F__)
#include <immintrin.h>

namespace camouflet::simd {

// The masked forms with every lane set and an explicit source: GCC 12's plain
// forms pass an undefined register that it then warns about where inlined.
[[gnu::always_inline]] inline __m512d unpacklo(__m512d a, __m512d b) {
  return _mm512_mask_unpacklo_pd(_mm512_setzero_pd(), 0xFF, a, b);
}
[[gnu::always_inline]] inline __m512d unpackhi(__m512d a, __m512d b) {
  return _mm512_mask_unpackhi_pd(_mm512_setzero_pd(), 0xFF, a, b);
}
// (low, high): 256-bit halves joined.
[[gnu::always_inline]] inline __m512d join(__m256d low, __m256d high) {
  return _mm512_mask_insertf64x4(_mm512_setzero_pd(), 0xFF, _mm512_castpd256_pd512(low), high, 1);
}

// out[c][r] = in[r][c] for an 8 x 8 block, in 24 shuffles.
[[gnu::always_inline]] inline void transpose_8x8(const __m512d in[8], __m512d out[8]) {
  // Index vectors of _mm512_permutex2var_pd (8 + k picks lane k of the second operand).
  const __m512i pairs_lo = _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0);
  const __m512i pairs_hi = _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2);
  const __m512i quads_lo = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
  const __m512i quads_hi = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
  __m512d t[8];  // t[2q] = in(2q)_0 in(2q+1)_0 in(2q)_2 in(2q+1)_2 ..., t[2q+1] the odd columns
  for (int q = 0; q < 4; ++q) {
    t[2 * q] = unpacklo(in[2 * q], in[2 * q + 1]);
    t[2 * q + 1] = unpackhi(in[2 * q], in[2 * q + 1]);
  }
  // u: rows 0-3 (u[0..3]) and 4-7 (u[4..7]) of columns (0, 4), (2, 6), (1, 5), (3, 7).
  __m512d u[8];
  for (int h = 0; h < 2; ++h) {
    u[4 * h + 0] = _mm512_permutex2var_pd(t[4 * h + 0], pairs_lo, t[4 * h + 2]);
    u[4 * h + 1] = _mm512_permutex2var_pd(t[4 * h + 0], pairs_hi, t[4 * h + 2]);
    u[4 * h + 2] = _mm512_permutex2var_pd(t[4 * h + 1], pairs_lo, t[4 * h + 3]);
    u[4 * h + 3] = _mm512_permutex2var_pd(t[4 * h + 1], pairs_hi, t[4 * h + 3]);
  }
  constexpr int column_of[4] = {0, 2, 1, 3};  // first column held by u[k] (and column + 4)
  for (int k = 0; k < 4; ++k) {
    out[column_of[k]] = _mm512_permutex2var_pd(u[k], quads_lo, u[k + 4]);
    out[column_of[k] + 4] = _mm512_permutex2var_pd(u[k], quads_hi, u[k + 4]);
  }
}

// Rows of 4 (one 256-bit register each) into 4 columns of 8: out[c][r] = rows[r][c], in 12
// shuffles. A column nobody reads costs nothing once inlined.
[[gnu::always_inline]] inline void transpose_8x4(const __m256d rows[8], __m512d out[4]) {
  const __m512i pairs_lo = _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0);
  const __m512i pairs_hi = _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2);
  __m512d q[4];  // q[k] = rows k and k + 4
  for (int k = 0; k < 4; ++k) q[k] = join(rows[k], rows[k + 4]);
  // Columns 0 and 2 of rows (0, 1 | 4, 5) and (2, 3 | 6, 7); columns 1 and 3 likewise.
  const __m512d even01 = unpacklo(q[0], q[1]), even23 = unpacklo(q[2], q[3]);
  const __m512d odd01 = unpackhi(q[0], q[1]), odd23 = unpackhi(q[2], q[3]);
  out[0] = _mm512_permutex2var_pd(even01, pairs_lo, even23);
  out[2] = _mm512_permutex2var_pd(even01, pairs_hi, even23);
  out[1] = _mm512_permutex2var_pd(odd01, pairs_lo, odd23);
  out[3] = _mm512_permutex2var_pd(odd01, pairs_hi, odd23);
}

// Rows of 2 (one 128-bit register each) into 2 columns of 8: out[c][r] = rows[r][c].
[[gnu::always_inline]] inline void transpose_8x2(const __m128d rows[8], __m512d out[2]) {
  __m512d q[2];  // rows 0-3 and 4-7, two values each
  for (int h = 0; h < 2; ++h) {
    const __m256d lo = _mm256_insertf128_pd(_mm256_zextpd128_pd256(rows[4 * h]), rows[4 * h + 1], 1);
    const __m256d hi = _mm256_insertf128_pd(_mm256_zextpd128_pd256(rows[4 * h + 2]), rows[4 * h + 3], 1);
    q[h] = join(lo, hi);
  }
  out[0] = _mm512_permutex2var_pd(q[0], _mm512_set_epi64(14, 12, 10, 8, 6, 4, 2, 0), q[1]);
  out[1] = _mm512_permutex2var_pd(q[0], _mm512_set_epi64(15, 13, 11, 9, 7, 5, 3, 1), q[1]);
}

}  // namespace camouflet::simd
#endif
