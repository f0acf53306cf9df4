// FemPackage::visit_state: the nodes, elements, material batches, erosion and hourglass sums
// and the embedded bars by name (core/state_visitor.hpp), in the driver's scope: the names
// are those of the checkpoints written before FEM was a package (solver/solver_state.cpp).
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
    visit(v, "edge_force", e.edge_force);
    visit(v, "subzone_fraction", e.subzone_fraction);
    visit(v, "subzone_pressure", e.subzone_pressure);
    visit(v, "subzone_volume", e.subzone_volume);
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
  visit(v, "eroded_count", eroded_count);
  visit(v, "hourglass_stored", hourglass_stored);
  visit(v, "hourglass_dissipated", hourglass_dissipated);
  bars.visit_state(v);
  // A restored state is checked again by the next step, and its force arrays zeroed by
  // begin_step (a checkpoint holds the forces of its last step). Its internal energy is the
  // driver's restored balance until the next update gathers it.
  forces_zeroed = false;
  nodes_checked_ = false;
}

template void FemPackage<2>::visit_state(StateVisitor&);
template void FemPackage<3>::visit_state(StateVisitor&);

}  // namespace camouflet
