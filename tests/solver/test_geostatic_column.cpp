// A soil column 10 m deep under gravity with its geostatic initial state stays at rest: peak
// velocity below 1e-3 m/s over 50 ms, stresses within 1 % of the overburden rho g d and of K0
// times it; with rollers and with transmitting boundaries on its side and base; elastic soil
// with a given K0 and the three-phase sandy clay with Drucker-Prager strength and Jaky's K0;
// plane strain, r-z and 3-D. Without the initial state the same column moves.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/geostatic_soils.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr double g = 9.81;         // m/s^2
constexpr double depth = 10.0;     // m
constexpr double end_time = 0.05;  // s

enum class Sides { rollers, transmitting };

using Soil = test::GeostaticSoil;
using test::elastic_soil;
using test::sandy_clay;

Model column(GeometryMode mode, const Soil& soil, Sides sides, bool geostatic) {
  const int dim = dimension_of(mode);
  Model model;
  model.run.mode = mode;
  model.mesh.dimension = dim;
  model.mesh.nodes_per_element = dim == 3 ? 8 : 4;
  const double width = 1.0;
  if (dim == 2)
    add_block(model.mesh, {"soil", 0, {0, -depth, 0}, {width, depth, 0}, {2, 40, 1}});
  else
    add_block(model.mesh, {"soil", 0, {0, 0, -depth}, {width, width, depth}, {2, 2, 40}});
  model.materials.push_back({"soil", soil.material, {}});
  Part part;
  part.name = "soil";
  part.material = 0;
  if (geostatic) part.geostatic = GeostaticState{0.0, soil.k0, 0.0, {}};
  model.parts.push_back(part);
  model.run.gravity = {};
  model.run.gravity[static_cast<std::size_t>(dim - 1)] = -g;
  model.run.end_time = end_time;

  const auto transmitting = [](const std::string& set) {
    BoundaryCondition bc;
    bc.kind = BoundaryKind::transmitting;
    bc.set = set;
    return bc;
  };
  // The column's centre side: a roller, or the axis in r-z.
  if (mode == GeometryMode::axisymmetric) {
    BoundaryCondition axis;
    axis.kind = BoundaryKind::axis;
    axis.set = "soil.xmin";
    model.boundaries.push_back(axis);
  } else {
    model.boundaries.push_back(test::symmetry("soil.xmin", {1, 0, 0}));
  }
  if (dim == 3) model.boundaries.push_back(test::symmetry("soil.ymin", {0, 1, 0}));
  const std::string base = dim == 3 ? "soil.zmin" : "soil.ymin";
  const std::array<double, 3> up = dim == 3 ? std::array<double, 3>{0, 0, 1} : std::array<double, 3>{0, 1, 0};
  if (sides == Sides::rollers) {
    model.boundaries.push_back(test::symmetry("soil.xmax", {1, 0, 0}));
    if (dim == 3) model.boundaries.push_back(test::symmetry("soil.ymax", {0, 1, 0}));
    model.boundaries.push_back(test::symmetry(base, up));
  } else {
    model.boundaries.push_back(transmitting("soil.xmax"));
    if (dim == 3) model.boundaries.push_back(transmitting("soil.ymax"));
    model.boundaries.push_back(transmitting(base));
  }
  return model;
}

struct ColumnResult {
  double peak_speed = 0.0;        // m/s, over all nodes and cycles
  double vertical_error = 0.0;    // largest |sigma_v - sigma_v,ref| / |sigma_v,ref| at 50 ms
  double horizontal_error = 0.0;  // the same for both horizontal stresses against K0 sigma_v,ref
  double energy_error = 0.0;
};

template <int D>
ColumnResult run_column(const Model& model, double density, double k0) {
  test::use_threads(1);
  Solver<D> solver(model);
  ColumnResult r;
  const auto peak = [&] {
    for (std::size_t n = 0; n < solver.node_count(); ++n) {
      double vv = 0.0;
      for (int i = 0; i < D; ++i) vv += solver.velocity()[n * D + i] * solver.velocity()[n * D + i];
      r.peak_speed = std::max(r.peak_speed, std::sqrt(vv));
    }
  };
  while (solver.time() < end_time) {
    solver.step();
    peak();
  }
  const auto& el = solver.elements();
  for (std::size_t e = 0; e < el.size(); ++e) {
    double elevation = 0.0;
    for (int a = 0; a < FemElements<D>::nodes; ++a)
      elevation += solver.position()[el.connectivity[e * FemElements<D>::nodes + a] * D + (D - 1)] /
                   FemElements<D>::nodes;
    const double sigma_v = -density * g * (-elevation);  // rho0 g d, compression negative
    const SymTensor& s = el.stress[e];
    const double v = D == 3 ? s.zz : s.yy;
    const double h1 = s.xx, h2 = D == 3 ? s.yy : s.zz;  // 2-D: out of plane or hoop
    r.vertical_error = std::max(r.vertical_error, std::abs(v - sigma_v) / std::abs(sigma_v));
    r.horizontal_error =
        std::max(r.horizontal_error,
                 std::max(std::abs(h1 - k0 * sigma_v), std::abs(h2 - k0 * sigma_v)) / std::abs(k0 * sigma_v));
  }
  r.energy_error = solver.energy().relative_error;
  return r;
}

