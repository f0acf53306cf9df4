#include "output/gauges.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

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
                 std::span<const double> damage, std::int64_t index) {
  const SymTensor s = stress.empty() ? SymTensor{} : stress[static_cast<std::size_t>(index)];
  out.insert(out.end(), {s.xx, s.yy, s.zz, s.xy, s.yz, s.zx});
  out.push_back(at_or_zero(pressure, index));
  out.push_back(at_or_zero(plastic, index));
  out.push_back(at_or_zero(damage, index));
}

}  // namespace

std::vector<std::string> gauge_quantities(int dim) {
  std::vector<std::string> q;
  for (const char* v : {"position", "displacement", "velocity", "acceleration"})
    for (int i = 0; i < dim; ++i) q.push_back(fmt::format("{}_{}", v, axis_names[i]));
  for (const char* s : {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx",
                        "pressure", "plastic_strain", "damage"})
    q.emplace_back(s);
  return q;
}

LocatedGauge locate_gauge(const GaugePoint& gauge, const FieldSnapshot& initial) {
  const int dim = initial.dimension;
  LocatedGauge located;
  located.name = gauge.name;
  const std::span<const double> x(gauge.position.data(), static_cast<std::size_t>(dim));
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
  if (gauge.element >= 0) {
    const int npe = s.nodes_per_element;
    double n[8];
    shape_functions(dim, gauge.xi, n);
    for (auto field : {s.node_position, s.node_displacement, s.node_velocity, s.node_acceleration})
      push_interpolated(out, field, s.connectivity, gauge.element, npe, n, dim);
    push_stress(out, s.element_stress, s.element_pressure, s.element_plastic_strain, s.element_damage,
                gauge.element);
    return;
  }
  for (auto field :
       {s.particle_position, s.particle_displacement, s.particle_velocity, s.particle_acceleration})
    push_vector(out, field, gauge.particle, dim);
  push_stress(out, s.particle_stress, s.particle_pressure, s.particle_plastic_strain, s.particle_damage,
              gauge.particle);
}

}  // namespace camouflet
