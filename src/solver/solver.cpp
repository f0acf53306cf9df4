#include "solver/solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace camouflet {

template <int D>
Solver<D>::Solver(const Model& model, const RankPart* ranks)
    : model_(model), mode_(model.run.mode), ranks_(ranks), fem_(model, ranks) {
  boundaries_ = Boundaries<D>(model, fem_);
  slides_ = SlideSurfaces<D>(model);
  boundaries_.constrain(fem_.velocity, 0.0);
  register_package(fem_);  // FEM, a member, first at every stage

  // SPH particles: same materials, own batches (sph/sph_package.hpp), mirrored in the planes the
  // boundaries give them.
  if (model.particles.count() > 0) {
    auto particles = std::make_unique<sph::SphPackage<D>>(model, boundaries_.mirror_planes());
    coupling_ = std::make_unique<SphFemCoupling<D>>(model, fem_, *particles);
    particles->add_forces(clock());
    sph_ = particles.get();
    register_package(std::move(particles));
  } else {
    SlidingContact<D> contact(model);  // refuses contacts of a model without particles, naming them
  }

  fem_.start();  // the element speeds and state the first vote reads
  gather_energies();
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
  fem_.start();
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
  const double kinetic = package_kinetic_energy();
  energy_.kinetic = kinetic;
  energy_.internal = internal_energy_;
  // The hourglass energy a stiffness form stores: nought at t = 0 unless a relaxation stored some.
  energy_.initial_total = kinetic + internal_energy_ + package_hourglass_energy();
  if (ranks_) reduce_energy(false);
}

template <int D>
void Solver<D>::limit_next_step(double dt_max) {
  if (dt_max > 0.0 && dt_max < dt_next_) dt_next_ = dt_max;
}

template <int D>
void Solver<D>::step() {
  // On ranks a stage that fails on one rank must not leave the others waiting in the next
  // exchange: each rank keeps its first failure, goes on through the step's exchanges (on a
  // state nobody will use), and all learn of it before the time step (agree_on_failure).
  std::optional<NumericalError> failure;
  int failed_stage = 0;  // which of the guarded stages failed, in the order of the step
  const auto guarded = [&](int stage_number, auto&& stage) {
    if (!ranks_) return stage();
    if (failure) return;
    try {
      stage();
    } catch (NumericalError& error) {
      failure = std::move(error);
      failed_stage = stage_number;
    }
  };
  try {
    guarded(0, [&] { check_packages(); });  // the state at t_n: a NaN is named before forces spread it
    // Forces at t_n.
    begin_packages();                                        // FEM: force arrays zeroed, r-z ring factors
    boundaries_.add_loads(fem_, time_, fem_.ring_factor());  // face loads, before the element forces
    add_package_forces();          // FEM: element stresses, hourglass control, bars; SPH: the particle sums
    add_coupling_forces();         // the join's reactions and the sliding contact (coupling/)
    add_gravity();                 // m g on every package's points, and its work (gravity.cpp)
    add_static_boundary_forces();  // the transmitting boundaries' static hold (gravity.cpp)
    // Velocities at t_(n+1/2).
    kick_packages();         // FEM: a = F / m, v(n+1/2); SPH: v(n+1/2), pair heating
    constrain_velocities();  // dashpots, fixed, prescribed, symmetry, axis; the join settles
    // Energies at t_n and positions at t_(n+1).
    drift_packages();  // reverse order: SPH, then the FEM node pass; their centred kinetic energies
    account_energy();  // the energy balance at t_n
    advance_clock();   // t_(n+1), the cycle count, dt(n+1/2)
    guarded(1, [&] { check_packages(); });  // every node and particle finite and inside the domain box
    // Kinematics and material state at t_(n+1), reverse order: SPH (eta, rho, h, D, W, material
    // update), then FEM (V, rho, D, W, q, materials, bars, erosion, sigma and wave speeds).
    guarded(2, [&] { update_packages(); });
    follow_packages();    // the join follows the FEM erosion
    gather_energies();    // internal energy at t_(n+1), per package
    if (ranks_) {  // the whole run's balance, and whether any rank failed (then every rank throws)
      const bool any_failed = reduce_energy(failure.has_value());
      if (any_failed) agree_on_failure(failure, failed_stage);
    }
    choose_time_step();   // dt(n+3/2) = CFL min l / (c + |v|), growth limited
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
void Solver<D>::constrain_velocities() {
  const double dt_mean = centred_step();
  if (relaxing_)  // the charges' nodes and particles held still (dynamic_relaxation.cpp)
    for (Package<D>* package : packages_) package->hold_still(relaxation_held_materials_);
  // The slide surfaces' friction, as impulses on v(n+1/2), before the constraints act on them.
  if (!slides_.empty()) slides_.apply_friction(fem_.velocity.data(), fem_.node_mass.data(), dt_mean);
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
  if (!slides_.empty()) {  // the slide surfaces' work on v(n-1/2) and v(n+1/2) (coupling/slide_surface.hpp)
    const double work = slides_.settle(fem_.velocity.data(), dt_mean);
    energy_.boundary_work += work;
    split_.contact += work;
  }
}

template <int D>
void Solver<D>::account_energy() {
  // The packages' centred kinetic energies at t_n (drift_packages), summed in their order.
  EnergyBalance& e = energy_;
  double kinetic = 0.0;
  for (const auto& share : split_.packages) kinetic += share.kinetic;
  e.kinetic = kinetic;
  e.internal = internal_energy_;
  e.hourglass = package_hourglass_energy();
  // On ranks the shares are added up at the end of the step (reduce_energy), with the viscous
  // and eroded energy the state update adds, as the serial balance holds them after the step.
  if (!ranks_) set_relative_error(e);
}

template <int D>
void Solver<D>::set_relative_error(EnergyBalance& e) {
  const double total = e.kinetic + e.internal + e.hourglass + e.eroded;
  const double scale = std::max(e.initial_total + std::abs(e.boundary_work), std::abs(total));
  e.relative_error = scale > 0.0 ? std::abs(total - e.initial_total - e.boundary_work) / scale : 0.0;
}

template <int D>
void Solver<D>::advance_clock() {
  dt_ = dt_next_;
  time_ += dt_;
  ++cycle_;
}

template <int D>
void Solver<D>::choose_time_step() {
  // The smallest stable step of every package (the first on a tie), times the CFL number.
  const RunControl& run = model_.run;
  double dt = std::numeric_limits<double>::infinity();
  std::string reason;
  const typename Package<D>::Vote* setter = nullptr;
  std::vector<typename Package<D>::Vote> votes;
  votes.reserve(packages_.size());
  for (const Package<D>* package : packages_) votes.push_back(package->vote());
  for (const auto& vote : votes)
    if (run.cfl * vote.dt < dt || !(vote.dt >= 0.0)) {
      dt = run.cfl * vote.dt;
      reason = vote.reason;
      setter = &vote;
    }
  if (ranks_ && !reduce_time_step(dt, reason)) setter = nullptr;  // another rank's point set it
  dt_stable_ = std::min(dt, run.max_dt);
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
    if (setter && setter->id > 0 && !setter->detail.empty())
      fail(NumericalError(setter->kind, setter->id, "time step",
                          fmt::format("dt {:.6g} s is below min_dt {:.6g} s ({})", dt, run.min_dt, setter->detail)));
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
  for (const Package<D>* package : packages_) package->fill_snapshot(s);
  return s;
}

template class Solver<2>;
template class Solver<3>;

}  // namespace camouflet
