// EmbeddedBars<D>::visit_state: what a restart of a run with embedded bars
// needs (checkpoints). Geometry and host weights are rebuilt from
// the case; the evolving state is listed here.
#include "fem/embedded_bars.hpp"
#include "materials/material_points_state.hpp"

namespace camouflet {

template <int D>
void EmbeddedBars<D>::visit_state(StateVisitor& v) {
  StateScope scope(v, "bars");
  visit(v, "axial_strain", axial_strain_);
  for (std::size_t k = 0; k < sets_.size(); ++k) {
    StateScope set(v, "set" + std::to_string(k));
    visit(v, "lateral_ratio", sets_[k].lateral_ratio);
    camouflet::visit_state(v, sets_[k].points);
  }
}

template void EmbeddedBars<2>::visit_state(StateVisitor&);
template void EmbeddedBars<3>::visit_state(StateVisitor&);

}  // namespace camouflet
