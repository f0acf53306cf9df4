#pragma once
// Lagrangian gauges (style.md #12): each gauge is found at
// t = 0 in an element of the initial mesh (natural coordinates by Newton
// inversion) and then follows that material point: kinematic quantities are
// interpolated from the element's nodes with the shape functions, stress-like
// quantities come from the element's integration point. A gauge outside every
// element follows the nearest particle at t = 0, when it lies within that
// particle's support.
//
// A gauge with GaugePoint::interpolate (group key `particles = "interpolate"`)
// stays at its position instead and samples the particles there by kernel
// interpolation, Shepard-normalised (Randles & Libersky 1996, CMAME 139;
// Liu & Liu 2003, "Smoothed Particle Hydrodynamics", section 4.3):
//     A(x) = sum_j V_j A_j W(|x - x_j|, h_j) / sum_j V_j W(|x - x_j|, h_j),
// V_j = m_j / rho_j (axisymmetric: the meridian area m_j / (2 pi r_j rho_j)),
// with the cubic B-spline whatever kernel the run uses. The normalisation
// makes constant fields exact and linear ones exact where the support is
// symmetric (interior). Its position column is the fixed point; the other
// columns are interpolated. Cost: one pass over the particles per gauge and sample.
//
// A member gauge (GaugePoint::member, group key `members`) is the mass-weighted
// mean over a set of elements, chosen at t = 0 by material and by the box that
// holds their centres: the members of a structure (a wall, the roof, the
// floor). Its nodal columns weigh each node by its consistent share of the
// set's mass, m_a = sum_e integral rho N_a dV (Gauss 2x2(x2), ring weight
// 2 pi r in r-z), so its velocity is the set's momentum over its mass, the
// span's rigid-body velocity; its element columns weigh each element by its
// mass (mean stress, mean damage). Its position column is the centre of mass.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/isoparametric.hpp"
#include "model/model.hpp"
#include "model/snapshot.hpp"

namespace camouflet {

struct LocatedGauge {
  std::string name;
  std::int64_t element = -1;      // 0-based; -1 when following a particle
  Natural xi{};                   // natural coordinates in `element`
  std::int64_t particle = -1;     // 0-based; -1 when in an element
  bool interpolate = false;       // fixed point, kernel-interpolated among particles
  std::array<double, 3> point{};  // m, the fixed point of an interpolating gauge
  // Member gauge: (node, mass share) and (element, mass share), each summing to 1.
  std::vector<std::pair<std::int64_t, double>> member_nodes, member_elements;
  bool is_member() const { return !member_elements.empty(); }
};

// Column names sampled for every gauge, in CSV order: position, displacement,
// velocity, acceleration (dim components each, _x _y [_z]; axisymmetric: x = r,
// y = z), stress_xx .. stress_zx (Cauchy, tension positive), pressure,
// plastic_strain, damage.
std::vector<std::string> gauge_quantities(int dim);

// Throws InputError at gauge.where when the point lies outside the mesh and
// outside every particle's support, when an interpolating gauge lies in the
// mesh, or when a member's box holds no element centre of its material.
LocatedGauge locate_gauge(const GaugePoint& gauge, const FieldSnapshot& initial);

// Values of every gauge_quantities() column at this instant, appended to `out`.
void sample_gauge(const LocatedGauge& gauge, const FieldSnapshot& state, std::vector<double>& out);

}  // namespace camouflet