template <int D>
void check_at_rest(GeometryMode mode, const Soil& soil, Sides sides, const std::string& label) {
  const ColumnResult r = run_column<D>(column(mode, soil, sides, true), soil.density, soil.expected_k0);
  test::verify({label + ": peak velocity over 50 ms", "at rest (below 1e-3 m/s)", 0.0, r.peak_speed, 1e-3,
                false, "m/s"});
  test::verify({label + ": vertical stress at 50 ms, largest relative error", "rho0 g d (analytic)", 0.0,
                r.vertical_error, 0.01, false, "relative"});
  test::verify({label + ": horizontal stresses at 50 ms, largest relative error", "K0 rho0 g d (analytic)",
                0.0, r.horizontal_error, 0.01, false, "relative"});
}

}  // namespace

TEST(Geostatic, ElasticColumnPlaneStrainAtRest) {
  check_at_rest<2>(GeometryMode::plane_strain, elastic_soil(), Sides::rollers,
                   "Geostatic elastic column 10 m, K0 = 0.5, plane strain, rollers");
}

TEST(Geostatic, ElasticColumnPlaneStrainTransmittingAtRest) {
  check_at_rest<2>(GeometryMode::plane_strain, elastic_soil(), Sides::transmitting,
                   "Geostatic elastic column 10 m, K0 = 0.5, plane strain, transmitting side and base");
}

TEST(Geostatic, ElasticColumnAxisymmetricAtRest) {
  check_at_rest<2>(GeometryMode::axisymmetric, elastic_soil(), Sides::rollers,
                   "Geostatic elastic column 10 m, K0 = 0.5, r-z, rollers");
}

TEST(Geostatic, ElasticColumnAxisymmetricTransmittingAtRest) {
  check_at_rest<2>(GeometryMode::axisymmetric, elastic_soil(), Sides::transmitting,
                   "Geostatic elastic column 10 m, K0 = 0.5, r-z, transmitting side and base");
}

TEST(Geostatic, ElasticColumn3dTransmittingAtRest) {
  check_at_rest<3>(GeometryMode::three_d, elastic_soil(), Sides::transmitting,
                   "Geostatic elastic column 10 m, K0 = 0.5, 3-D, transmitting sides and base");
}

TEST(Geostatic, SandyClayJakyPlaneStrainAtRest) {
  check_at_rest<2>(
      GeometryMode::plane_strain, sandy_clay(), Sides::rollers,
      "Geostatic sandy clay (three-phase soil, Drucker-Prager) 10 m, Jaky K0, plane strain, rollers");
}

TEST(Geostatic, SandyClayJakyAxisymmetricTransmittingAtRest) {
  check_at_rest<2>(
      GeometryMode::axisymmetric, sandy_clay(), Sides::transmitting,
      "Geostatic sandy clay (three-phase soil, Drucker-Prager) 10 m, Jaky K0, r-z, transmitting");
}

TEST(Geostatic, ColumnWithoutInitialStateMoves) {
  // The check above would catch a missing initial state: unstressed, the column settles at
  // about g d / c_p ~ 0.3 m/s.
  const Soil soil = elastic_soil();
  const ColumnResult r =
      run_column<2>(column(GeometryMode::plane_strain, soil, Sides::rollers, false), soil.density, 0.5);
  EXPECT_GT(r.peak_speed, 0.05);
  test::record_check("Elastic column 10 m under gravity without the geostatic state",
                     "must move (peak velocity far above 1e-3 m/s)",
                     fmt::format("peak velocity {:.3g} m/s over 50 ms", r.peak_speed), r.peak_speed > 0.05);
}

TEST(Geostatic, JakyNeedsAFrictionAngle) {
  const Soil soil = elastic_soil();
  Model model = column(GeometryMode::plane_strain, soil, Sides::rollers, true);
  model.parts[0].geostatic->k0.reset();
  try {
    Solver<2> solver(model);
    FAIL() << "Jaky's K0 on an elastic material must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("friction angle"), std::string::npos) << e.what();
  }
}

TEST(Geostatic, StateOutsideTheStrengthIsRefused) {
  // Cohesionless Drucker-Prager with alpha = 0.1: K0 = 0.1 puts sqrt(J2) = 0.52 sigma_v above
  // the limit 0.12 sigma_v at every depth.
  Parameters strength;
  strength.set_string("type", "soil_drucker_prager");
  strength.set_number("shear_modulus", 6.0e7);
  strength.set_number("friction_slope", 0.1);
  strength.set_number("cohesion", 0.0);
  Parameters eos;
  eos.set_string("type", "linear");
  eos.set_number("density", 1800.0);
  eos.set_number("bulk_modulus", 1.0e8);
  Soil soil{make_material("soil", "", {}, eos, strength, Parameters{}), 1800.0, 0.1, 0.1};
  Model model = column(GeometryMode::plane_strain, soil, Sides::rollers, true);
  try {
    Solver<2> solver(model);
    FAIL() << "a K0 state outside the yield surface must be refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("part 'soil'"), std::string::npos) << what;
    EXPECT_NE(what.find("depth"), std::string::npos) << what;
    EXPECT_NE(what.find("outside the strength"), std::string::npos) << what;
  }
}
