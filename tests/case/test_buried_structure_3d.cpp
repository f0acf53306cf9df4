// The 3-D variant of the buried-structure generator (src/mesh/buried_structure_3d.cpp):
// the half model it writes reads into one fused hex mesh whose soil, concrete
// and charge volumes are the analytic ones, the SPH zone and rebar mats are
// what was asked for, bad parameters are refused naming the key, and a tiny
// case runs with a finite energy balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>

#include "buried_structure_checks.hpp"
#include "case/buried_structure_params.hpp"
#include "case/case_reader.hpp"
#include "common/test_output.hpp"
#include "common/verification.hpp"
#include "mesh/buried_structure.hpp"
#include "solver/run.hpp"

namespace camouflet {
namespace {

using test::expect_refused;

// The paper's example in 3-D, coarse: a 4 m x 4 m x 1 m box, a 14 x 7 x 6 m half domain.
BuriedStructureSpec coarse_3d() {
  BuriedStructureSpec s;
  s.three_d = true;
  s.box_width = 4.0;
  s.domain_radius = 12.0;
  s.domain_side = 6.0;
  s.domain_depth = 6.0;
  s.size_near = 0.2;
  s.size_structure = 0.1;
  s.size_soil = 0.8;
  s.size_far = 2.0;
  return s;
}

// Bounding box of element e (the block generator's hexes are axis-aligned boxes).
std::pair<std::array<double, 3>, std::array<double, 3>> bounds_of(const FemMesh& mesh, std::size_t e) {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (int k = 0; k < 8; ++k) {
    const auto n = static_cast<std::size_t>(mesh.connectivity[8 * e + static_cast<std::size_t>(k)]);
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], mesh.coordinates[3 * n + static_cast<std::size_t>(i)]);
      hi[i] = std::max(hi[i], mesh.coordinates[3 * n + static_cast<std::size_t>(i)]);
    }
  }
  return {lo, hi};
}

std::string material_of(const Model& m, std::size_t e) {
  const std::string& name = m.parts[static_cast<std::size_t>(m.mesh.element_part[e])].name;
  return name.substr(0, name.find('_'));
}

