// Solver<D>::visit_state: the complete state of the explicit cycle by name
// (core/state_visitor.hpp) for checkpoints and restarts. Anything
// a later cycle reads must be listed here; restart-determinism tests
// (tests/solver/test_restart.cpp) compare a restarted run bit for bit with an
// uninterrupted one and fail when something is missing.
#include "materials/material_points_state.hpp"
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::visit_state(StateVisitor& v) {
  StateScope scope(v, "solver");
  visit(v, "time", time_);
  visit(v, "cycle", cycle_);
  visit(v, "dt", dt_);
  visit(v, "dt_next", dt_next_);
  if (!slides_.empty()) visit(v, "dt_stable", dt_stable_);  // the slide surfaces' stiffness
  visit(v, "limit.dt", limit_.dt);
  visit(v, "limit.reason", limit_.reason);
  visit(v, "energy.kinetic", energy_.kinetic);
  visit(v, "energy.internal", energy_.internal);
  visit(v, "energy.hourglass", energy_.hourglass);
  visit(v, "energy.viscous", energy_.viscous);
  visit(v, "energy.boundary_work", energy_.boundary_work);
  visit(v, "energy.initial_total", energy_.initial_total);
  visit(v, "energy.relative_error", energy_.relative_error);
  visit(v, "energy.eroded", energy_.eroded);
  // The boundary work's parts (energy.csv); the shares of kinetic and internal energy are recomputed each
  // cycle.
  visit(v, "energy_split.transmitting", split_.transmitting);
  visit(v, "energy_split.constraints", split_.constraints);
  visit(v, "energy_split.join", split_.join);
  visit(v, "energy_split.join_face", split_.join_face);
  visit(v, "energy_split.contact", split_.contact);
  for (auto& share : split_.packages) {
    visit(v, "energy_split." + share.name + "_kinetic", share.kinetic);
    visit(v, "energy_split." + share.name + "_internal", share.internal);
  }
  visit(v, "energy_split.bar_internal", split_.bar_internal);
  visit(v, "energy_split.gravity", split_.gravity);
  if (coupling_) coupling_->visit_state(v);  // join_power, contact_power
  visit(v, "internal_energy", internal_energy_);

  // FEM in the solver's scope (its names predate the packages), each other package in its own
  // (SPH: "sph"); then the boundaries.
  visit_package_state(v);
  boundaries_.visit_state(v);  // loads, reactions, the transmitting boundaries' static hold
  // The join's interface is a function of the eroded flags (coupling/join_erosion.cpp).
  if (coupling_ && v.loading()) coupling_->follow_erosion();
  // On ranks the whole run's balance is not kept: the restored shares added up again, by every
  // rank at the same point of the restart.
  if (ranks_ && v.loading()) reduce_energy(false);
}

template void Solver<2>::visit_state(StateVisitor&);
template void Solver<3>::visit_state(StateVisitor&);

}  // namespace camouflet
