#pragma once
// Lagrangian gauges (issue 2, "Output"; style.md #12): each gauge is found at
// t = 0 in an element of the initial mesh (natural coordinates by Newton
// inversion) and then follows that material point: kinematic quantities are
// interpolated from the element's nodes with the shape functions, stress-like
// quantities come from the element's integration point. A gauge outside every
// element follows the nearest particle at t = 0, when it lies within that
// particle's support.
#include <cstdint>
#include <string>
#include <vector>

#include "model/isoparametric.hpp"
#include "model/model.hpp"
#include "output/snapshot.hpp"

namespace camouflet {

struct LocatedGauge {
  std::string name;
  std::int64_t element = -1;   // 0-based; -1 when following a particle
  Natural xi{};                // natural coordinates in `element`
  std::int64_t particle = -1;  // 0-based; -1 when in an element
};

// Column names sampled for every gauge, in CSV order: position, displacement,
// velocity, acceleration (dim components each, _x _y [_z]; axisymmetric: x = r,
// y = z), stress_xx .. stress_zx (Cauchy, tension positive), pressure,
// plastic_strain, damage.
std::vector<std::string> gauge_quantities(int dim);

// Throws InputError at gauge.where when the point lies outside the mesh and
// outside every particle's support.
LocatedGauge locate_gauge(const GaugePoint& gauge, const FieldSnapshot& initial);

// Values of every gauge_quantities() column at this instant, appended to `out`.
void sample_gauge(const LocatedGauge& gauge, const FieldSnapshot& state, std::vector<double>& out);

}  // namespace camouflet
