#include "materials/density_at_pressure.hpp"

#include <cmath>

namespace camouflet {

DensityInversion set_density_for_pressure(const EquationOfState& eos, MaterialPoints& pts,
                                          const std::vector<double>& pressure, const std::vector<char>& active) {
  const std::size_t n = pts.size();
  const double rho0 = eos.reference_density();
  const MaterialContext ctx{};
  std::vector<double> lo(n, rho0), hi(n, 2.0 * rho0);
  DensityInversion result;
  // The bracket's ends: both evaluated before any bisection, so a pressure beyond them is named.
  for (const double* end : {lo.data(), hi.data()}) {
    for (std::size_t i = 0; i < n; ++i)
      if (active[i]) pts.density[i] = end[i];
    eos.evaluate(pts, ctx, false);
    for (std::size_t i = 0; i < n && result.failed_point < 0; ++i) {
      if (!active[i]) continue;
      const bool below = end == lo.data() ? pts.pressure[i] > pressure[i] : pts.pressure[i] < pressure[i];
      if (below) result = {static_cast<std::int64_t>(i), pts.pressure[i]};
    }
  }
  if (result.failed_point >= 0) return result;
  // 60 halvings take the bracket from rho0 to below 1e-18 rho0: round-off ends it first.
  for (int it = 0; it < 60; ++it) {
    for (std::size_t i = 0; i < n; ++i)
      if (active[i]) pts.density[i] = 0.5 * (lo[i] + hi[i]);
    eos.evaluate(pts, ctx, false);
    for (std::size_t i = 0; i < n; ++i) {
      if (!active[i]) continue;
      (pts.pressure[i] < pressure[i] ? lo[i] : hi[i]) = pts.density[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (active[i]) pts.density[i] = pts.density_previous[i] = 0.5 * (lo[i] + hi[i]);
  eos.evaluate(pts, ctx, false);  // the predictor's trial, which the commit then takes over
  eos.evaluate(pts, ctx, true);
  return result;
}

}  // namespace camouflet
