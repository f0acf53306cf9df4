#include "fem/embedded_bars.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "model/bar_hosts.hpp"

namespace camouflet {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

}  // namespace

template <int D>
EmbeddedBars<D>::EmbeddedBars(const Model& model, const std::vector<double>& x0)
    : EmbeddedBars(model, locate_bar_nodes(model, x0), nullptr, {}) {}

template <int D>
EmbeddedBars<D>::EmbeddedBars(const Model& model, const BarHosts& hosts, const std::vector<char>* hosted_here,
                              std::span<const std::int64_t> global_nodes)
    : axisymmetric_(model.run.mode == GeometryMode::axisymmetric) {
  // The host nodes in this rank's numbering (the whole mesh's on one rank).
  const auto local_node = [&](std::int64_t whole) -> std::int64_t {
    if (!hosted_here) return whole;
    const auto found = std::lower_bound(global_nodes.begin(), global_nodes.end(), whole);
    if (found == global_nodes.end() || *found != whole)
      throw std::logic_error(fmt::format("embedded bars: host node {} is not held on this rank", whole + 1));
    return found - global_nodes.begin();
  };
  const auto here = [&](std::size_t b) { return !hosted_here || (*hosted_here)[b] != 0; };
  std::size_t first_node = 0;  // of the set, in the whole model's bar nodes
  for (const BarSet& spec : model.bars) {
    const auto segments = static_cast<std::size_t>(spec.segments);
    // This rank steps the segments whose first node its elements host, and holds the bar nodes
    // they use and those its elements host (whose mass it counts).
    std::vector<char> step(segments), hold(segments + 1);
    for (std::size_t s = 0; s < segments; ++s) step[s] = here(first_node + s);
    for (std::size_t b = 0; b <= segments; ++b)
      hold[b] = here(first_node + b) || (b > 0 && step[b - 1]) || (b < segments && step[b]);
    const auto stepped = static_cast<std::size_t>(std::count(step.begin(), step.end(), 1));

    Set set;
    set.name = spec.name;
    set.material = model.materials[static_cast<std::size_t>(spec.material)].material.get();
    set.hoop = spec.orientation == BarOrientation::hoop;
    set.material->setup(set.points, stepped);
    MaterialPoints reference;  // the material's reference state, whatever this rank steps of the set
    set.material->setup(reference, 1);
    const double rho0 = reference.density.empty() ? 0.0 : reference.density[0];
    set.shear_modulus = reference.shear_modulus.empty() ? 0.0 : reference.shear_modulus[0];
    set.bulk_modulus = reference.sound_speed.empty() ? 0.0 : rho0 * std::pow(reference.sound_speed[0], 2);
    // First guess of the lateral rate: the elastic Poisson contraction.
    const double k = set.bulk_modulus, g = set.shear_modulus;
    const double poisson = k + g > 0.0 ? (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g)) : 0.5;
    set.lateral_ratio.assign(stepped, -poisson);

    // Segment masses and lengths of the whole set from the located positions (a bar node's mass is
    // half of each segment beside it, wherever that segment is stepped).
    std::vector<double> mass(segments), length(segments), radius(segments), half_masses(segments + 1, 0.0);
    for (std::size_t s = 0; s < segments; ++s) {
      const double* xi = &hosts.position[(first_node + s) * 3];
      const double* xj = &hosts.position[(first_node + s + 1) * 3];
      double l = 0.0;
      for (int c = 0; c < D; ++c) l += (xj[c] - xi[c]) * (xj[c] - xi[c]);
      l = std::sqrt(l);
      const double r_bar = axisymmetric_ ? 0.5 * (xi[0] + xj[0]) : 0.0;
      if (axisymmetric_ && !(r_bar > 0.0))
        throw InputError(spec.where, fmt::format("bar '{}': segment {} lies on the axis", spec.name, s + 1));
      // Volume: area x length (x 2 pi r in axisymmetric, where the area is per metre of circumference
      // for bars along the segment, per metre of segment for rings).
      const double volume = spec.area * l * (axisymmetric_ ? two_pi * r_bar : 1.0);
      mass[s] = rho0 * volume;
      length[s] = l;
      radius[s] = r_bar;
      half_masses[s] += 0.5 * mass[s];
      half_masses[s + 1] += 0.5 * mass[s];
    }

    std::vector<std::size_t> local_bar(segments + 1, 0);
    for (std::size_t b = 0; b <= segments; ++b) {
      if (!hold[b]) continue;
      local_bar[b] = node_mass_.size();
      const std::size_t whole = first_node + b;
      for (int a = 0; a < host_nodes; ++a) {
        const std::size_t k_host = whole * static_cast<std::size_t>(host_nodes) + static_cast<std::size_t>(a);
        host_node_.push_back(local_node(hosts.node[k_host]));
        weight_.push_back(hosts.weight[k_host]);
      }
      node_mass_.push_back(here(whole) ? half_masses[b] : 0.0);  // counted by the rank hosting it
    }
    const std::size_t set_index = sets_.size();
    std::size_t point = 0;
    for (std::size_t s = 0; s < segments; ++s) {
      if (!step[s]) continue;
      segment_node_.push_back(local_bar[s]);
      segment_node_.push_back(local_bar[s + 1]);
      segment_set_.push_back(set_index);
      segment_point_.push_back(point);
      segment_in_set_.push_back(s);
      segment_whole_.push_back(total_segments_ + s);
      segment_mass_.push_back(mass[s]);
      reference_length_.push_back(set.hoop ? radius[s] : length[s]);
      axial_strain_.push_back(0.0);
      set.points.characteristic_length[point] = length[s];
      ++point;
    }
    sets_.push_back(std::move(set));
    first_node += segments + 1;
    total_segments_ += segments;
  }
}

