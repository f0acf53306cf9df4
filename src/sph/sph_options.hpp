#pragma once
// Reading the SPH package's settings (model/sph_options.hpp) from an [sph]
// block, and the pair viscosity they set.
#include "core/parameters.hpp"
#include "model/sph_options.hpp"
#include "sph/kernel.hpp"

namespace camouflet::sph {

// Linear and quadratic viscosity coefficients of a pair from the particles' alpha
// (SphOptions::viscosity_switch).
// Written once for one pair (T = double) and for SIMD lanes of pairs (pair_lanes.cpp).
template <class T = double>
struct PairViscosity {
  T alpha{}, beta{};
};
// With the switch on: alpha the mean of the two points', beta in the fixed ratio to it.
template <class T, class Ti>
inline PairViscosity<T> switched_pair_viscosity(const SphOptions& o, Ti alpha_i, T alpha_j) {
  const T a = 0.5 * (alpha_i + alpha_j);
  return {a, o.viscosity_beta * a / o.viscosity_alpha};
}
inline PairViscosity<> pair_viscosity(const SphOptions& o, double alpha_i, double alpha_j) {
  if (!o.viscosity_switch || !(o.viscosity_alpha > 0.0)) return {o.viscosity_alpha, o.viscosity_beta};
  return switched_pair_viscosity(o, alpha_i, alpha_j);
}

// Reads the optional keys of an `[sph]` block (names as SphOptions' members;
// `kernel` a string). Bounds inverted or out of range -> InputError naming the key.
SphOptions read_sph_options(Parameters& block);

}  // namespace camouflet::sph
