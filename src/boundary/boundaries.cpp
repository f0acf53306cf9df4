#include "boundary/boundaries.hpp"

namespace camouflet {

template <int D>
Boundaries<D>::Boundaries(const Model& model, const FemPackage<D>& fem)
    : conditions_(model), transmitting_(model, fem.elements), mirror_planes_(sph::particle_mirror_planes(model)) {
  if (fem.sharing()) transmitting_.share_nodes(fem.sharing(), fem.node_count());
}

template <int D>
double Boundaries<D>::add_static_forces(FemPackage<D>& fem, double dt_old) const {
  if (transmitting_.empty()) return 0.0;
  return transmitting_.add_static_forces(fem.velocity.data(), dt_old, fem.force.data());
}

template <int D>
typename Boundaries<D>::Work Boundaries<D>::constrain(FemPackage<D>& fem, double time, double dt_old,
                                                      double dt_mean, bool relaxing) {
  Work work;
  // Centred dashpots on v(n+1/2) first (transmitting_boundary.hpp), then the constraints.
  if (!transmitting_.empty() && relaxing) {
    transmitting_.hold_still(fem.velocity.data());
  } else if (!transmitting_.empty()) {
    transmitting_.damp(fem.position.data(), fem.velocity_old.data(), fem.velocity.data(), fem.node_mass.data(),
                       fem.elements, fem.batches, dt_mean);
  }
  const double reaction_work = conditions_.constrain(fem.velocity.data(), fem.velocity_old.data(),
                                                     fem.node_mass.data(), time, dt_old, dt_mean, fem.owned_nodes());
  if (!transmitting_.empty() && !relaxing)
    work.transmitting = transmitting_.work(fem.velocity_old.data(), fem.velocity.data(), dt_mean);
  work.constraints = reaction_work + conditions_.load_work(fem.velocity_old.data(), dt_old);
  return work;
}

template <int D>
void Boundaries<D>::hold_initial_state(FemPackage<D>& fem, const std::array<double, 3>& g, bool has_gravity,
                                       bool relaxed) {
  if (transmitting_.empty() || !(relaxed || has_gravity)) return;
  // Each node's internal force plus its weight in the initial state: what the soil beyond a
  // transmitting boundary held, which the boundary now holds in its place. A load applied to the
  // boundary's own nodes is not part of the hold (the dashpots see its effect as motion).
  std::vector<double> unbalanced(fem.position.size(), 0.0);
  if (fem.elements.area_weighted_momentum()) fem.elements.update_ring_factors(fem.position.data());
  fem.elements.add_internal_forces(fem.position.data(), fem.velocity.data(), unbalanced.data(), nullptr,
                                   fem.hourglass, 0.0);
  // On ranks each holder of a node on a cut has its own elements' share: added up, before the
  // weight of the whole node mass.
  if (fem.sharing()) fem.sharing()->sum_shared(unbalanced, D);
  for (std::size_t n = 0; n < fem.node_mass.size(); ++n)
    for (int i = 0; i < D; ++i)
      unbalanced[n * D + static_cast<std::size_t>(i)] += fem.node_mass[n] * g[static_cast<std::size_t>(i)];
  transmitting_.hold_initial_state(unbalanced.data());
}

template class Boundaries<2>;
template class Boundaries<3>;

}  // namespace camouflet