template <int D>
void EmbeddedBars<D>::bar_node_position(const double* x, std::size_t b, double* out) const {
  for (int i = 0; i < D; ++i) out[i] = 0.0;
  for (int a = 0; a < host_nodes; ++a) {
    const std::size_t k = b * host_nodes + static_cast<std::size_t>(a);
    for (int i = 0; i < D; ++i) out[i] += weight_[k] * x[host_node_[k] * D + i];
  }
}

template <int D>
void EmbeddedBars<D>::bar_node_velocity(const double* v, std::size_t b, double* out) const {
  bar_node_position(v, b, out);  // the same interpolation
}

template <int D>
void EmbeddedBars<D>::add_masses(std::vector<double>& node_mass) const {
  for (std::size_t b = 0; b < node_mass_.size(); ++b)
    for (int a = 0; a < host_nodes; ++a) {
      const std::size_t k = b * host_nodes + static_cast<std::size_t>(a);
      node_mass[static_cast<std::size_t>(host_node_[k])] += weight_[k] * node_mass_[b];
    }
}

template <int D>
void EmbeddedBars<D>::add_forces(const double* x, double* f) const {
  for (std::size_t s = 0; s < segment_set_.size(); ++s) {
    const Set& set = sets_[segment_set_[s]];
    const MaterialPoints& pts = set.points;
    const std::size_t p = segment_point_[s];
    const std::size_t i = segment_node_[2 * s], j = segment_node_[2 * s + 1];
    double xi[D], xj[D], fi[D] = {}, fj[D] = {};
    bar_node_position(x, i, xi);
    bar_node_position(x, j, xj);
    const double sigma = pts.deviator[p].xx - pts.pressure[p];  // along the bar (its local x)
    const double volume = segment_mass_[s] / pts.density[p];    // current volume, m^3
    if (set.hoop) {
      // Virtual power of the hoop stress against v_r / r at the segment centre
      // (the axisymmetric element's hoop term, eq. of fem_forces.cpp).
      const double r_bar = 0.5 * (xi[0] + xj[0]);
      fi[0] = fj[0] = -0.5 * sigma * volume / r_bar;
    } else {
      double e[D], l = 0.0;
      for (int c = 0; c < D; ++c) {
        e[c] = xj[c] - xi[c];
        l += e[c] * e[c];
      }
      l = std::sqrt(l);
      // Axial force N = sigma A with the current area A = V / L (mass conservation).
      const double force = sigma * volume / l;
      for (int c = 0; c < D; ++c) {
        fi[c] = force * e[c] / l;
        fj[c] = -fi[c];
      }
    }
    for (int a = 0; a < host_nodes; ++a) {
      const std::size_t ki = i * host_nodes + static_cast<std::size_t>(a);
      const std::size_t kj = j * host_nodes + static_cast<std::size_t>(a);
      for (int c = 0; c < D; ++c) {
        f[host_node_[ki] * D + c] += weight_[ki] * fi[c];
        f[host_node_[kj] * D + c] += weight_[kj] * fj[c];
      }
    }
  }
}

