#pragma once
// Reading the SPH package's settings (model/sph_options.hpp) from an [sph]
// block, and the pair viscosity they set.
#include "core/parameters.hpp"
#include "model/sph_options.hpp"
#include "sph/kernel.hpp"

namespace camouflet::sph {

// Linear and quadratic viscosity coefficients of a pair from the particles' alpha
// (SphOptions::viscosity_switch).
struct PairViscosity {
  double alpha = 0.0, beta = 0.0;
};
inline PairViscosity pair_viscosity(const SphOptions& o, double alpha_i, double alpha_j) {
  if (!o.viscosity_switch || !(o.viscosity_alpha > 0.0)) return {o.viscosity_alpha, o.viscosity_beta};
  const double a = 0.5 * (alpha_i + alpha_j);
  return {a, o.viscosity_beta * a / o.viscosity_alpha};
}

// Reads the optional keys of an `[sph]` block (names as SphOptions' members;
// `kernel` a string). Bounds inverted or out of range -> InputError naming the key.
SphOptions read_sph_options(Parameters& block);

}  // namespace camouflet::sph
