// The SPH and coupling stages of step() (solver.cpp lists them all): the particle package's
// forces, kick, drift and kinematics, the join's and the contact's forces between the
// particles and the FEM nodes, and the join following the FEM package's erosion.
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_particle_forces() {
  if (particles_) particles_->compute_accelerations();  // sets the accelerations: gravity adds after it
}

template <int D>
void Solver<D>::add_coupling_forces() {
  if (join_) join_->add_reactions(*particles_, fem_.force.data());  // reactions on the joined nodes
  if (particles_ && !contact_.empty())
    contact_power_ = contact_.apply(*particles_, fem_.position.data(), fem_.velocity.data(), fem_.force.data(),
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

template <int D>
void Solver<D>::erode_elements() {
  // The SPH-FEM interface loses the eroded elements' faces and gains those they exposed.
  if (fem_.erode(dt_, energy_.eroded) && join_) join_->follow_erosion();
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
template void Solver<2>::erode_elements();
template void Solver<3>::erode_elements();

}  // namespace camouflet
