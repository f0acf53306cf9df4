#pragma once
// Elements are processed in packs of `pack_width`: lane l of a Pack holds the
// value of element e0 + l, so the element formulas (shape.hpp) run on whole
// SIMD registers without the compiler having to discover the vectorisation.
// The width follows the target (-march; CMake option CAMOUFLET_NATIVE builds
// src/fem for this CPU): 8 doubles with AVX-512, 4 with AVX, 2 with SSE2.
// pack_width has internal linkage, so translation units built for different
// targets (the fem layer, tests including shape.hpp) each see their own.
// GCC/Clang vector extension; arithmetic with a scalar broadcasts it.
// docs/performance.md.
#include <cmath>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace camouflet {

#if defined(__AVX512F__)
constexpr int pack_width = 8;
#elif defined(__AVX__)
constexpr int pack_width = 4;
#else
constexpr int pack_width = 2;
#endif

using Pack = double __attribute__((vector_size(pack_width * sizeof(double))));

inline Pack broadcast(double s) {
  return Pack{} + s;
}

// Lane-wise max and square root; the double overloads let shape.hpp's
// formulas serve single elements and packs alike.
inline double max_of(double a, double b) {
  return a < b ? b : a;
}  // as std::max
inline double sqrt_of(double a) {
  return std::sqrt(a);
}
// Written as whole-register operations: a loop over lanes compiled to one
// extract and one insert per lane (docs/performance.md, "hex8 at 74eacb6"). The
// results are those of the scalar versions lane by lane (a compare and a
// select; the correctly rounded IEEE square root).
inline double hypot_of(double a, double b) {
  return std::hypot(a, b);
}
inline Pack hypot_of(const Pack& a, const Pack& b) {  // glibc's hypot lane by lane (no vector form)
  Pack r;
  for (int l = 0; l < pack_width; ++l) r[l] = std::hypot(a[l], b[l]);
  return r;
}
inline Pack max_of(const Pack& a, const Pack& b) {
  return a < b ? b : a;
}
inline Pack sqrt_of(const Pack& a) {
#if defined(__AVX512F__)
  return _mm512_mask_sqrt_pd(a, 0xFF, a);  // all lanes; the unmasked form warns (GCC 12)
#elif defined(__AVX__)
  return _mm256_sqrt_pd(a);
#elif defined(__SSE2__)
  return _mm_sqrt_pd(a);
#else
  Pack r;
  for (int l = 0; l < pack_width; ++l) r[l] = std::sqrt(a[l]);
  return r;
#endif
}

}  // namespace camouflet
