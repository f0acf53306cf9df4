// The coupling stages of step() (solver.cpp lists them all): the join's and the contact's
// forces between the particles and the FEM nodes, the slide surfaces' between FEM parts, and the join following the FEM package's
// erosion.
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_coupling_forces() {
  if (coupling_) coupling_->add_forces(centred_step());  // join reactions, contact (coupling/)
  if (!slides_.empty())  // FEM-FEM slide surfaces, on v(n-1/2)
    slides_.apply(fem_.position.data(), fem_.velocity.data(), fem_.node_mass.data(), fem_.elements.eroded,
                  fem_.force.data(), dt_stable_);
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
