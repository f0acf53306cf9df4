// The SPH and coupling stages of step() (solver.cpp lists them all): the particle package's
// forces, kick, drift and kinematics, and the join's and the contact's forces between the
// particles and the FEM nodes.
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_particle_forces() {
  if (particles_) particles_->compute_accelerations();  // sets the accelerations: gravity adds after it
}

template <int D>
void Solver<D>::add_coupling_forces() {
  if (join_) join_->add_reactions(*particles_, force_.data());  // reactions on the joined nodes
  if (particles_ && !contact_.empty())
    contact_power_ = contact_.apply(*particles_, position_.data(), velocity_.data(), force_.data(),
                                    centred_step());
}

template <int D>
void Solver<D>::kick_particles() {
  if (particles_) particles_->kick(centred_step());  // the nodes' interval
}

template <int D>
void Solver<D>::drift_particles() {
  // The particles' kinetic energy at t_n in the centred form, before they move (the nodes' is
  // taken in drift_nodes_and_account_energy, which adds this one).
  split_.sph_kinetic = particles_ ? particles_->centred_kinetic_energy() : 0.0;
  if (particles_) particles_->drift(dt_next_);
}

template <int D>
void Solver<D>::particle_kinematics() {
  // Density, velocity gradient and the particles' own material batches (the same Material::update).
  if (particles_) particles_->update_state(dt_, time_);
}

template void Solver<2>::add_particle_forces();
template void Solver<3>::add_particle_forces();
template void Solver<2>::add_coupling_forces();
template void Solver<3>::add_coupling_forces();
template void Solver<2>::kick_particles();
template void Solver<3>::kick_particles();
template void Solver<2>::drift_particles();
template void Solver<3>::drift_particles();
template void Solver<2>::particle_kinematics();
template void Solver<3>::particle_kinematics();

}  // namespace camouflet
