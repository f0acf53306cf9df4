// The FEM package's side of Package<D> (fem_package.hpp): what the driver's stages call, the
// vote, the energies, the checks of the nodes and elements with their warnings, and its part in
// a dynamic relaxation.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "fem/fem_package.hpp"
#include "fem/parallel.hpp"
#include "model/domain_box.hpp"

namespace camouflet {

template <int D>
void FemPackage<D>::add_gravity(const std::array<double, 3>& g, double& power) {
  // The work of the constant force over the step t_(n-1) -> t_n is m g . v(n-1/2) dt(n-1/2),
  // exactly m g . (x_n - x_(n-1)): the loss of potential energy, the form the central
  // difference's kinetic energy at t_n balances. velocity still holds v(n-1/2) here.
  // On ranks every copy of a shared node takes the whole m g (the shares of the forces were
  // added up before), and only its owner counts the power.
  const std::int64_t nn = static_cast<std::int64_t>(node_mass.size());
  const char* owned = owned_nodes();
  double nodes = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : nodes) if (nn > parallel_threshold_nodes)
  for (std::int64_t n = 0; n < nn; ++n) {
    const double m = node_mass[static_cast<std::size_t>(n)];
    const bool counted = !owned || owned[n];
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      force[k] += m * g[static_cast<std::size_t>(i)];
      if (counted) nodes += m * g[static_cast<std::size_t>(i)] * velocity[k];
    }
  }
  power += nodes;
}

template <int D>
double FemPackage<D>::drift(const StepClock& clock) {
  const Drift d = drift_nodes(clock.dt, clock.dt_mean(), clock.dt_next);
  drift_bad_node_ = d.bad_node;
  nodes_checked_ = true;
  return d.kinetic;
}

template <int D>
NumericalError FemPackage<D>::node_failure(std::int64_t bad) const {
  const RunControl& run = model_->run;
  const auto n = static_cast<std::size_t>(bad);
  const double* x = &position[n * D];
  const double* v = &velocity[n * D];
  bool finite = true;
  for (int i = 0; i < D; ++i) finite = finite && std::isfinite(x[i]) && std::isfinite(v[i]);
  if (!finite)
    return NumericalError(EntityKind::node, node_id(bad), "velocity",
                          fmt::format("non-finite position or velocity (v = {})", position_text<D>(v)));
  const int axis = first_outside_domain<D>(run, x);
  return NumericalError(EntityKind::node, node_id(bad), "position",
                        fmt::format("left the domain box: coordinate {} = {:.6g} m outside [{:.6g}, {:.6g}] m",
                                    axis + 1, x[axis], run.domain_min[static_cast<std::size_t>(axis)],
                                    run.domain_max[static_cast<std::size_t>(axis)]));
}

template <int D>
void FemPackage<D>::check() const {
  if (drift_bad_node_ >= 0) throw node_failure(drift_bad_node_);
  if (nodes_checked_) return;  // the node pass tested them, and nothing wrote them since
  const std::int64_t nn = static_cast<std::int64_t>(node_mass.size());
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
#pragma omp parallel for schedule(static) reduction(min : bad) if (nn > 20000)
  for (std::int64_t n = 0; n < nn; ++n) {
    const double* x = &position[static_cast<std::size_t>(n * D)];
    const double* v = &velocity[static_cast<std::size_t>(n * D)];
    bool ok = first_outside_domain<D>(model_->run, x) < 0;
    for (int i = 0; i < D; ++i) ok = ok && std::isfinite(v[i]);
    if (!ok) bad = std::min(bad, n);
  }
  if (bad != std::numeric_limits<std::int64_t>::max()) throw node_failure(bad);
}

template <int D>
void FemPackage<D>::update_state(const StepClock& clock, EnergyBalance& energy) {
  report_axis_crossings(clock);
  const KinematicsResult r =
      elements.kinematics(position.data(), velocity.data(), velocity_old.data(), clock.dt, viscosity, batches);
  energy.viscous += r.viscous_work;
  if (r.bad_element >= 0)
    throw NumericalError(
        EntityKind::element, element_id(r.bad_element), "volume",
        fmt::format("volume {:.6g} m^3 is not positive (element inverted or collapsed)", r.bad_volume));
  if (r.tangled_element >= 0) report_tangled(r, clock);
  update_materials({clock.dt, clock.time});  // EOS + strength + damage, one call per material batch
  update_bars(clock.dt, clock.time);         // the bars' uniaxial-stress update
  erode(clock.dt, energy.eroded);            // the couplings follow (eroded_count)
  gather_and_check();
}

