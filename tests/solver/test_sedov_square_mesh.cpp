// Sedov's point blast on a square mesh of Lagrangian quads (plane strain, a
// cylindrical blast): the energy in the one element at the corner of a
// quarter plane, cold ideal gas (gamma = 1.4, rho = 1) around it. The exact
// shock radius is R = (E / (alpha rho))^(1/4) t^(1/2), E the energy per unit
// length of the whole cylinder, alpha = 0.9840 for gamma = 1.4 (Kamm and
// Timmes 2007, LA-UR-07-2849, cylindrical case). Without subzonal pressures
// the element beside the hot one is crushed into a bow-tie within a few dozen
// cycles; with them no element tangles (docs/theory-fem.md, "Subzonal
// pressures and edge viscosity").
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "../sph/sph_test_models.hpp"
#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr int cells = 40;
constexpr double side = 1.2, cell = side / cells;
constexpr double quarter_energy = 4.515077;  // J/m: e0 = 5016.75 J/kg in a cell of 9e-4 kg/m
constexpr double alpha_cylindrical = 0.9840;

struct Blast {
  std::int64_t first_tangled = 0;  // 1-based element, 0: none
  double radius[3] = {};           // m, the densest element's centre within 0-10, 40-50, 80-90 degrees
  double peak_density[3] = {};
  double energy_error = 0.0;
};

Blast blast(double subzonal, ViscosityForm form, double end_time) {
  test::use_threads(1);
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  model.run.end_time = end_time;
  model.run.cfl = 0.5;
  model.run.subzonal_pressure = subzonal;
  model.run.viscosity_form = form;
  const double e0 = quarter_energy / (cell * cell);
  model.materials.push_back({"cold", test::ideal_gas("cold", 1.0, 1.4, 1e-8), {}});
  model.materials.push_back({"hot", test::ideal_gas("hot", 1.0, 1.4, e0), {}});
  for (const char* name : {"cold", "hot"}) {
    Part part;
    part.name = name;
    part.material = model.parts.empty() ? 0 : 1;
    model.parts.push_back(part);
  }
  add_block(model.mesh, {"hot", 1, {0, 0, 0}, {cell, cell, 0}, {1, 1, 1}});
  add_block(model.mesh, {"b", 0, {cell, 0, 0}, {side - cell, cell, 0}, {cells - 1, 1, 1}});
  add_block(model.mesh, {"c", 0, {0, cell, 0}, {side, side - cell, 0}, {cells, cells - 1, 1}});
  for (const char* set : {"hot.xmin", "c.xmin"}) model.boundaries.push_back(test::symmetry(set, {1, 0, 0}));
  for (const char* set : {"hot.ymin", "b.ymin"}) model.boundaries.push_back(test::symmetry(set, {0, 1, 0}));
  Solver<2> solver(model);
  while (solver.time() < end_time * (1 - 1e-12)) {
    solver.limit_next_step(end_time - solver.time());
    solver.step();
  }
  Blast b;
  b.first_tangled = solver.first_tangled_element();
  b.energy_error = solver.energy().relative_error;
  const auto& el = solver.elements();
  const auto& x = solver.position();
  for (std::size_t e = 0; e < el.size(); ++e) {
    double c[2] = {};
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 2; ++i) c[i] += 0.25 * x[static_cast<std::size_t>(el.connectivity[e * 4 + a] * 2 + i)];
    const double angle = std::atan2(c[1], c[0]) * 180.0 / M_PI;
    const int band = angle < 10.0 ? 0 : (angle >= 40.0 && angle < 50.0) ? 1 : angle >= 80.0 ? 2 : -1;
    if (band < 0 || el.density[e] <= b.peak_density[band]) continue;
    b.peak_density[band] = el.density[e];
    b.radius[band] = std::hypot(c[0], c[1]);
  }
  return b;
}

}  // namespace

TEST(SedovSquareMesh, PlaneBlastKeepsEveryElementUntangledWithSubzonalPressures) {
  const double t = 0.2;  // s
  const double exact = std::pow(4.0 * quarter_energy / alpha_cylindrical, 0.25) * std::sqrt(t);  // 0.926 m
  const Blast with = blast(1.0, ViscosityForm::acceleration, t);
  const Blast without = blast(0.0, ViscosityForm::acceleration, t);
  // The contrast the subzonal pressures make: without them the element next to the hot one tangles.
  EXPECT_GT(without.first_tangled, 0);
  test::record_check("Sedov point blast on a square mesh (plane, 40 x 40 quads, t = 0.2 s)",
                     "no element tangled (bow-tie) with subzonal pressures; one tangles without them",
                     fmt::format("first tangled element with: {} (0 = none), without: {}", with.first_tangled,
                                 without.first_tangled),
                     with.first_tangled == 0 && without.first_tangled > 0);
  EXPECT_EQ(with.first_tangled, 0);
  const char* direction[3] = {"along x", "diagonal", "along y"};
  for (int k = 0; k < 3; ++k) {
    // The densest element sits about half a cell behind the front: 40 cells place it to about
    // 2 % of the radius, along the mesh lines and across them alike.
    test::verify({fmt::format("Sedov point blast on a square mesh (plane, 40 x 40 quads, subzonal pressures): "
                              "shock radius {} at t = 0.2 s",
                              direction[k]),
                  "(E / (alpha rho))^(1/4) t^(1/2), alpha = 0.9840 (Kamm and Timmes 2007)", exact, with.radius[k],
                  0.03, true, "m"});
    // Strong-shock density (gamma + 1) / (gamma - 1) = 6, smeared by q over about two cells.
    EXPECT_GT(with.peak_density[k], 0.8 * 6.0) << direction[k];
  }
  EXPECT_LT(std::abs(with.energy_error), 0.02);
}
