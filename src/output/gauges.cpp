#include "output/gauges.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace camouflet {

namespace {

constexpr const char* axis_names[3] = {"x", "y", "z"};

// Particle support radius in smoothing lengths (cubic spline kernel: 2h).
constexpr double support_in_h = 2.0;

void push_vector(std::vector<double>& out, std::span<const double> field, std::int64_t index, int dim) {
  for (int i = 0; i < dim; ++i)
    out.push_back(field.empty() ? 0.0 : field[static_cast<std::size_t>(index * dim + i)]);
}

void push_interpolated(std::vector<double>& out, std::span<const double> field,
                       std::span<const std::int64_t> conn, std::int64_t element, int npe, const double* n,
                       int dim) {
  for (int i = 0; i < dim; ++i) {
    double v = 0.0;
    if (!field.empty())
      for (int a = 0; a < npe; ++a) {
        const auto node = conn[static_cast<std::size_t>(element * npe + a)];
        v += n[a] * field[static_cast<std::size_t>(node * dim + i)];
      }
    out.push_back(v);
  }
}

template <class T>
double at_or_zero(std::span<const T> field, std::int64_t index) {
  return field.empty() ? 0.0 : static_cast<double>(field[static_cast<std::size_t>(index)]);
}

void push_stress(std::vector<double>& out, std::span<const SymTensor> stress,
                 std::span<const double> pressure, std::span<const double> plastic,
                 std::span<const double> damage, std::span<const double> temperature, std::int64_t index) {
  const SymTensor s = stress.empty() ? SymTensor{} : stress[static_cast<std::size_t>(index)];
  out.insert(out.end(), {s.xx, s.yy, s.zz, s.xy, s.yz, s.zx});
  out.push_back(at_or_zero(pressure, index));
  out.push_back(at_or_zero(plastic, index));
  out.push_back(at_or_zero(damage, index));
  out.push_back(at_or_zero(temperature, index));
}

// Cubic B-spline W(r, h) (Monaghan 1992, eq. 2.6), support 2h, in `dim` dimensions.
double cubic_spline(double r, double h, int dim) {
  const double q = r / h;
  if (q >= support_in_h) return 0.0;
  const double sigma =
      dim == 2 ? 10.0 / (7.0 * std::numbers::pi * h * h) : 1.0 / (std::numbers::pi * h * h * h);
  if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
  const double t = 2.0 - q;
  return sigma * 0.25 * t * t * t;
}

// Shepard weights V_j W(|x - x_j|, h_j) of the particles around `point`: (index, weight) and their sum.
std::vector<std::pair<std::size_t, double>> shepard_weights(const FieldSnapshot& s, const double* point,
                                                            double& total) {
  const int dim = s.dimension;
  const bool axisymmetric = s.mode == GeometryMode::axisymmetric;
  std::vector<std::pair<std::size_t, double>> w;
  total = 0.0;
  if (s.particle_smoothing_length.empty() || s.particle_mass.empty() || s.particle_density.empty()) return w;
  for (std::size_t p = 0; p < s.particle_count(); ++p) {
    const double* x = &s.particle_position[p * static_cast<std::size_t>(dim)];
    const double h = s.particle_smoothing_length[p];
    double r2 = 0.0;
    for (int i = 0; i < dim; ++i) r2 += (x[i] - point[i]) * (x[i] - point[i]);
    if (r2 >= support_in_h * support_in_h * h * h) continue;
    const double weight_geometry = axisymmetric ? 2.0 * std::numbers::pi * x[0] : 1.0;
    const double volume = s.particle_mass[p] / (s.particle_density[p] * weight_geometry);
    const double wj = volume * cubic_spline(std::sqrt(r2), h, dim);
    if (!(wj > 0.0)) continue;
    w.emplace_back(p, wj);
    total += wj;
  }
  return w;
}

void sample_interpolated(const LocatedGauge& gauge, const FieldSnapshot& s, std::vector<double>& out) {
  const int dim = s.dimension;
  double total = 0.0;
  const auto w = shepard_weights(s, gauge.point.data(), total);
  auto vector_field = [&](std::span<const double> field) {
    for (int i = 0; i < dim; ++i) {
      double v = 0.0;
      if (!field.empty() && total > 0.0)
        for (const auto& [p, wp] : w)
          v += wp * field[p * static_cast<std::size_t>(dim) + static_cast<std::size_t>(i)];
      out.push_back(total > 0.0 ? v / total : std::numeric_limits<double>::quiet_NaN());
    }
  };
  for (int i = 0; i < dim; ++i) out.push_back(gauge.point[static_cast<std::size_t>(i)]);
  vector_field(s.particle_displacement);
  vector_field(s.particle_velocity);
  vector_field(s.particle_acceleration);
  // A point no particle covers any more (the material moved away) samples NaN: nothing to interpolate.
  SymTensor sigma{};
  double pressure = 0.0, plastic = 0.0, damage = 0.0, temperature = 0.0;
  for (const auto& [p, wp] : w) {
    if (!s.particle_stress.empty()) sigma += s.particle_stress[p] * wp;
    pressure += wp * at_or_zero(s.particle_pressure, static_cast<std::int64_t>(p));
    plastic += wp * at_or_zero(s.particle_plastic_strain, static_cast<std::int64_t>(p));
    damage += wp * at_or_zero(s.particle_damage, static_cast<std::int64_t>(p));
    temperature += wp * at_or_zero(s.particle_temperature, static_cast<std::int64_t>(p));
  }
  const double inv = total > 0.0 ? 1.0 / total : std::numeric_limits<double>::quiet_NaN();
  sigma = sigma * inv;
  out.insert(out.end(), {sigma.xx, sigma.yy, sigma.zz, sigma.xy, sigma.yz, sigma.zx});
  out.insert(out.end(), {pressure * inv, plastic * inv, damage * inv, temperature * inv});
}

// The elements of a member and the consistent nodal masses of their set, normalised.
LocatedGauge locate_member(const GaugePoint& gauge, const FieldSnapshot& s) {
  const int dim = s.dimension, npe = s.nodes_per_element;
  const bool axisymmetric = s.mode == GeometryMode::axisymmetric;
  LocatedGauge located;
  located.name = gauge.name;
  std::vector<std::pair<std::int64_t, double>> nodes;  // (node, mass), repeated per element
  double total = 0.0;
  const double g = 1.0 / std::sqrt(3.0);  // Gauss points +-1/sqrt 3, weight 1
  double x[8 * 3];
  for (std::size_t e = 0; e < s.element_count(); ++e) {
    if (gauge.member_material >= 0 && !s.element_material.empty() &&
        s.element_material[e] != gauge.member_material)
      continue;
    if (!element_centre_in_box(dim, s.node_position, s.connectivity, static_cast<std::int64_t>(e), gauge.region_min,
                               gauge.region_max))
      continue;
    gather_element(dim, s.node_position, s.connectivity, static_cast<std::int64_t>(e), x);
    const double rho = s.element_density.empty() ? 1.0 : s.element_density[e];
    double share[8] = {}, mass = 0.0;
    for (int q = 0; q < (dim == 3 ? 8 : 4); ++q) {
      const Natural xi{(q & 1) ? g : -g, (q & 2) ? g : -g, dim == 3 ? ((q & 4) ? g : -g) : 0.0};
      double n[8];
      shape_functions(dim, xi, n);
      double weight = jacobian_determinant(dim, std::span<const double>(x, static_cast<std::size_t>(npe * dim)), xi);
      if (axisymmetric) {
        double r = 0.0;
        for (int a = 0; a < npe; ++a) r += n[a] * x[a * dim];
        weight *= 2.0 * std::numbers::pi * r;
      }
      for (int a = 0; a < npe; ++a) share[a] += rho * n[a] * weight;
      mass += rho * weight;
    }
    located.member_elements.emplace_back(static_cast<std::int64_t>(e), mass);
    for (int a = 0; a < npe; ++a) nodes.emplace_back(s.connectivity[e * static_cast<std::size_t>(npe) + a], share[a]);
    total += mass;
  }
  if (located.member_elements.empty() || !(total > 0.0)) {
    const std::span<const double> lo(gauge.region_min.data(), static_cast<std::size_t>(dim));
    const std::span<const double> hi(gauge.region_max.data(), static_cast<std::size_t>(dim));
    throw InputError(gauge.where, fmt::format("member '{}': no element centre of its material lies in the box "
                                              "({}) .. ({})",
                                              gauge.name, fmt::join(lo, ", "), fmt::join(hi, ", ")));
  }
  for (auto& [e, m] : located.member_elements) m /= total;
  std::sort(nodes.begin(), nodes.end());
  for (const auto& [node, m] : nodes) {
    if (!located.member_nodes.empty() && located.member_nodes.back().first == node)
      located.member_nodes.back().second += m / total;
    else
      located.member_nodes.emplace_back(node, m / total);
  }
  return located;
}

void sample_member(const LocatedGauge& gauge, const FieldSnapshot& s, std::vector<double>& out) {
  const int dim = s.dimension;
  for (auto field : {s.node_position, s.node_displacement, s.node_velocity, s.node_acceleration})
    for (int i = 0; i < dim; ++i) {
      double v = 0.0;
      if (!field.empty())
        for (const auto& [node, w] : gauge.member_nodes) v += w * field[static_cast<std::size_t>(node * dim + i)];
      out.push_back(v);
    }
  SymTensor sigma{};
  double pressure = 0.0, plastic = 0.0, damage = 0.0, temperature = 0.0;
  for (const auto& [e, w] : gauge.member_elements) {
    if (!s.element_stress.empty()) sigma += s.element_stress[static_cast<std::size_t>(e)] * w;
    pressure += w * at_or_zero(s.element_pressure, e);
    plastic += w * at_or_zero(s.element_plastic_strain, e);
    damage += w * at_or_zero(s.element_damage, e);
    temperature += w * at_or_zero(s.element_temperature, e);
  }
  out.insert(out.end(), {sigma.xx, sigma.yy, sigma.zz, sigma.xy, sigma.yz, sigma.zx});
  out.insert(out.end(), {pressure, plastic, damage, temperature});
}

}  // namespace

