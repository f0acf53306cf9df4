#include "solver/solver.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "fem/parallel.hpp"

namespace camouflet {

template <int D>
Solver<D>::Solver(const Model& model) : model_(model), mode_(model.run.mode), fem_(model) {
  boundaries_ = Boundaries<D>(model, fem_);
  boundaries_.constrain(fem_.velocity, 0.0);

  // SPH particles: same materials, own batches (sph/sph_package.hpp), mirrored in the planes the
  // boundaries give them.
  if (model.particles.count() > 0) {
    auto particles = std::make_unique<sph::SphPackage<D>>(model, boundaries_.mirror_planes());
    coupling_ = std::make_unique<SphFemCoupling<D>>(model, fem_, *particles);
    particles->add_forces(0.0);
    sph_ = particles.get();
    register_package(std::move(particles));
  } else {
    SlidingContact<D> contact(model);  // refuses contacts of a model without particles, naming them
  }

  // The first step votes with the initial velocities like every later one
  // (the kinematics that measure |v| have not run yet).
  fem_.elements.set_speeds(fem_.velocity.data());
  gather_element_state();
  // The transmitting boundaries' static load, from the initial stresses gathered above.
  boundaries_.hold_initial_state(fem_, model.run.gravity, model.run.has_gravity(), false);
  start_energy_and_step();
}

template <int D>
void Solver<D>::set_initial_velocity(const std::vector<double>& v) {
  if (cycle_ != 0 || v.size() != fem_.velocity.size())
    throw std::logic_error("set_initial_velocity: before the first step, one value per node and component");
  fem_.velocity = v;
  boundaries_.constrain(fem_.velocity, 0.0);
  fem_.elements.set_speeds(fem_.velocity.data());
  nodes_checked_cycle_ = -1;
  start_energy_and_step();
}

template <int D>
void Solver<D>::start_energy_and_step() {
  choose_time_step();
  const Model& model = model_;
  if (model.run.initial_dt > 0.0) {
    dt_next_ = std::min(model.run.initial_dt, model.run.max_dt);
    limit_.dt = dt_next_;
    limit_.reason = "initial_dt";
  }
  const std::size_t nn = fem_.node_mass.size();
  double kinetic = 0.0;
  for (std::size_t n = 0; n < nn; ++n)
    for (int i = 0; i < D; ++i)
      kinetic += 0.5 * fem_.node_mass[n] * fem_.velocity[n * D + static_cast<std::size_t>(i)] *
                 fem_.velocity[n * D + static_cast<std::size_t>(i)];
  kinetic += package_kinetic_energy();
  energy_.kinetic = kinetic;
  energy_.internal = internal_energy_;
  // The stiffness-form hourglass energy is nought at t = 0 unless a relaxation stored some.
  energy_.initial_total = kinetic + internal_energy_ + fem_.hourglass_stored;
}

template <int D>
void Solver<D>::limit_next_step(double dt_max) {
  if (dt_max > 0.0 && dt_max < dt_next_) dt_next_ = dt_max;
}

template <int D>
void Solver<D>::step() {
  try {
    // The state at t_n: a NaN is named before forces spread it. FEM-only
    // models skip the nodes that the previous step's node pass checked.
    if (!packages_.empty() || !fem_.bars.empty() || nodes_checked_cycle_ != cycle_) check_nodes_and_packages();
    // Forces at t_n.
    add_element_forces();          // FEM: face loads, element stresses and hourglass control (fem/)
    add_package_forces();          // packages: SPH's particle sums and accelerations (sph/), the others'
    add_coupling_forces();         // the join's reactions and the sliding contact (coupling/)
    add_gravity();                 // m g on nodes and on every package's points, its work (gravity.cpp)
    add_static_boundary_forces();  // the transmitting boundaries' static hold (gravity.cpp)
    fem_.add_bar_forces();         // embedded reinforcement bars onto their host nodes
    // Velocities at t_(n+1/2).
    fem_.kick(centred_step());  // FEM: a = F / m, v(n+1/2) by the central difference
    kick_packages();            // packages: v(n+1/2) (SPH: the pair heating), their own constraints
    constrain_velocities();     // dashpots, fixed, prescribed, symmetry, axis; the join settles
    // Energies at t_n and positions at t_(n+1).
    drift_packages();                  // packages: centred kinetic energy, x(n+1)
    drift_nodes_and_account_energy();  // FEM: x(n+1) = x(n) + v(n+1/2) dt; the energy balance at t_n
    advance_clock();                   // t_(n+1), the cycle count, dt(n+1/2)
    check_drifted_nodes();             // finite and inside the domain box (found by the drift's pass)
    check_packages();                  // packages: every point sound (SPH: finite, inside the box)
    check_axis_crossings();            // r-z: a node across the axis is reported (a warning)
    // Kinematics and material state at t_(n+1).
    update_packages();       // packages (SPH: eta, rho, h, D, W, material update), before the elements'
    element_kinematics();    // FEM: V, rho at t_(n+1); D, W, q at mid-step
    fem_.update_materials({dt_, time_});  // FEM: EOS + strength + damage, one call per material batch
    fem_.update_bars(dt_, time_);         // embedded bars: uniaxial-stress material update
    erode_elements();        // elements past their material's erosion threshold (the join follows)
    gather_element_state();  // sigma = s - p I, wave speeds, internal energy, dt vote
    choose_time_step();      // dt(n+3/2) = CFL min l / (c + |v|), growth limited
  } catch (NumericalError& error) {
    if (error.cycle() < 0) error.set_context(cycle_, time_, describe(error.kind(), error.id()));
    throw;
  }
}

template <int D>
void Solver<D>::fail(NumericalError error) const {
  error.set_context(cycle_, time_, describe(error.kind(), error.id()));
  throw error;
}

template <int D>
void Solver<D>::add_element_forces() {
  // Loads first, then the elements' forces: each node's force sums them in that order.
  const double* ring_factor = fem_.begin_forces();
  boundaries_.add_loads(fem_, time_, ring_factor);
  fem_.add_element_forces(dt_);
}

template <int D>
void Solver<D>::constrain_velocities() {
  const double dt_mean = centred_step();
  if (relaxing_) hold_charges_still();
  // Dashpots, then fixed, prescribed, symmetry and axis nodes (boundary/boundaries.hpp).
  const typename Boundaries<D>::Work work = boundaries_.constrain(fem_, time_ + 0.5 * dt_next_, dt_, dt_mean, relaxing_);
  energy_.boundary_work += work.transmitting;
  split_.transmitting += work.transmitting;
  energy_.boundary_work += work.constraints;
  split_.constraints += work.constraints;
  if (coupling_) {  // the join settles; its work and the contact's (coupling/sph_fem_coupling.hpp)
    const typename SphFemCoupling<D>::Powers powers = coupling_->settle(dt_mean);
    split_.join_face += powers.join_face_work;
    energy_.boundary_work += (powers.join + powers.contact) * dt_mean;
    split_.join += powers.join * dt_mean;
    split_.contact += powers.contact * dt_mean;
  }
}

template <int D>
void Solver<D>::drift_nodes_and_account_energy() {
  // The nodes' pass (FemPackage::drift) gives their centred kinetic energy at t_n; the
  // packages' was taken in drift_packages. check_drifted_nodes reports a failed node once the
  // clock has moved on.
  const typename FemPackage<D>::Drift drift = fem_.drift(dt_, centred_step(), dt_next_);
  EnergyBalance& e = energy_;
  e.kinetic = drift.kinetic;
  if (!packages_.empty()) e.kinetic += package_kinetic_;
  e.internal = internal_energy_;
  e.hourglass = fem_.hourglass_energy();
  const double total = e.kinetic + e.internal + e.hourglass + e.eroded;
  const double scale = std::max(e.initial_total + std::abs(e.boundary_work), std::abs(total));
  e.relative_error = scale > 0.0 ? std::abs(total - e.initial_total - e.boundary_work) / scale : 0.0;
  drifted_bad_node_ = drift.bad_node;
}

template <int D>
void Solver<D>::advance_clock() {
  dt_ = dt_next_;
  time_ += dt_;
  ++cycle_;
}

template <int D>
void Solver<D>::check_drifted_nodes() {
  if (drifted_bad_node_ >= 0) fail_node(drifted_bad_node_);
  nodes_checked_cycle_ = cycle_;
}

template <int D>
void Solver<D>::element_kinematics() {
  const KinematicsResult r = fem_.kinematics(dt_);
  energy_.viscous += r.viscous_work;
  if (r.bad_element >= 0)
    fail(NumericalError(
        EntityKind::element, r.bad_element + 1, "volume",
        fmt::format("volume {:.6g} m^3 is not positive (element inverted or collapsed)", r.bad_volume)));
  if (r.tangled_element >= 0) {
    // Not fatal: the buried-structure cases tangle an element now and then
    // (docs/reliability.md); a run must not carry one silently. Each newly tangled element is
    // reported, at most 20 lines.
    const std::int64_t id = r.tangled_element + 1;
    if (first_tangled_cycle_ < 0) first_tangled_element_ = id, first_tangled_cycle_ = cycle_;
    if (id != last_tangled_element_ && tangled_reports_ < 20) {
      ++tangled_reports_;
      fmt::print(stderr,
                 "warning: element {} ({}) at cycle {}, time {:.6e} s: {} of its 4 corner Jacobians are "
                 "negative: its edges cross (element tangled, a bow-tie; its area is still positive){}\n",
                 id, describe(EntityKind::element, id), cycle_, time_, r.tangled_corners,
                 tangled_reports_ == 20 ? " (no more such warnings)" : "");
    }
    last_tangled_element_ = id;
  }
}

template <int D>
void Solver<D>::gather_element_state() {
  const typename FemPackage<D>::State state = fem_.gather_state();
  // Elements, packages, bars: the packages' sum is SPH's own share when it is the only one.
  const double packages = package_internal_energy();
  split_.bar_internal = fem_.bars.internal_energy();
  internal_energy_ = state.internal + packages + split_.bar_internal;
  if (state.bad_element >= 0) {
    const std::int64_t bad = state.bad_element;
    const std::size_t e = static_cast<std::size_t>(bad);
    const MaterialPoints& pts = fem_.batches[static_cast<std::size_t>(fem_.elements.material[e])];
    const std::size_t p = fem_.elements.point[e];
    fail(NumericalError(
        EntityKind::element, bad + 1, "stress",
        fmt::format("non-finite state: pressure {} Pa, specific energy {} J/kg, sound speed {} m/s",
                    pts.pressure[p], pts.specific_energy[p], pts.sound_speed[p])));
  }
}

template <int D>
void Solver<D>::choose_time_step() {
  // Smallest l / (c + |v|) over the elements (the lowest index on a tie), the particles and the bars.
  const typename FemPackage<D>::Vote vote = fem_.element_vote();
  const double best = vote.dt;
  const std::int64_t best_e = vote.element;
  const RunControl& run = model_.run;
  double dt = run.cfl * best;
  std::string reason;
  if (best_e >= 0) {
    const auto m = static_cast<std::size_t>(fem_.elements.material[static_cast<std::size_t>(best_e)]);
    reason = fmt::format("element {} ({}): l/(c+|v|)", best_e + 1, model_.materials[m].name);
  }
  vote_packages(dt, reason);
  if (!fem_.bars.empty()) {
    std::size_t s = 0;
    const double t = fem_.bars.stable_time_step(fem_.position.data(), s);
    if (run.cfl * t < dt || !(t >= 0.0)) {
      dt = run.cfl * t;
      reason = fmt::format("bar '{}' segment {}: L/c", fem_.bars.set_name(s), s + 1);
    }
  }
  // Hold the step while the limit sits within 2 % above it: a step that
  // follows |v| every cycle pumps energy in or out of a vibration (the
  // central difference conserves energy only between changes of dt).
  if (dt_ > 0.0 && dt >= dt_ && dt < 1.02 * dt_ && dt_ <= run.max_dt) dt = dt_;
  if (dt_ > 0.0 && dt > run.dt_growth * dt_) {
    dt = run.dt_growth * dt_;
    reason = "growth limit dt_growth";
  }
  if (dt > run.max_dt) {
    dt = run.max_dt;
    reason = "max_dt";
  }
  if (!(dt > run.min_dt) || !std::isfinite(dt)) {
    if (best_e >= 0 && (packages_.empty() || reason.rfind("element", 0) == 0))
      fail(NumericalError(
          EntityKind::element, best_e + 1, "time step",
          fmt::format("dt {:.6g} s is below min_dt {:.6g} s (l = {:.6g} m, c = {:.6g} m/s, |v| = {:.6g} m/s)",
                      dt, run.min_dt, fem_.elements.length[static_cast<std::size_t>(best_e)],
                      fem_.elements.stable_wave_speed[static_cast<std::size_t>(best_e)],
                      fem_.elements.speed[static_cast<std::size_t>(best_e)])));
    fail(NumericalError(EntityKind::model, 0, "time step", fmt::format("dt {:.6g} s is not usable", dt)));
  }
  dt_next_ = dt;
  limit_ = {dt, reason};
}

template <int D>
FieldSnapshot Solver<D>::snapshot() const {
  FieldSnapshot s;
  s.dimension = D;
  s.mode = mode_;
  s.time = time_;
  s.cycle = cycle_;
  fem_.fill_snapshot(s);
  for (const auto& package : packages_) package->fill_snapshot(s);
  return s;
}

template class Solver<2>;
template class Solver<3>;

}  // namespace camouflet
