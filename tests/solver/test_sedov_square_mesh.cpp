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
#include <string>

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

// Two ideal gases (gamma = 1.4, rho = 1): part 0 "cold" (1e-8 J/kg), part 1 "hot" (e0 J/kg).
void add_gases(Model& model, double e0) {
  model.materials.push_back({"cold", test::ideal_gas("cold", 1.0, 1.4, 1e-8), {}});
  model.materials.push_back({"hot", test::ideal_gas("hot", 1.0, 1.4, e0), {}});
  for (const char* name : {"cold", "hot"}) {
    Part part;
    part.name = name;
    part.material = model.parts.empty() ? 0 : 1;
    model.parts.push_back(part);
  }
}

// The energy in the corner element of a 40 x 40 quarter: plane strain (x, y >= 0, both edges
// symmetry lines) or r-z (r, z >= 0, the axis and the symmetry plane z = 0); the rest cold gas.
struct BlastSpec {
  GeometryMode mode = GeometryMode::plane_strain;
  bool area_momentum = false;
  double subzonal = 0.0;
  ViscosityForm form = ViscosityForm::acceleration;
  double end_time = 0.2;  // s
  bool limiter = false;   // [run.viscosity] limiter = "csw" (the edge form's)
};

struct Blast {
  std::int64_t first_tangled = 0;        // 1-based element, 0: none
  std::int64_t first_axis_crossing = 0;  // r-z: 1-based node, 0: none
  double radius[3] = {};  // m, the densest element's centre within 0-10, 40-50, 80-90 degrees of the x (r) axis
  double peak_density[3] = {};
  double energy_error = 0.0;
};

