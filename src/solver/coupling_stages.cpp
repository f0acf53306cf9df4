// The coupling stages of step() (solver.cpp lists them all): the join's and the contact's
// forces between the particles and the FEM nodes, and the join following the FEM package's
// erosion.
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_coupling_forces() {
  if (coupling_) coupling_->add_forces(centred_step());  // join reactions, contact (coupling/)
}

template <int D>
void Solver<D>::follow_packages() {
  // The SPH-FEM interface loses the eroded elements' faces and gains those they exposed.
  if (coupling_) coupling_->follow_packages();
}

template void Solver<2>::add_coupling_forces();
template void Solver<3>::add_coupling_forces();
template void Solver<2>::follow_packages();
template void Solver<3>::follow_packages();

}  // namespace camouflet
