#pragma once
// Root of a scalar function on a bracket [lo, hi] with f(lo) and f(hi) of
// opposite sign (or zero), by the Illinois variant of regula falsi: it keeps
// the bracket at every step, so it cannot diverge, and converges
// superlinearly on smooth functions. Used by the P-alpha pressure solve and
// the RHT return map, which must never fail on an admissible state.
#include <cmath>

namespace camouflet {

struct RootResult {
  double x = 0.0;
  bool converged = false;
  int iterations = 0;
};

// `tolerance` is absolute on x; `f_lo`, `f_hi` are f(lo), f(hi), already known.
template <class F>
RootResult bracketed_root(F&& f, double lo, double hi, double f_lo, double f_hi, double tolerance,
                          int max_iterations = 200) {
  RootResult r;
  if (f_lo == 0.0) return {lo, true, 0};
  if (f_hi == 0.0) return {hi, true, 0};
  if ((f_lo > 0.0) == (f_hi > 0.0)) return {0.5 * (lo + hi), false, 0};
  int side = 0;  // which end was kept last: halve its value when kept twice (Illinois)
  for (int it = 1; it <= max_iterations; ++it) {
    double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    // Fall back to bisection when the secant point is not strictly inside.
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    r.iterations = it;
    if (fx == 0.0 || hi - lo < tolerance) return {x, true, it};
    if ((fx > 0.0) == (f_hi > 0.0)) {
      hi = x;
      f_hi = fx;
      if (side == -1) f_lo *= 0.5;
      side = -1;
    } else {
      lo = x;
      f_lo = fx;
      if (side == 1) f_hi *= 0.5;
      side = 1;
    }
    if (hi - lo < tolerance) return {0.5 * (lo + hi), true, it};
  }
  r.x = 0.5 * (lo + hi);
  return r;
}

}  // namespace camouflet
