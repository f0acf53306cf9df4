// Gravity: the body force m g on every package's points, and the static load that transmitting
// boundaries carry under it or after a dynamic relaxation (docs/theory/gravity.md).
#include <cstddef>
#include <cstdint>

#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_gravity() {
  if (!model_.run.has_gravity()) return;
  // Each package adds m g to its points and m g . v(n-1/2) to one running sum (FEM's nodes
  // first): the work of the constant force over the step t_(n-1) -> t_n is that power times
  // dt(n-1/2), exactly m g . (x_n - x_(n-1)), the potential energy given up.
  double power = 0.0;
  for (Package<D>* package : packages_) package->add_gravity(model_.run.gravity, power);
  const double work = power * dt_;
  energy_.boundary_work += work;
  split_.gravity += work;
}

template <int D>
void Solver<D>::add_static_boundary_forces() {
  // The static load the transmitting boundaries carry (Boundaries::hold_initial_state): under
  // gravity, and after a dynamic relaxation under the t = 0 loads with or without it. Boundaries
  // that hold nothing add nothing.
  const double static_work = boundaries_.add_static_forces(fem_, dt_);
  energy_.boundary_work += static_work;
  split_.transmitting += static_work;
}

template void Solver<2>::add_gravity();
template void Solver<3>::add_gravity();
template void Solver<2>::add_static_boundary_forces();
template void Solver<3>::add_static_boundary_forces();

}  // namespace camouflet
