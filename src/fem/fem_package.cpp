// The FEM package's stages (fem_package.hpp): the node passes, the material
// update of its batches, erosion, the element state the next forces read, the
// element vote and the snapshot fields.
#include "fem/fem_package.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fem/parallel.hpp"
#include "model/domain_box.hpp"

namespace camouflet {

template <int D>
void FemPackage<D>::begin_step(const StepClock&) {
  // The node passes of the previous step zeroed force and hourglass_force_previous as they read
  // them for the last time (forces_zeroed); otherwise zero them here.
  if (!forces_zeroed) std::fill(force.begin(), force.end(), 0.0);
  ring_factor_ = nullptr;
  if (!elements.area_weighted_momentum()) return;
  elements.update_ring_factors(position.data());
  ring_factor_ = elements.ring_factors().data();
}

template <int D>
void FemPackage<D>::add_element_forces(double dt_previous) {
  double* f_hourglass = nullptr;
  if (!hourglass_force.empty()) {
    hourglass_force.swap(hourglass_force_previous);
    if (!forces_zeroed) std::fill(hourglass_force.begin(), hourglass_force.end(), 0.0);
    f_hourglass = hourglass_force.data();
  }
  forces_zeroed = false;
  hourglass_stored =
      elements.add_internal_forces(position.data(), velocity.data(), force.data(), f_hourglass, hourglass, dt_previous);
  // The viscous hourglass forces stay each rank's own share: their work (drift_nodes) is the sum
  // of the shares' over the ranks, as the serial sum is over the elements.
  // The bars' forces join the sum: on ranks a segment is stepped by one rank, and other ranks
  // hold some of its host nodes too.
  if (!bars.empty()) bars.add_forces(position.data(), force.data());
  if (sharing_) sharing_->sum_shared(force, D);
}

template <int D>
void FemPackage<D>::kick_nodes(double dt_mean) {
  const std::int64_t nn = static_cast<std::int64_t>(node_mass.size());
#pragma omp parallel for schedule(static) if (nn > parallel_threshold_nodes)
  for (std::int64_t n = 0; n < nn; ++n) {
    const double inv_m =
        node_mass[static_cast<std::size_t>(n)] > 0.0 ? 1.0 / node_mass[static_cast<std::size_t>(n)] : 0.0;
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      const double a = force[k] * inv_m;
      force[k] = 0.0;  // its last use: zeroed for the next begin_forces
      acceleration[k] = a;
      velocity_old[k] = velocity[k];
      velocity[k] += a * dt_mean;
    }
  }
}

template <int D>
typename FemPackage<D>::Drift FemPackage<D>::drift_nodes(double dt_minus, double dt_mean, double dt) {
  // Kinetic energy at t_n in the form the central difference conserves:
  // (1/2) m (v_n^2 - a^2 dt-^2 / 4) with v_n = v(n-1/2) + a dt- / 2 and a the
  // applied (constrained) acceleration; for equal steps it is (1/2) m
  // v(n-1/2) . v(n+1/2), and a short next step (landing on the end time)
  // does not disturb it. The viscous hourglass work from t_(n-1) to t_n is the
  // trapezoid of its forces against v(n-1/2), the same centring as the
  // internal energy's.
  // The same pass moves each node (x(n+1) = x(n) + v(n+1/2) dt) and tests it
  // (the driver's node check): the node arrays are read once. The energy sums
  // keep their grouping (one thread's share per contiguous block of nodes).
  const std::int64_t nn = static_cast<std::int64_t>(node_mass.size());
  const bool with_hourglass = !hourglass_force.empty();
  const RunControl& run = model_->run;
  const char* owned = owned_nodes();  // on ranks, a shared node's kinetic energy counts once
  double kinetic = 0.0, hourglass_power = 0.0;
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
#pragma omp parallel for schedule(static) reduction(+ : kinetic, hourglass_power) reduction(min : bad) if (nn > parallel_threshold_nodes)
  for (std::int64_t n = 0; n < nn; ++n) {
    double vv = 0.0, fv = 0.0;
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      const double a = (velocity[k] - velocity_old[k]) / dt_mean;
      const double v_n = velocity_old[k] + 0.5 * a * dt_minus;
      vv += v_n * v_n - 0.25 * a * a * dt_minus * dt_minus;
      if (with_hourglass) {
        fv += 0.5 * (hourglass_force[k] + hourglass_force_previous[k]) * velocity_old[k];
        hourglass_force_previous[k] = 0.0;  // its last use: the next add_element_forces fills it
      }
    }
    if (!owned || owned[n]) kinetic += 0.5 * node_mass[static_cast<std::size_t>(n)] * vv;
    hourglass_power -= fv;
    bool ok = true;
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      const double dx = velocity[k] * dt;
      position[k] += dx;
      displacement[k] += dx;
      ok = ok && std::isfinite(velocity[k]);
    }
    if (!ok || first_outside_domain<D>(run, &position[static_cast<std::size_t>(n * D)]) >= 0) bad = std::min(bad, n);
  }
  hourglass_dissipated += hourglass_power * dt_minus;
  forces_zeroed = true;  // force in kick, hourglass_force_previous above
  return {kinetic, bad == std::numeric_limits<std::int64_t>::max() ? -1 : bad};
}

template <int D>
void FemPackage<D>::update_materials(const MaterialContext& context) {
  for (std::size_t m = 0; m < batches.size(); ++m)
    if (batches[m].size() > 0) model_->materials[m].material->update(batches[m], context);
}

template <int D>
void FemPackage<D>::update_bars(double dt, double time) {
  if (!bars.empty()) bars.update(position.data(), velocity.data(), dt, time);
}

