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
  node_forces_zeroed_ = false;  // and its force arrays zeroed by add_element_forces
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
  visit(v, "energy_split.sph_kinetic", split_.sph_kinetic);
  visit(v, "energy_split.sph_internal", split_.sph_internal);
  visit(v, "energy_split.bar_internal", split_.bar_internal);
  visit(v, "energy_split.gravity", split_.gravity);
  visit(v, "eroded_count", eroded_count_);
  visit(v, "join_power", join_power_);
  visit(v, "contact_power", contact_power_);
  visit(v, "internal_energy", internal_energy_);
  visit(v, "hourglass_stored", hourglass_stored_);
  visit(v, "hourglass_dissipated", hourglass_dissipated_);

  {
    StateScope nodes(v, "nodes");
    visit(v, "position", position_);
    visit(v, "velocity", velocity_);
    visit(v, "velocity_old", velocity_old_);
    visit(v, "acceleration", acceleration_);
    visit(v, "force", force_);
    visit(v, "displacement", displacement_);
    visit(v, "hourglass_force", hourglass_force_);
    visit(v, "hourglass_force_previous", hourglass_force_previous_);
    visit(v, "mass", node_mass_);
  }
  {
    StateScope elements(v, "elements");
    FemElements<D>& e = elements_;
    visit(v, "connectivity", e.connectivity);
    visit(v, "material", e.material);
    visit(v, "point", e.point);
    visit(v, "mass", e.mass);
    visit(v, "volume", e.volume);
    visit(v, "stress", e.stress);
    visit(v, "viscosity", e.viscosity);
    visit(v, "density", e.density);
    visit(v, "wave_speed", e.wave_speed);
    visit(v, "stable_wave_speed", e.stable_wave_speed);
    visit(v, "length", e.length);
    visit(v, "speed", e.speed);
    visit(v, "hourglass_displacement", e.hourglass_displacement);
    visit(v, "eroded", e.eroded);
    // Geometric-strain erosion sums D dt over the run (empty when no material
    // erodes by it): without it a restarted run erodes later than the original.
    visit(v, "total_strain", total_strain_);
  }
  for (std::size_t m = 0; m < batches_.size(); ++m) {
    StateScope batch(v, "batch" + std::to_string(m));
    camouflet::visit_state(v, batches_[m]);
  }
  boundaries_.visit_state(v);
  transmitting_.visit_state(v);
  if (particles_) particles_->visit_state(v);
  bars_.visit_state(v);
  // The join's interface is a function of the eroded flags (coupling/join_erosion.cpp).
  if (join_ && v.loading()) join_->follow_erosion();
}

template void Solver<2>::visit_state(StateVisitor&);
template void Solver<3>::visit_state(StateVisitor&);

}  // namespace camouflet