template <int D>
void EmbeddedBars<D>::update(const double* x, const double* v, double dt, double time) {
  std::vector<std::vector<double>> rate(sets_.size());
  for (std::size_t k = 0; k < sets_.size(); ++k) rate[k].assign(sets_[k].points.size(), 0.0);
  for (std::size_t s = 0; s < segment_set_.size(); ++s) {
    const std::size_t i = segment_node_[2 * s], j = segment_node_[2 * s + 1];
    double xi[D], xj[D], vi[D], vj[D];
    bar_node_position(x, i, xi);
    bar_node_position(x, j, xj);
    bar_node_velocity(v, i, vi);
    bar_node_velocity(v, j, vj);
    double d = 0.0;
    if (sets_[segment_set_[s]].hoop) {
      // Ring strain rate v_r / r at the segment centre, mid-step geometry.
      const double r_half = 0.5 * (xi[0] + xj[0]) - 0.25 * dt * (vi[0] + vj[0]);
      d = 0.5 * (vi[0] + vj[0]) / r_half;
      axial_strain_[s] = std::log(0.5 * (xi[0] + xj[0]) / reference_length_[s]);
    } else {
      double dx[D], lh = 0.0, l = 0.0, dv_e = 0.0;
      for (int c = 0; c < D; ++c) {
        dx[c] = (xj[c] - xi[c]) - 0.5 * dt * (vj[c] - vi[c]);
        lh += dx[c] * dx[c];
        l += (xj[c] - xi[c]) * (xj[c] - xi[c]);
      }
      lh = std::sqrt(lh);
      for (int c = 0; c < D; ++c) dv_e += (vj[c] - vi[c]) * dx[c] / lh;
      d = dv_e / lh;
      axial_strain_[s] = std::log(std::sqrt(l) / reference_length_[s]);
      sets_[segment_set_[s]].points.characteristic_length[segment_point_[s]] = std::sqrt(l);
    }
    rate[segment_set_[s]][segment_point_[s]] = d;
  }
  for (std::size_t k = 0; k < sets_.size(); ++k) update_set(sets_[k], rate[k], dt, time);
}

template <int D>
void EmbeddedBars<D>::update_set(Set& set, const std::vector<double>& axial_rate, double dt, double time) {
  MaterialPoints& pts = set.points;
  const std::size_t n = pts.size();
  if (n == 0) return;
  const MaterialPoints start = pts;
  const MaterialContext ctx{dt, time};
  std::vector<double> lateral(n), residual(n), lateral_old(n), residual_old(n);
  // Lateral stress after the update with the lateral rates `lateral`.
  auto evaluate = [&]() {
    pts = start;
    for (std::size_t p = 0; p < n; ++p) {
      const double volumetric = axial_rate[p] + 2.0 * lateral[p];
      pts.density_previous[p] = start.density[p];
      pts.density[p] = start.density[p] / (1.0 + volumetric * dt);
      pts.strain_rate[p] = SymTensor{axial_rate[p], lateral[p], lateral[p], 0.0, 0.0, 0.0};
      pts.spin[p] = Spin{};
      pts.artificial_viscosity[p] = 0.0;
    }
    set.material->update(pts, ctx);
    for (std::size_t p = 0; p < n; ++p) residual[p] = pts.deviator[p].yy - pts.pressure[p];
  };
  // Elastic lateral stiffness d(sigma_l)/d(d_l dt) with both lateral rates equal: 2K + 2G/3.
  const double stiffness = 2.0 * set.bulk_modulus + 2.0 * set.shear_modulus / 3.0;
  // Converged to round-off, not to an engineering tolerance: where the iteration stops depends on
  // the last bits of its input, and stopping at 1e-7 of the axial stress made a bar's stress jump
  // by that much between runs whose positions differ by one ulp (on MPI ranks: 1e-8 to 1e-7 of the
  // largest stress after 400 cycles of an RC beam). The secant is exact in the elastic range and
  // superlinear in the plastic one: 0.62 iterations per update on average in `coarse`, 0.50 at
  // 1e-7. The floor: an equation of state resolves pressure in steps of about K times one ulp of
  // the density ratio (3e-5 Pa for steel); 1e-14 of the stiffness is a hundred of them.
  const double floor = 1e-14 * stiffness;  // Pa
  auto converged = [&](std::size_t p) {
    const double axial = std::abs(pts.deviator[p].xx - pts.pressure[p]);
    return std::abs(residual[p]) <= 1e-12 * axial + floor;
  };
  for (std::size_t p = 0; p < n; ++p) lateral[p] = set.lateral_ratio[p] * axial_rate[p];
  evaluate();
  for (int iteration = 0; iteration < 6; ++iteration) {
    bool all = true;
    for (std::size_t p = 0; p < n; ++p) all = all && converged(p);
    if (all) break;
    for (std::size_t p = 0; p < n; ++p) {
      const double step = iteration > 0 && residual[p] != residual_old[p]
                              ? -residual[p] * (lateral[p] - lateral_old[p]) / (residual[p] - residual_old[p])
                              : -residual[p] / (stiffness * dt);
      lateral_old[p] = lateral[p];
      residual_old[p] = residual[p];
      if (!converged(p)) lateral[p] += step;
    }
    evaluate();
  }
  for (std::size_t p = 0; p < n; ++p)
    if (std::abs(axial_rate[p]) > 1e-12 && std::isfinite(lateral[p] / axial_rate[p]))
      set.lateral_ratio[p] = lateral[p] / axial_rate[p];
}