template <int D>
bool FemPackage<D>::erode(double dt, double& eroded_energy) {
  if (!erosion) return false;
  const std::size_t eroded_before = eroded_count;
  const std::size_t ne = elements.size();
  for (std::size_t e = 0; e < ne; ++e) {
    if (elements.eroded[e]) continue;
    const auto m = static_cast<std::size_t>(elements.material[e]);
    const ErosionCriteria criteria = model_->erosion_of(m);
    if (!criteria.enabled()) continue;
    MaterialPoints& pts = batches[m];
    const std::size_t p = elements.point[e];
    bool erode_it = criteria.damage > 0.0 && pts.damage[p] >= criteria.damage;
    if (criteria.geometric_strain > 0.0) {
      // Geometric strain: the equivalent of the total strain summed from the
      // strain rates, sqrt(2/3 eps:eps) (the Autodyn "geometric strain").
      SymTensor& eps = total_strain[e];
      eps += pts.strain_rate[p] * dt;
      erode_it = erode_it || std::sqrt(2.0 / 3.0 * contract(eps, eps)) >= criteria.geometric_strain;
    }
    if (!erode_it) continue;
    // The mass stays on the nodes (momentum and kinetic energy are kept); the
    // internal energy the element holds leaves the internal sum for the eroded one.
    elements.eroded[e] = 1;
    eroded_energy += elements.mass[e] * pts.specific_energy[p];
    pts.deviator[p] = SymTensor{};
    pts.pressure[p] = 0.0;
    pts.strain_rate[p] = SymTensor{};
    pts.spin[p] = Spin{};
    pts.artificial_viscosity[p] = 0.0;
    pts.density_previous[p] = pts.density[p];
    elements.viscosity[e] = 0.0;
    ++eroded_count;
  }
  return eroded_count != eroded_before;
}

template <int D>
typename FemPackage<D>::State FemPackage<D>::gather_state() {
  const std::int64_t ne = static_cast<std::int64_t>(elements.size());
  double internal = 0.0;
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
  // The same static split and per-thread sums as a parallel for; each thread
  // keeps the batch of its previous element, so the batch is looked up only
  // where the material changes.
#pragma omp parallel reduction(+ : internal) reduction(min : bad) if (ne > parallel_threshold)
  {
    int batch_index = -1;
    const MaterialPoints* pts = nullptr;
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < ne; ++k) {
      const std::size_t e = static_cast<std::size_t>(k);
      if (elements.eroded[e]) {
        elements.stress[e] = SymTensor{};  // its energy went to EnergyBalance::eroded
        continue;
      }
      if (elements.material[e] != batch_index) {
        batch_index = elements.material[e];
        pts = &batches[static_cast<std::size_t>(batch_index)];
      }
      const std::size_t p = elements.point[e];
      const double pressure = pts->pressure[p];
      SymTensor s = pts->deviator[p];
      s.xx -= pressure;
      s.yy -= pressure;
      s.zz -= pressure;
      elements.stress[e] = s;
      elements.wave_speed[e] = pts->wave_speed(p);
      elements.stable_wave_speed[e] = pts->stable_wave_speed(p);
      const double energy = elements.mass[e] * pts->specific_energy[p];
      internal += energy;
      if (!std::isfinite(s.xx + s.yy + s.zz + s.xy + s.yz + s.zx) || !std::isfinite(elements.wave_speed[e]) ||
          !std::isfinite(energy))
        bad = std::min(bad, k);
    }
  }
  return {internal, bad == std::numeric_limits<std::int64_t>::max() ? -1 : bad};
}

template <int D>
typename FemPackage<D>::ElementVote FemPackage<D>::element_vote() const {
  const std::int64_t ne = static_cast<std::int64_t>(elements.size());
  double best = std::numeric_limits<double>::infinity();
  std::int64_t best_e = -1;
#pragma omp parallel if (ne > parallel_threshold)
  {
    double local = std::numeric_limits<double>::infinity();
    std::int64_t local_e = -1;
#pragma omp for schedule(static) nowait
    for (std::int64_t k = 0; k < ne; ++k) {
      const std::size_t e = static_cast<std::size_t>(k);
      if (elements.eroded[e]) continue;
      double t = elements.length[e] / (elements.stable_wave_speed[e] + elements.speed[e]);
      if (!(t >= 0.0)) t = -1.0;  // NaN: this element is reported as the collapse
      if (t < local) {
        local = t;
        local_e = k;
      }
    }
#pragma omp critical
    if (local_e >= 0 && (local < best || (local == best && local_e < best_e))) {
      best = local;
      best_e = local_e;
    }
  }
  return {best, best_e};
}

template <int D>
void FemPackage<D>::fill_snapshot(FieldSnapshot& s) const {
  const std::size_t ne = elements.size();
  element_pressure_.resize(ne);
  element_plastic_strain_.resize(ne);
  element_damage_.resize(ne);
  element_temperature_.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    const MaterialPoints& pts = batches[static_cast<std::size_t>(elements.material[e])];
    const std::size_t p = elements.point[e];
    element_pressure_[e] = pts.pressure[p];
    element_plastic_strain_[e] = pts.plastic_strain[p];
    element_damage_[e] = pts.damage[p];
    element_temperature_[e] = pts.temperature[p];
  }
  s.node_position = position;
  s.node_displacement = displacement;
  s.node_velocity = velocity;
  s.node_acceleration = acceleration;
  s.nodes_per_element = FemElements<D>::nodes;
  s.connectivity = elements.connectivity;
  s.element_density = elements.density;
  s.element_pressure = element_pressure_;
  s.element_stress = elements.stress;
  s.element_plastic_strain = element_plastic_strain_;
  s.element_damage = element_damage_;
  s.element_temperature = element_temperature_;
  s.element_material = elements.material;
}

template class FemPackage<2>;
template class FemPackage<3>;

}  // namespace camouflet
