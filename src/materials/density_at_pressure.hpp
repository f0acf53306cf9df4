#pragma once
// The density at which a batch's equation of state gives an asked pressure:
// the inverse of p(rho, e) at the points' own specific energy, for initial
// states given by a stress (the geostatic state, docs/theory/gravity.md).
#include <cstdint>
#include <vector>

#include "materials/material.hpp"

namespace camouflet {

struct DensityInversion {
  std::int64_t failed_point = -1;  // 0-based, the first point whose pressure lies outside the bracket
  double bracket_pressure = 0.0;   // Pa, the pressure at the bracket's end it did not reach
};

// For every point with `active[i]`, sets density (and density_previous) so that the EOS gives
// `pressure[i]` (Pa, compression positive) within 1e-9 relative, then commits the EOS at that
// density: a history (the three-phase soil's compaction) is the virgin loading state there.
// Bisection on the whole batch at once (one virtual call per iteration, not per point) in
// [rho0, 2 rho0], compression only (a geostatic pressure is never a tension); p(rho) must
// increase with density there, as every EOS of the library does on loading. Points not active keep their density. Returns the first point not bracketed.
DensityInversion set_density_for_pressure(const EquationOfState& eos, MaterialPoints& pts,
                                          const std::vector<double>& pressure, const std::vector<char>& active);

}  // namespace camouflet