template <int D>
double EmbeddedBars<D>::internal_energy() const {
  double e = 0.0;
  for (std::size_t s = 0; s < segment_set_.size(); ++s)
    e += segment_mass_[s] * sets_[segment_set_[s]].points.specific_energy[segment_point_[s]];
  return e;
}

template <int D>
double EmbeddedBars<D>::stable_time_step(const double* x, std::size_t& segment) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < segment_set_.size(); ++s) {
    const Set& set = sets_[segment_set_[s]];
    const std::size_t i = segment_node_[2 * s], j = segment_node_[2 * s + 1];
    double xi[D], xj[D];
    bar_node_position(x, i, xi);
    bar_node_position(x, j, xj);
    double l = 0.0;
    if (set.hoop) {
      l = 0.5 * (xi[0] + xj[0]);  // a ring's breathing mode: omega = c / r
    } else {
      for (int c = 0; c < D; ++c) l += (xj[c] - xi[c]) * (xj[c] - xi[c]);
      l = std::sqrt(l);
    }
    const double t = l / set.points.wave_speed(segment_point_[s]);
    if (t < best || !(t >= 0.0)) {
      best = t >= 0.0 ? t : -1.0;
      segment = s;
    }
  }
  return best;
}

template <int D>
const std::string& EmbeddedBars<D>::set_name(std::size_t s) const {
  return sets_[segment_set_[s]].name;
}

template <int D>
double EmbeddedBars<D>::axial_stress(std::size_t s) const {
  const MaterialPoints& pts = sets_[segment_set_[s]].points;
  const std::size_t p = segment_point_[s];
  return pts.deviator[p].xx - pts.pressure[p];
}

template <int D>
double EmbeddedBars<D>::axial_force(std::size_t s) const {
  const Set& set = sets_[segment_set_[s]];
  const std::size_t p = segment_point_[s];
  // sigma A with A = V / L: the ring's cross-section for hoop bars (V / (2 pi r)).
  const double volume = segment_mass_[s] / set.points.density[p];
  const double l = set.points.characteristic_length[p];
  const double length = set.hoop ? two_pi * reference_length_[s] * std::exp(axial_strain_[s]) : l;
  return axial_stress(s) * volume / length;
}

template <int D>
double EmbeddedBars<D>::plastic_strain(std::size_t s) const {
  return sets_[segment_set_[s]].points.plastic_strain[segment_point_[s]];
}

template <int D>
double EmbeddedBars<D>::plastic_strain_rate(std::size_t s) const {
  return sets_[segment_set_[s]].points.plastic_strain_rate[segment_point_[s]];
}

template <int D>
double EmbeddedBars<D>::temperature(std::size_t s) const {
  return sets_[segment_set_[s]].points.temperature[segment_point_[s]];
}

template <int D>
const MaterialPoints& EmbeddedBars<D>::points_of(std::size_t s, std::size_t& point) const {
  point = segment_point_[s];
  return sets_[segment_set_[s]].points;
}

template class EmbeddedBars<2>;
template class EmbeddedBars<3>;

}  // namespace camouflet