std::vector<std::string> gauge_quantities(int dim) {
  std::vector<std::string> q;
  for (const char* v : {"position", "displacement", "velocity", "acceleration"})
    for (int i = 0; i < dim; ++i) q.push_back(fmt::format("{}_{}", v, axis_names[i]));
  for (const char* s : {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx",
                        "pressure", "plastic_strain", "damage", "temperature"})
    q.emplace_back(s);
  return q;
}

LocatedGauge locate_gauge(const GaugePoint& gauge, const FieldSnapshot& initial) {
  const int dim = initial.dimension;
  if (gauge.member) return locate_member(gauge, initial);
  LocatedGauge located;
  located.name = gauge.name;
  const std::span<const double> x(gauge.position.data(), static_cast<std::size_t>(dim));
  if (gauge.interpolate) {
    // Kernel interpolation among particles at a fixed point.
    if (initial.element_count() > 0 && locate_point(dim, initial.node_position, initial.connectivity, x))
      throw InputError(
          gauge.where,
          fmt::format("gauge '{}' at ({}) lies in the mesh; `particles = \"interpolate\"` samples "
                      "particles only (use a separate gauge group for element gauges)",
                      gauge.name, fmt::join(x.begin(), x.end(), ", ")));
    double total = 0.0;
    shepard_weights(initial, gauge.position.data(), total);
    if (!(total > 0.0))
      throw InputError(gauge.where, fmt::format("gauge '{}' at ({}) lies outside every particle's support",
                                                gauge.name, fmt::join(x.begin(), x.end(), ", ")));
    located.interpolate = true;
    located.point = gauge.position;
    return located;
  }
  if (initial.element_count() > 0) {
    if (const auto loc = locate_point(dim, initial.node_position, initial.connectivity, x)) {
      located.element = loc->element;
      located.xi = loc->xi;
      return located;
    }
  }
  // Nearest particle whose support contains the point.
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < initial.particle_count(); ++p) {
    double d2 = 0.0;
    for (int i = 0; i < dim; ++i) {
      const double d =
          initial.particle_position[p * static_cast<std::size_t>(dim) + static_cast<std::size_t>(i)] -
          gauge.position[static_cast<std::size_t>(i)];
      d2 += d * d;
    }
    const double h = initial.particle_smoothing_length.empty() ? 0.0 : initial.particle_smoothing_length[p];
    if (d2 < best && std::sqrt(d2) <= support_in_h * h) {
      best = d2;
      located.particle = static_cast<std::int64_t>(p);
    }
  }
  if (located.particle >= 0) return located;
  throw InputError(gauge.where,
                   fmt::format("gauge '{}' at ({}) lies outside the mesh{}", gauge.name,
                               fmt::join(x.begin(), x.end(), ", "),
                               initial.particle_count() > 0 ? " and every particle's support" : ""));
}

void sample_gauge(const LocatedGauge& gauge, const FieldSnapshot& s, std::vector<double>& out) {
  const int dim = s.dimension;
  if (gauge.is_member()) return sample_member(gauge, s, out);
  if (gauge.element >= 0) {
    const int npe = s.nodes_per_element;
    double n[8];
    shape_functions(dim, gauge.xi, n);
    for (auto field : {s.node_position, s.node_displacement, s.node_velocity, s.node_acceleration})
      push_interpolated(out, field, s.connectivity, gauge.element, npe, n, dim);
    push_stress(out, s.element_stress, s.element_pressure, s.element_plastic_strain, s.element_damage,
                s.element_temperature, gauge.element);
    return;
  }
  if (gauge.interpolate) return sample_interpolated(gauge, s, out);
  for (auto field :
       {s.particle_position, s.particle_displacement, s.particle_velocity, s.particle_acceleration})
    push_vector(out, field, gauge.particle, dim);
  push_stress(out, s.particle_stress, s.particle_pressure, s.particle_plastic_strain, s.particle_damage,
              s.particle_temperature, gauge.particle);
}

}  // namespace camouflet
