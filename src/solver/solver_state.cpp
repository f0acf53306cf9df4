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
  nodes_checked_cycle_ = -1;    // a restored state is checked again by the next step
  fem_.forces_zeroed = false;  // and its force arrays zeroed by add_element_forces
  visit(v, "time", time_);
  visit(v, "cycle", cycle_);
  visit(v, "dt", dt_);
  visit(v, "dt_next", dt_next_);
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
  visit(v, "eroded_count", fem_.eroded_count);
  if (coupling_) coupling_->visit_state(v);  // join_power, contact_power
  visit(v, "internal_energy", internal_energy_);
  visit(v, "hourglass_stored", fem_.hourglass_stored);
  visit(v, "hourglass_dissipated", fem_.hourglass_dissipated);

  fem_.visit_state(v);  // nodes, elements, material batches (the bars come after the particles)
  boundaries_.visit_state(v);  // loads, reactions, the transmitting boundaries' static hold
  visit_package_state(v);  // each in its own scope (SPH: "sph")
  fem_.bars.visit_state(v);
  // The join's interface is a function of the eroded flags (coupling/join_erosion.cpp).
  if (coupling_ && v.loading()) coupling_->follow_erosion();
}

template void Solver<2>::visit_state(StateVisitor&);
template void Solver<3>::visit_state(StateVisitor&);

}  // namespace camouflet
