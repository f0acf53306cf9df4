// BoundaryConditions<D>::visit_state: the load and reaction forces of the
// previous cycles that the time-centred boundary work needs (checkpoints).
#include "boundary/boundary_conditions.hpp"

namespace camouflet {

template <int D>
void BoundaryConditions<D>::visit_state(StateVisitor& v) {
  StateScope scope(v, "boundaries");
  for (auto* forces : {&load_forces_, &load_forces_previous_}) {
    const std::string name = forces == &load_forces_ ? "load_forces" : "load_forces_previous";
    std::vector<std::int64_t> node(forces->size());
    std::vector<double> force(forces->size() * D);
    for (std::size_t k = 0; k < forces->size(); ++k) {
      node[k] = (*forces)[k].node;
      for (int i = 0; i < D; ++i)
        force[k * D + static_cast<std::size_t>(i)] = (*forces)[k].force[static_cast<std::size_t>(i)];
    }
    visit(v, name + ".node", node);
    visit(v, name + ".force", force);
    if (v.loading()) {
      if (force.size() != node.size() * D)
        throw std::runtime_error("checkpoint: '" + name + "' is inconsistent");
      forces->resize(node.size());
      for (std::size_t k = 0; k < node.size(); ++k) {
        (*forces)[k].node = node[k];
        for (int i = 0; i < D; ++i)
          (*forces)[k].force[static_cast<std::size_t>(i)] = force[k * D + static_cast<std::size_t>(i)];
      }
    }
  }
  visit(v, "reaction_previous", reaction_previous_);
}

template void BoundaryConditions<2>::visit_state(StateVisitor&);
template void BoundaryConditions<3>::visit_state(StateVisitor&);

}  // namespace camouflet