Blast blast(const BlastSpec& spec) {
  test::use_threads(1);
  const bool rz = spec.mode == GeometryMode::axisymmetric;
  Model model;
  model.run.mode = spec.mode;
  model.mesh.dimension = 2;
  model.run.end_time = spec.end_time;
  model.run.cfl = 0.5;
  model.run.energy_error_limit = 0.5;  // the area form closes only to its truncation error (recorded)
  model.run.area_weighted_momentum = spec.area_momentum;
  model.run.subzonal_pressure = spec.subzonal;
  model.run.viscosity_form = spec.form;
  model.run.viscosity_limiter = spec.limiter;
  // Plane: quarter_energy per metre in the cell's 9e-4 kg/m; r-z: the half-space's share of the
  // sphere's 0.851072 J in the corner ring of pi dx^3.
  const double e0 = rz ? 0.851072 / 2.0 / (M_PI * cell * cell * cell) : quarter_energy / (cell * cell);
  add_gases(model, e0);
  add_block(model.mesh, {"hot", 1, {0, 0, 0}, {cell, cell, 0}, {1, 1, 1}});
  add_block(model.mesh, {"b", 0, {cell, 0, 0}, {side - cell, cell, 0}, {cells - 1, 1, 1}});
  add_block(model.mesh, {"c", 0, {0, cell, 0}, {side, side - cell, 0}, {cells, cells - 1, 1}});
  for (const char* set : {"hot.xmin", "c.xmin"}) {
    BoundaryCondition left = test::symmetry(set, {1, 0, 0});
    if (rz) left.kind = BoundaryKind::axis;
    model.boundaries.push_back(left);
  }
  for (const char* set : {"hot.ymin", "b.ymin"}) model.boundaries.push_back(test::symmetry(set, {0, 1, 0}));
  Solver<2> solver(model);
  while (solver.time() < spec.end_time * (1 - 1e-12)) {
    solver.limit_next_step(spec.end_time - solver.time());
    solver.step();
  }
  Blast b;
  b.first_tangled = solver.first_tangled_element();
  b.first_axis_crossing = solver.first_axis_crossing_node();
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
  const Blast with = blast({GeometryMode::plane_strain, false, 1.0, ViscosityForm::acceleration, t});
  const Blast without = blast({GeometryMode::plane_strain, false, 0.0, ViscosityForm::acceleration, t});
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

namespace {

// The same blast in 3-D: the energy in the corner hex of an octant of 20^3 cubes (1.2 m), exact
// front R = (E t^2 / (alpha rho))^(1/5), alpha = 0.851072 for gamma = 1.4 (Kamm and Timmes 2007),
// E = 0.851072 J for the whole sphere, so R = t^(2/5). Hexes have no tangle warning (the corner
// Jacobians are checked in 2-D only): here they are counted at the end.
struct Blast3d {
  int negative_corners = 0;  // corner Jacobians <= 0 over all elements at the end
  double radius[3] = {};     // m, densest element within 8 degrees of the x axis, the xy diagonal, the body diagonal
};

Blast3d blast_3d(double subzonal, double end_time) {
  test::use_threads(1);
  constexpr int n = 20;
  constexpr double side3 = 1.2, cell3 = side3 / n;
  Model model;
  model.run.mode = GeometryMode::three_d;
  model.mesh.dimension = 3;
  model.run.end_time = end_time;
  model.run.cfl = 0.5;
  model.run.subzonal_pressure = subzonal;
  const double e0 = 0.851072 / 8.0 / (cell3 * cell3 * cell3);
  add_gases(model, e0);
  add_block(model.mesh, {"hot", 1, {0, 0, 0}, {cell3, cell3, cell3}, {1, 1, 1}});
  add_block(model.mesh, {"b", 0, {cell3, 0, 0}, {side3 - cell3, cell3, cell3}, {n - 1, 1, 1}});
  add_block(model.mesh, {"c", 0, {0, cell3, 0}, {side3, side3 - cell3, cell3}, {n, n - 1, 1}});
  add_block(model.mesh, {"d", 0, {0, 0, cell3}, {side3, side3, side3 - cell3}, {n, n, n - 1}});
  for (const char* set : {"hot.xmin", "c.xmin", "d.xmin"}) model.boundaries.push_back(test::symmetry(set, {1, 0, 0}));
  for (const char* set : {"hot.ymin", "b.ymin", "d.ymin"}) model.boundaries.push_back(test::symmetry(set, {0, 1, 0}));
  for (const char* set : {"hot.zmin", "b.zmin", "c.zmin"}) model.boundaries.push_back(test::symmetry(set, {0, 0, 1}));
  Solver<3> solver(model);
  while (solver.time() < end_time * (1 - 1e-12)) {
    solver.limit_next_step(end_time - solver.time());
    solver.step();
  }
  Blast3d b;
  const auto& el = solver.elements();
  const auto& x = solver.position();
  // Node a's three neighbours, ordered so that the corner Jacobian of an undistorted hex is positive.
  static constexpr int around[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                       {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  const double directions[3][3] = {{1, 0, 0}, {M_SQRT1_2, M_SQRT1_2, 0}, {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}};
  double peak[3] = {};
  for (std::size_t e = 0; e < el.size(); ++e) {
    double p[8][3], c[3] = {};
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) {
        p[a][i] = x[static_cast<std::size_t>(el.connectivity[e * 8 + a] * 3 + i)];
        c[i] += p[a][i] / 8;
      }
    for (int a = 0; a < 8; ++a) {
      double u[3][3];
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) u[k][i] = p[around[a][k]][i] - p[a][i];
      const double det = u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1]) -
                         u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0]) +
                         u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0]);
      if (det <= 0.0) ++b.negative_corners;
    }
    const double r = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (int k = 0; k < 3; ++k) {
      const double cosine = (c[0] * directions[k][0] + c[1] * directions[k][1] + c[2] * directions[k][2]) / r;
      if (cosine < std::cos(8.0 * M_PI / 180.0) || el.density[e] <= peak[k]) continue;
      peak[k] = el.density[e];
      b.radius[k] = r;
    }
  }
  return b;
}

}  // namespace

// Recorded, not asserted: the subzonal pressures keep most hexes around the 3-D blast sound but
// not all (docs/theory-fem.md, "Subzonal pressures and edge viscosity").
TEST(SedovSquareMesh, CubeBlastRecorded) {
  const double t = 0.5, exact = std::pow(t, 0.4);  // 0.758 m
  const Blast3d with = blast_3d(1.0, t), without = blast_3d(0.0, t);
  test::record_observation("Sedov point blast on a cube mesh (3-D octant, 20^3 hexes, t = 0.5 s): corner Jacobians "
                           "<= 0 at the end, with subzonal pressures; without",
                           "none", fmt::format("{}; {}", with.negative_corners, without.negative_corners),
                           with.negative_corners == 0);
  const char* direction[3] = {"along x", "xy diagonal", "body diagonal"};
  for (int k = 0; k < 3; ++k)
    test::record_observation(fmt::format("Sedov point blast on a cube mesh (3-D octant, 20^3 hexes, subzonal "
                                         "pressures): densest element {} at t = 0.5 s / exact front",
                                         direction[k]),
                             "1 within 5 % (R = t^(2/5), Kamm and Timmes 2007)", fmt::format("{:.3f}", with.radius[k] / exact),
                             std::abs(with.radius[k] / exact - 1.0) < 0.05);
  EXPECT_LT(with.negative_corners, without.negative_corners);
}