double volume_of(const Model& m, const std::string& material) {
  double v = 0.0;
  for (std::size_t e = 0; e < m.mesh.element_count(); ++e) {
    if (material_of(m, e) != material) continue;
    const auto [lo, hi] = bounds_of(m.mesh, e);
    v += (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  }
  return v;
}

TEST(BuriedStructure3d, CaseReadsAsOneFusedHalfModel) {
  const BuriedStructureSpec spec = coarse_3d();
  const BuriedStructureLayout layout = layout_buried_structure(spec);
  const Model model = read_case_text(buried_structure_case(spec, "test"), "generated3d.toml");
  ASSERT_EQ(model.run.mode, GeometryMode::three_d);
  EXPECT_EQ(model.mesh.element_count(), layout.element_count);
  const FemMesh& mesh = model.mesh;

  // Fused: no two nodes at one place.
  EXPECT_FALSE(test::has_duplicate_nodes(mesh)) << "duplicate nodes: blocks not fused";

  // The box is fused with the soil: every node on the box's outer faces below
  // the ground (x = 6 or 10, y = 2, z = -1) belongs to a concrete and a soil element.
  std::vector<int> touches(mesh.node_count(), 0);  // bit 1: concrete, bit 2: soil
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    const int bit = material_of(model, e) == "concrete" ? 1 : material_of(model, e) == "soil" ? 2 : 0;
    for (int k = 0; k < 8; ++k) touches[static_cast<std::size_t>(mesh.connectivity[8 * e + k])] |= bit;
  }
  std::size_t face_nodes = 0, fused = 0;
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    const double x = mesh.coordinates[3 * n], y = mesh.coordinates[3 * n + 1],
                 z = mesh.coordinates[3 * n + 2];
    const bool in_box = x >= 6.0 - 1e-9 && x <= 10.0 + 1e-9 && y <= 2.0 + 1e-9 && z >= -1.0 - 1e-9;
    const bool outer = std::abs(x - 6.0) < 1e-9 || std::abs(x - 10.0) < 1e-9 || std::abs(y - 2.0) < 1e-9 ||
                       std::abs(z + 1.0) < 1e-9;
    if (!in_box || !outer || z > -1e-9) continue;
    ++face_nodes;
    fused += touches[n] == 3;
    // No node inside the box's hollow.
  }
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    const double x = mesh.coordinates[3 * n], y = mesh.coordinates[3 * n + 1],
                 z = mesh.coordinates[3 * n + 2];
    EXPECT_FALSE(x > 6.1 + 1e-9 && x < 9.9 - 1e-9 && y < 1.9 - 1e-9 && z < -0.1 - 1e-9 && z > -0.9 + 1e-9)
        << x << ", " << y << ", " << z;
  }
  EXPECT_GT(face_nodes, 1000u);
  EXPECT_EQ(fused, face_nodes) << "box nodes not shared with the soil";

  // Volumes of the half model (tolerance: round-off of the summed hexes).
  const double charge = 0.5 * 100.0 / 1630.0;  // half of the equal-volume cube
  const double outer = 0.5 * 4.0 * 4.0 * 1.0, inner = 0.5 * 3.8 * 3.8 * 0.8;
  const double domain = (6.0 + 12.0) * 6.0 * 6.0;
  test::verify({"3-D buried-structure generator: charge volume (half model)", "0.5 x 100 kg / 1630 kg/m^3",
                charge, volume_of(model, "charge"), 1e-9, true, "m^3"});
  test::verify({"3-D buried-structure generator: concrete volume (half model)",
                "closed box 4 x 4 x 1 m, 0.1 m walls, halved", outer - inner, volume_of(model, "concrete"),
                1e-9, true, "m^3"});
  test::verify({"3-D buried-structure generator: soil volume (half model)", "domain - box - charge",
                domain - outer - charge, volume_of(model, "soil"), 1e-9, true, "m^3"});

  // Gauges: groups A and B and targets 1-9, all in the symmetry plane.
  ASSERT_EQ(model.gauges.size(), 4u);
  EXPECT_EQ(model.gauges[2].points.size(), 9u);
  // The box's members, averaged (members.csv).
  ASSERT_EQ(model.gauges[3].points.size(), 4u);
  for (const auto& m : model.gauges[3].points) EXPECT_TRUE(m.member) << m.name;
  EXPECT_EQ(model.gauges[3].points[0].name, "front_wall");
  for (const auto& g : model.gauges)
    for (const auto& p : g.points) EXPECT_EQ(p.position[1], 0.0) << p.name;
  for (const auto& p : model.gauges[1].points)
    EXPECT_NEAR(p.position[0], -0.5 - p.position[2], 1e-5) << p.name;
  // The symmetry plane and the far faces; no condition on the ground surface.
  std::size_t symmetry = 0, far = 0;
  for (const auto& bc : model.boundaries) {
    symmetry += bc.kind == BoundaryKind::symmetry;
    far += bc.kind == BoundaryKind::transmitting;
  }
  EXPECT_GT(symmetry, 0u);
  EXPECT_GT(far, 0u);
  EXPECT_EQ(symmetry + far, model.boundaries.size());
}

