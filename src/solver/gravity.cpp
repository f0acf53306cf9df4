// Gravity: the body force m g on every node and every package's points, and the static load that transmitting
// boundaries carry under it or after a dynamic relaxation (docs/theory/gravity.md).
#include <cstddef>
#include <cstdint>

#include "fem/parallel.hpp"
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_gravity() {
  if (!model_.run.has_gravity()) return;
  const std::array<double, 3>& g = model_.run.gravity;
  // The work of the constant force over the step t_(n-1) -> t_n is m g . v(n-1/2) dt(n-1/2),
  // exactly m g . (x_n - x_(n-1)): the booked work is the loss of potential energy, the form the
  // central difference's kinetic energy at t_n balances. fem_.velocity still holds v(n-1/2) here.
  const std::int64_t nn = static_cast<std::int64_t>(fem_.node_mass.size());
  double power = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : power) if (nn > parallel_threshold_nodes)
  for (std::int64_t n = 0; n < nn; ++n) {
    const double m = fem_.node_mass[static_cast<std::size_t>(n)];
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      fem_.force[k] += m * g[static_cast<std::size_t>(i)];
      power += m * g[static_cast<std::size_t>(i)] * fem_.velocity[k];
    }
  }
  add_package_gravity(g, power);  // the particles' and any other package's points, into the same sum
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