template <int D>
void FemPackage<D>::start() {
  // The first step votes with the initial velocities like every later one (the kinematics that
  // measure |v| have not run yet).
  elements.set_speeds(velocity.data());
  nodes_checked_ = false;
  gather_and_check();
}

template <int D>
void FemPackage<D>::gather_and_check() {
  const State state = gather_state();
  element_internal_ = state.internal;
  if (state.bad_element < 0) return;
  const auto e = static_cast<std::size_t>(state.bad_element);
  const MaterialPoints& pts = batches[static_cast<std::size_t>(elements.material[e])];
  const std::size_t p = elements.point[e];
  throw NumericalError(EntityKind::element, element_id(state.bad_element), "stress",
                       fmt::format("non-finite state: pressure {} Pa, specific energy {} J/kg, sound speed {} m/s",
                                   pts.pressure[p], pts.specific_energy[p], pts.sound_speed[p]));
}

template <int D>
void FemPackage<D>::report_tangled(const KinematicsResult& r, const StepClock& clock) {
  // Not fatal: the buried-structure cases tangle an element now and then (docs/reliability.md);
  // a run must not carry one silently. Each newly tangled element is reported, at most 20 lines.
  const std::int64_t id = element_id(r.tangled_element);
  Reports& w = reports_;
  if (w.first_tangled_cycle < 0) w.first_tangled_element = id, w.first_tangled_cycle = clock.cycle;
  if (id != w.last_tangled_element && w.tangled_lines < 20) {
    ++w.tangled_lines;
    fmt::print(stderr,
               "warning: element {} ({}) at cycle {}, time {:.6e} s: {} of its 4 corner Jacobians are "
               "negative: its edges cross (element tangled, a bow-tie; its area is still positive){}\n",
               id, describe(EntityKind::element, id), clock.cycle, clock.time, r.tangled_corners,
               w.tangled_lines == 20 ? " (no more such warnings)" : "");
  }
  w.last_tangled_element = id;
}

template <int D>
void FemPackage<D>::report_axis_crossings(const StepClock& clock) {
  // r-z: a node that has moved to r < 0 has crossed the axis; the ring volumes around it stop
  // meaning anything (join-face nodes next to the axis were once driven across it, and the run
  // went on for 20 ms with inverted elements, unreported, since the element centres stayed at
  // r > 0). Reported like a tangled element (a warning naming the node, cycle and time, at most 20
  // lines), not fatal: the rest of the model is still meaningful, and the buried-structure cases
  // reach it (docs/reliability.md). Nodes that start on the axis keep r = 0 exactly (the axis
  // condition); a node at r0 > 0 counts from the step that takes it below r = 0.
  if (D != 2 || model_->run.mode != GeometryMode::axisymmetric) return;
  Reports& w = reports_;
  const std::size_t nn = node_mass.size();
  if (w.axis_reported.size() != nn) w.axis_reported.assign(nn, 0);
  for (std::size_t n = 0; n < nn; ++n) {
    if (!(position[n * D] < 0.0 && displacement[n * D] < 0.0) || w.axis_reported[n]) continue;
    w.axis_reported[n] = 1;
    const std::int64_t id = node_id(static_cast<std::int64_t>(n));
    if (w.first_axis_cycle < 0) w.first_axis_node = id, w.first_axis_cycle = clock.cycle;
    if (w.axis_lines >= 20) continue;
    ++w.axis_lines;
    fmt::print(stderr,
               "warning: node {} ({}) at cycle {}, time {:.6e} s: crossed the axis of the axisymmetric model "
               "(r = {:.6g} m; it started at r = {:.6g} m): the elements around it are inverted{}\n",
               id, describe(EntityKind::node, id), clock.cycle, clock.time, position[n * D],
               position[n * D] - displacement[n * D], w.axis_lines == 20 ? " (no more such warnings)" : "");
  }
}