TEST(BuriedStructure3d, SphZoneAndRebarMats) {
  const BuriedStructureSpec spec = test::with_sph_zone_and_rebar(coarse_3d(), 1.5, 0.025, 0.005);
  const BuriedStructureLayout L = layout_buried_structure(spec);
  const Model model = read_case_text(buried_structure_case(spec, "test"), "generated3d_sph.toml");
  ASSERT_EQ(model.joins.size(), 1u);
  const test::SphZoneParticles p = test::sph_zone_particles(model);
  ASSERT_GE(p.charge, 0);
  ASSERT_GE(p.zone, 0);
  const double charge_volume = p.charge_volume, zone_volume = p.zone_volume;
  EXPECT_EQ(p.charge_count, L.charge_particles);
  EXPECT_EQ(p.zone_count, L.zone_particles);
  // The half cube is tiled exactly: the charge mass is the given one.
  test::verify({"3-D buried-structure generator: SPH charge mass (both halves)",
                "100 kg TNT (paper section 5)", 100.0, 2.0 * charge_volume * 1630.0, 1e-9, true, "kg"});
  // Charge + zone tile the zone box 2R x R x (d + R) = 9 m^3 but for the cells
  // along the charge's surface, where the two lattices meet: at most half a
  // zone cell (0.1 m) over the half cube's surface (12 h^2 = 0.47 m^2), 0.047 m^3
  // or 0.5 %, plus its edges: tolerance 0.8 %.
  const double box = 2.0 * 1.5 * 1.5 * 2.0;
  test::verify({"3-D buried-structure generator: SPH zone + charge particle volume", "2 R^2 (d + R)", box,
                charge_volume + zone_volume, 0.008, true, "m^3"});
  // The hole: no FEM element left with its centre in the zone.
  for (std::size_t e = 0; e < model.mesh.element_count(); ++e) {
    const auto [lo, hi] = bounds_of(model.mesh, e);
    const double x = 0.5 * (lo[0] + hi[0]), y = 0.5 * (lo[1] + hi[1]), z = 0.5 * (lo[2] + hi[2]);
    EXPECT_FALSE(std::abs(x) < 1.5 && y < 1.5 && z > -2.0) << "element " << e << " in the SPH zone";
  }

  // Rebar: two mats in each of the five walls of the half model, bars both ways;
  // total steel = ratio x wall x mat area per direction (the strips tile each mat; areas printed to 9
  // digits).
  double steel = 0.0;
  for (const auto& bar : model.bars) {
    double len2 = 0.0;
    for (int i = 0; i < 3; ++i) len2 += std::pow(bar.to[i] - bar.from[i], 2);
    steel += bar.area * std::sqrt(len2);
  }
  const double ratio_t = 0.005 * 0.1;
  double expected = 0.0;
  for (double e : {0.025, 0.075}) {  // outer and inner mat: offset from the outer faces
    const double lx = 4.0 - 2 * e, ly = 2.0 - e, lz = 1.0 - 2 * e;
    expected += 2.0 * ratio_t * (2 * ly * lz + lx * lz + 2 * lx * ly);  // front+back, side, roof+floor
  }
  test::verify({"3-D buried-structure generator: rebar steel volume (half model)",
                "ratio x thickness x mat area, both directions", expected, steel, 1e-8, true, "m^3"});
  std::set<std::string> walls;
  for (const auto& bar : model.bars) walls.insert(bar.name.substr(0, bar.name.rfind('_')));
  EXPECT_EQ(walls.size(), 10u);
  EXPECT_NE(buried_structure_case(spec, "t").find("# rebar gauges (bars.csv): In-1=front_in_z1.1"),
            std::string::npos);
}

TEST(BuriedStructure3d, BadInputNamesTheKey) {
  auto s = coarse_3d();
  s.standoff = 0.2;  // inside the charge
  s.near_radius = 0.25;
  expect_refused(s, "structure.standoff");
  s = coarse_3d();
  s.sph_radius = 5.95;  // the SPH zone reaches the front wall at x = 6 m
  expect_refused(s, "sph.radius");
  s = coarse_3d();
  s.has_rebar = true;
  s.rebar_cover = -0.01;
  expect_refused(s, "rebar.cover");
  s = coarse_3d();
  s.burst_depth = 0.2;
  expect_refused(s, "charge.depth");
  s = coarse_3d();
  s.box_width = -1.0;
  expect_refused(s, "structure.width");
  s.box_width = 0.15;  // no room inside 0.1 m walls
  expect_refused(s, "structure.width");
  s = coarse_3d();
  s.box_width = 0.0;  // not given
  expect_refused(s, "structure.width");
  s = coarse_3d();
  s.domain_side = 2.0;  // the box's half width is 2 m
  expect_refused(s, "domain.side");
  s = coarse_3d();
  s.three_d = false;  // a width in r-z
  expect_refused(s, "structure.width");
}

