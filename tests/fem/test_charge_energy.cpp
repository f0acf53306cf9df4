// Energy of a whole detonating charge: the seed paper's
// 100 kg TNT sphere (Wang et al. 2005, Table 5; 3.68e8 J of chemical energy)
// lit at its centre, in axisymmetric quad4 FEM, expanding into vacuum. The
// chemical energy is internal energy from the start (e0 / rho0 per kg,
// docs/theory/explosive-and-steel.md §2), so once the whole charge has burnt
// the total (internal + kinetic + hourglass) must still equal E0 x V: the
// chemical energy released. The detonation turns a large part of it into
// kinetic energy, so a balance that held only because nothing moved would
// fail the second check.
//
// Mesh: the quarter disc r >= 0, z >= 0 (the upper half of the sphere; axis
// boundary at r = 0, symmetry plane z = 0) from one block on the unit square
// mapped by the elliptical map (u, v) -> R (u sqrt(1 - v^2/2), v sqrt(1 - u^2/2)),
// which sends the edges u = 1 and v = 1 onto the circle: no cavity, no
// degenerate element.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "materials/registry.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

TEST(ChargeEnergy, HundredKilogramTntSphereReleasesE0TimesVolume) {
  test::use_threads(1);
  const double mass = 100.0, rho0 = 1630.0, e0 = 6.0e9;  // kg, kg/m^3, J/m^3 (Table 5)
  const double radius = std::cbrt(3.0 * mass / (4.0 * std::numbers::pi * rho0));
  const int cells = 24;

  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  model.mesh.dimension = 2;
  add_block(model.mesh, {"charge", 0, {0, 0, 0}, {1.0, 1.0, 0}, {cells, cells, 1}});
  for (std::size_t n = 0; n < model.mesh.node_count(); ++n) {
    const double u = model.mesh.coordinates[2 * n], v = model.mesh.coordinates[2 * n + 1];
    model.mesh.coordinates[2 * n] = radius * u * std::sqrt(1.0 - 0.5 * v * v);
    model.mesh.coordinates[2 * n + 1] = radius * v * std::sqrt(1.0 - 0.5 * u * u);
  }
  model.materials.push_back(
      {"tnt", make_material("tnt", "tnt_wang2005", {}, Parameters{}, Parameters{}, Parameters{}), {}});
  Part part;
  part.name = "charge";
  part.material = 0;
  model.parts.push_back(part);
  BoundaryCondition axis;
  axis.kind = BoundaryKind::axis;
  axis.set = "charge.xmin";
  model.boundaries.push_back(axis);
  model.boundaries.push_back(test::symmetry("charge.ymin", {0, 1, 0}));
  model.detonations.push_back(DetonationPoint{{0.0, 0.0, 0.0}, 0.0});
  model.detonation_where.push_back({});
  // The front reaches the surface at R / D = 35 us; the burn ramp (3 cells)
  // ends a few us later. Run on until the products have expanded.
  model.run.end_time = 60e-6;

  Solver<2> solver(model);
  // The half sphere's chemical energy, doubled to the whole charge.
  const double chemical = 2.0 * solver.energy().initial_total;
  double worst = 0.0;  // largest |E(t) - E0 V| / E0 V over the run
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    const EnergyBalance& e = solver.energy();
    const double total = 2.0 * (e.kinetic + e.internal + e.hourglass);
    worst = std::max(worst, std::abs(total - chemical) / chemical);
  }
  const MaterialPoints& pts = solver.batches()[0];
  const double* burnt = pts.history.column(pts.history.slot("burn_fraction"));
  double least_burnt = 1.0;
  for (std::size_t i = 0; i < pts.size(); ++i) least_burnt = std::min(least_burnt, burnt[i]);
  const double kinetic = 2.0 * solver.energy().kinetic;
  std::printf(
      "TNT sphere R = %.4f m: E0 V (mesh) = %.4e J, worst energy error %.2e, kinetic %.3f of E0 V, "
      "least burn fraction %.3f, %lld cycles\n",
      radius, chemical, worst, kinetic / chemical, least_burnt, static_cast<long long>(solver.cycle()));

  // The faceted sphere holds the chemical energy of the real one (its
  // chords lose a few 1e-4 of the volume).
  test::verify({"100 kg TNT sphere (FEM r-z): chemical energy of the meshed charge",
                "E0 x V = 6.0e9 J/m^3 x 100 kg / 1630 kg/m^3 = 3.68e8 J", e0 * mass / rho0,
                chemical, 0.005, true, "J"});
  EXPECT_EQ(least_burnt, 1.0) << "the whole charge must have burnt";
  test::verify({"100 kg TNT sphere (FEM r-z): total energy vs chemical energy released, worst over the run",
                "E_kin + E_int + E_hg = E0 x V within 1 %", 0.0, worst, 0.01, false, "relative"});
  EXPECT_GT(kinetic, 0.2 * chemical) << "the detonation must have turned chemical energy into motion";
}
