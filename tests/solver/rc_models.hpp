#pragma once
// Reinforced-concrete test models: the 35 MPa concrete, a weaker
// crack seed, Steel 1006 through the preset path, and the section force of a
// column of elements.
#include <cmath>
#include <memory>

#include "common/fem_models.hpp"
#include "materials/concrete_fixture.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/registry.hpp"
#include "solver/solver.hpp"

namespace camouflet::test {

// Concrete without rate enhancement (the tests pull far above the reference
// rates), tensile strength scaled by `tensile_factor` (a crack seed below 1).
inline std::shared_ptr<const Material> rate_free_concrete(double tensile_factor = 1.0) {
  Parameters strength;
  strength.set_number("compressive_rate_exponent", 0.0);
  strength.set_number("tensile_rate_exponent", 0.0);
  strength.set_number("tensile_strength", 3.5e6 * tensile_factor);
  return concrete_35mpa({}, strength);
}

inline std::shared_ptr<const Material> steel_1006() {
  return make_material("steel", "steel_1006_wang2005", SourceLocation{}, Parameters{}, Parameters{},
                       Parameters{});
}

inline const JohnsonCookParameters& johnson_cook_of(const Material& m) {
  return dynamic_cast<const JohnsonCookStrength&>(*m.strength()).parameters();
}

// An elastic host strip (plane strain, 0.1 m x 0.02 m, 5 x 1 quads;
// material and part "host"), its left end held and its right end pulled along
// x at 0.1 m/s, y = 0 held: a homogeneous stretch along x for 1 ms.
inline Model pulled_host_strip() {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  model.run.end_time = 1e-3;
  model.materials.push_back({"host", elastic_material({2000.0, 1e8, 5e7, 0.0}, "host"), {}});
  model.parts.push_back(Part{"host", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  add_block(model.mesh, {"host", 0, {0, 0, 0}, {0.1, 0.02, 0}, {5, 1, 1}});
  model.boundaries.push_back(velocity("host.xmin", 0, 0.0));
  model.boundaries.push_back(velocity("host.xmax", 0, 0.1));
  model.boundaries.push_back(velocity("host.ymin", 1, 0.0));
  return model;
}

// Current cross-section (m^2; m^2/m in plane strain) of element e normal to
// x: V / L_x, L_x the mean distance between its x-min and x-max faces.
template <int D>
double element_cross_section(const Solver<D>& solver, std::size_t e) {
  constexpr int N = FemElements<D>::nodes;
  // Node order of the block generator: xmin corners 0, 3 (+4, 7), xmax 1, 2 (+5, 6).
  static constexpr int lo[4] = {0, 3, 4, 7}, hi[4] = {1, 2, 5, 6};
  const auto& conn = solver.elements().connectivity;
  const auto& x = solver.position();
  double x_lo = 0.0, x_hi = 0.0;
  for (int k = 0; k < N / 2; ++k) {
    x_lo += x[static_cast<std::size_t>(conn[e * N + static_cast<std::size_t>(lo[k])] * D)];
    x_hi += x[static_cast<std::size_t>(conn[e * N + static_cast<std::size_t>(hi[k])] * D)];
  }
  const double length = (x_hi - x_lo) / (N / 2);
  return solver.elements().volume[e] / length;
}

// Axial force (N; per metre of depth in plane strain) carried by element e.
template <int D>
double element_axial_force(const Solver<D>& solver, std::size_t e) {
  return solver.elements().stress[e].xx * element_cross_section(solver, e);
}

}  // namespace camouflet::test