template <int D>
typename Package<D>::Vote FemPackage<D>::vote() const {
  const ElementVote best = element_vote();
  typename Package<D>::Vote vote;
  vote.dt = best.dt;
  if (best.element >= 0) {
    const auto e = static_cast<std::size_t>(best.element);
    vote.reason = fmt::format("element {} ({}): l/(c+|v|)", element_id(best.element),
                              model_->materials[static_cast<std::size_t>(elements.material[e])].name);
    vote.kind = EntityKind::element;
    vote.id = element_id(best.element);
    vote.detail = fmt::format("l = {:.6g} m, c = {:.6g} m/s, |v| = {:.6g} m/s", elements.length[e],
                              elements.stable_wave_speed[e], elements.speed[e]);
  }
  if (!bars.empty()) {
    std::size_t s = 0;
    const double t = bars.stable_time_step(position.data(), s);
    if (t < vote.dt || !(t >= 0.0)) {
      vote = {};
      vote.dt = t;
      vote.reason = fmt::format("bar '{}' segment {}: L/c", bars.set_name(s), bars.segment_in_set(s) + 1);
    }
  }
  return vote;
}

template <int D>
double FemPackage<D>::kinetic_energy() const {
  const char* owned = owned_nodes();
  double kinetic = 0.0;
  for (std::size_t n = 0; n < node_mass.size(); ++n)
    if (!owned || owned[n])
      for (int i = 0; i < D; ++i)
      kinetic += 0.5 * node_mass[n] * velocity[n * D + static_cast<std::size_t>(i)] *
                 velocity[n * D + static_cast<std::size_t>(i)];
  return kinetic;
}

template <int D>
std::int64_t FemPackage<D>::local_index(EntityKind kind, std::int64_t id) const {
  if (!sharing_) return id - 1;
  const std::vector<std::int64_t>& global =
      kind == EntityKind::element ? sharing_->global_elements() : sharing_->global_nodes();
  const auto it = std::lower_bound(global.begin(), global.end(), id - 1);
  return it != global.end() && *it == id - 1 ? it - global.begin() : -1;
}

template <int D>
std::string FemPackage<D>::describe(EntityKind kind, std::int64_t id) const {
  if (id < 1 || (kind != EntityKind::element && kind != EntityKind::node)) return {};
  const std::int64_t local = local_index(kind, id);
  if (local < 0) return {};
  const auto k = static_cast<std::size_t>(local);
  if (kind == EntityKind::element && k < elements.size()) {
    constexpr int N = FemElements<D>::nodes;
    double c[D] = {};
    for (int a = 0; a < N; ++a)
      for (int i = 0; i < D; ++i)
        c[i] += position[static_cast<std::size_t>(elements.connectivity[k * N + static_cast<std::size_t>(a)] * D + i)] /
                N;
    return fmt::format("material '{}', centre {}", model_->materials[static_cast<std::size_t>(elements.material[k])].name,
                       position_text<D>(c));
  }
  if (kind == EntityKind::node && k < node_mass.size())
    return fmt::format("position {}", position_text<D>(&position[k * D]));
  return {};
}

template <int D>
void FemPackage<D>::scale_velocities(double factor) {
  for (double& v : velocity) v *= factor;
}

template <int D>
void FemPackage<D>::hold_still(const std::vector<char>& held_material) {
  if (held_material != held_material_) {  // the nodes of the held materials' elements, once
    held_material_ = held_material;
    held_nodes_.clear();
    constexpr int N = FemElements<D>::nodes;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const auto m = static_cast<std::size_t>(elements.material[e]);
      if (m < held_material.size() && held_material[m])
        for (int a = 0; a < N; ++a) held_nodes_.push_back(elements.connectivity[e * N + static_cast<std::size_t>(a)]);
    }
    std::sort(held_nodes_.begin(), held_nodes_.end());
    held_nodes_.erase(std::unique(held_nodes_.begin(), held_nodes_.end()), held_nodes_.end());
  }
  for (const std::int64_t n : held_nodes_)
    for (int i = 0; i < D; ++i) velocity[static_cast<std::size_t>(n * D + i)] = 0.0;
}

template <int D>
void FemPackage<D>::come_to_rest() {
  for (auto* field : {&velocity, &velocity_old, &acceleration, &displacement})
    std::fill(field->begin(), field->end(), 0.0);
  hourglass_dissipated = 0.0;
  nodes_checked_ = false;
}

template class FemPackage<2>;
template class FemPackage<3>;

}  // namespace camouflet