namespace {

// The r-z blast's front against t^(2/5) at t = 0.3 s (0.618 m) along r and at 45 degrees, the
// front along the axis and the energy balance recorded; `viscosity` names the edge form used.
void check_rz_front(const Blast& with, const std::string& viscosity) {
  const double exact = std::pow(0.3, 0.4);
  const char* direction[3] = {"along r (equator)", "at 45 degrees", "along the axis"};
  for (int k = 0; k < 2; ++k)
    test::verify({fmt::format("Sedov point blast on a square mesh (r-z, 40 x 40 quads, area form, {}, "
                              "subzonal pressures): shock radius {} at t = 0.3 s",
                              viscosity, direction[k]),
                  "t^(2/5) (E = 0.851072 J, alpha = 0.851072, Kamm and Timmes 2007)", exact, with.radius[k], 0.05,
                  true, "m"});
  test::record_observation(fmt::format("Sedov point blast on a square mesh (r-z, 40 x 40 quads, area form, {}, "
                                       "subzonal pressures): shock radius along the axis at t = 0.3 s / exact",
                                       viscosity),
                           "1 within 5 %", fmt::format("{:.3f}", with.radius[2] / exact),
                           std::abs(with.radius[2] / exact - 1.0) < 0.05);
  // The area form closes its balance only to the truncation error; the violent start (all the
  // energy in one element) costs a few per cent, first order in the step.
  test::record_observation(fmt::format("Sedov point blast on a square mesh (r-z, area form, {}, subzonal "
                                       "pressures): energy balance at t = 0.3 s",
                                       viscosity),
                           "within 1 %", fmt::format("{:+.4f}", with.energy_error), std::abs(with.energy_error) < 0.01);
}

}  // namespace

// In r-z the volume form's axis nodes run ahead whatever the viscosity (docs/theory-fem.md); the
// area form with the edge viscosity and the subzonal pressures keeps every element sound, where
// the area form with q along a tangles the element beside the hot one within ten cycles.
TEST(SedovSquareMesh, RzBlastKeepsEveryElementUntangledInTheAreaFormWithEdgeViscosityAndSubzonalPressures) {
  const double t = 0.3;
  const Blast with = blast({GeometryMode::axisymmetric, true, 1.0, ViscosityForm::edge, t});
  const Blast q_only = blast({GeometryMode::axisymmetric, true, 0.0, ViscosityForm::acceleration, t});
  test::record_check("Sedov point blast on a square mesh (r-z, 40 x 40 quads, area form, t = 0.3 s)",
                     "no element tangled with the edge viscosity and subzonal pressures; q along a alone tangles",
                     fmt::format("first tangled element with: {} (0 = none), q alone: {}", with.first_tangled,
                                 q_only.first_tangled),
                     with.first_tangled == 0 && q_only.first_tangled > 0);
  EXPECT_EQ(with.first_tangled, 0);
  EXPECT_EQ(with.first_axis_crossing, 0);
  EXPECT_GT(q_only.first_tangled, 0);
  check_rz_front(with, "edge viscosity");
}

// The same r-z blast with the edge viscosity's limiter (CSW 1998; [run.viscosity] limiter =
// "csw"): the viscosity then acts at the front, not in the smooth flow behind it, and the mesh
// must still come through sound, with the front where it was (6 Dec 2026, along the axis: 0.958
// of the exact front with the limiter, 0.968 without).
TEST(SedovSquareMesh, RzBlastKeepsEveryElementUntangledWithTheLimitedEdgeViscosity) {
  BlastSpec spec{GeometryMode::axisymmetric, true, 1.0, ViscosityForm::edge, 0.3};
  spec.limiter = true;
  const Blast with = blast(spec);
  test::record_check("Sedov point blast on a square mesh (r-z, 40 x 40 quads, area form, limited edge viscosity, "
                     "subzonal pressures, t = 0.3 s)",
                     "no element tangled, no node across the axis",
                     fmt::format("first tangled element: {}, first axis crossing: {} (0 = none)", with.first_tangled,
                                 with.first_axis_crossing),
                     with.first_tangled == 0 && with.first_axis_crossing == 0);
  EXPECT_EQ(with.first_tangled, 0);
  EXPECT_EQ(with.first_axis_crossing, 0);
  check_rz_front(with, "limited edge viscosity");
}