TEST(BuriedStructure3d, ParameterFileKeysAndLines) {
  const std::string text =
      "[domain]\ngeometry = \"3d\"\nside = 6.0\n[structure]\nwidth = 4.0\nstandoff = 0.1\n[mesh]\n"
      "near_radius = 0.3\n";
  const BuriedStructureSpec s = read_buried_structure_params_text(text, "p3.toml");
  EXPECT_TRUE(s.three_d);
  try {
    layout_buried_structure(s);
    ADD_FAILURE() << "accepted an overlapping structure";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "structure.standoff");
    EXPECT_EQ(e.where().line, 6);
  }
  // structure.width in an axisymmetric parameter file: refused at its line.
  const BuriedStructureSpec rz = read_buried_structure_params_text("[structure]\n\nwidth = 4.0\n", "p2.toml");
  try {
    layout_buried_structure(rz);
    ADD_FAILURE() << "accepted a width in r-z";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "structure.width");
    EXPECT_EQ(e.where().line, 3);
  }
  EXPECT_THROW(read_buried_structure_params_text("[domain]\ngeometry = \"3-d\"\n", "p.toml"), InputError);
}

// Through `camouflet generate`: status 2 and one line naming file, line and key.
TEST(BuriedStructure3d, GenerateRefusesANegativeWidth) {
  const auto r = test::generate_from("generate-bad-3d", "width.params.toml",
                                     "[domain]\ngeometry = \"3d\"\n[structure]\nwidth = -1.0\n");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("width.params.toml:4"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("key 'structure.width'"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(r.case_file));
}

// A tiny 3-D case (2 kg TNT at 0.2 m beside a 0.6 m box) with the SPH zone and rebar.
BuriedStructureSpec tiny_3d() {
  BuriedStructureSpec s;
  s.three_d = true;
  s.charge_mass = 2.0;
  s.burst_depth = 0.2;
  s.standoff = 0.6;
  s.box_length = 0.6;
  s.box_width = 0.6;
  s.box_height = 0.4;
  s.wall_thickness = 0.06;
  s.domain_radius = 1.5;
  s.domain_side = 1.0;
  s.domain_depth = 1.0;
  s.near_radius = 0.25;
  s.sph_radius = 0.3;
  s.size_near = 0.05;
  s.size_structure = 0.06;
  s.size_soil = 0.15;
  s.size_far = 0.3;
  s.has_rebar = true;
  s.rebar_cover = 0.015;
  s.rebar_ratio = 0.005;
  s.run.end_time = 0.25e-3;
  s.run.field_interval = 0.0;
  s.run.gauge_interval = 2e-5;
  s.gauge_count = 3;
  return s;
}

RunSummary run_tiny(const BuriedStructureSpec& s, const std::string& name) {
  const Model model = read_case_text(buried_structure_case(s, "test"), name + ".toml");
  const RunSummary summary = run_model(model, test::quiet_run_options(test::fresh_test_output(name)));
  std::cout << name << ": " << model.mesh.element_count() << " elements, " << model.particles.count()
            << " particles, " << model.bars.size() << " bars, " << summary.cycles << " cycles, energy error "
            << summary.energy.relative_error << "\n";
  return summary;
}

// Its first 0.25 ms run with a finite, small energy-balance error.
TEST(BuriedStructure3d, TinyCaseRuns) {
  const RunSummary summary = run_tiny(tiny_3d(), "buried_3d_tiny");
  ASSERT_FALSE(summary.failed) << summary.stop_reason;
  EXPECT_GT(summary.cycles, 20);
  EXPECT_TRUE(std::isfinite(summary.energy.relative_error));
  EXPECT_LT(summary.energy.relative_error, 0.05);
}

// The same without SPH zone and rebar: the charge as hex elements (the half
// cube), lit on the symmetry plane, runs its first 0.1 ms.
TEST(BuriedStructure3d, TinyFemChargeCaseRuns) {
  BuriedStructureSpec s = tiny_3d();
  s.sph_radius = 0.0;
  s.has_rebar = false;
  s.run.end_time = 0.1e-3;
  const RunSummary summary = run_tiny(s, "buried_3d_tiny_fem");
  ASSERT_FALSE(summary.failed) << summary.stop_reason;
  EXPECT_GT(summary.cycles, 10);
  EXPECT_TRUE(std::isfinite(summary.energy.relative_error));
  EXPECT_LT(summary.energy.relative_error, 0.05);
}

}  // namespace
}  // namespace camouflet
