// FemPackage::visit_state: the nodes, elements and material batches by name
// (core/state_visitor.hpp), in the order of the solver's checkpoint layout
// (solver/solver_state.cpp calls it between its scalars and the boundaries).
#include "fem/fem_package.hpp"
#include "materials/material_points_state.hpp"

namespace camouflet {

template <int D>
void FemPackage<D>::visit_state(StateVisitor& v) {
  {
    StateScope node_scope(v, "nodes");
    visit(v, "position", position);
    visit(v, "velocity", velocity);
    visit(v, "velocity_old", velocity_old);
    visit(v, "acceleration", acceleration);
    visit(v, "force", force);
    visit(v, "displacement", displacement);
    visit(v, "hourglass_force", hourglass_force);
    visit(v, "hourglass_force_previous", hourglass_force_previous);
    visit(v, "mass", node_mass);
  }
  {
    StateScope element_scope(v, "elements");
    FemElements<D>& e = elements;
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
    visit(v, "total_strain", total_strain);
  }
  for (std::size_t m = 0; m < batches.size(); ++m) {
    StateScope batch(v, "batch" + std::to_string(m));
    camouflet::visit_state(v, batches[m]);
  }
}

template void FemPackage<2>::visit_state(StateVisitor&);
template void FemPackage<3>::visit_state(StateVisitor&);

}  // namespace camouflet
