// The buried-structure generator (src/mesh/buried_structure.hpp): the case it
// writes for the paper's example is read by the case reader into one fused
// mesh of the right masses, its gauges sit where the paper puts them, and bad
// parameters are refused naming the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "buried_structure_checks.hpp"
#include "case/buried_structure_params.hpp"
#include "case/case_reader.hpp"
#include "common/verification.hpp"
#include "mesh/buried_structure.hpp"

namespace camouflet {
namespace {

using test::expect_refused;

BuriedStructureSpec paper_coarse() {
  BuriedStructureSpec s;
  s.size_near = 0.1;
  s.size_structure = 0.05;
  s.size_soil = 0.4;
  s.size_far = 1.5;
  s.domain_radius = 14.0;
  s.domain_depth = 9.0;
  return s;
}

// Volume of revolution of every element of `part_prefix` (m^3), by the
// centroid rule (exact for the rectangles of the block generator).
double volume_of(const Model& m, const std::string& part_prefix) {
  double v = 0.0;
  const auto& mesh = m.mesh;
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    if (m.parts[static_cast<std::size_t>(mesh.element_part[e])].name.rfind(part_prefix, 0) != 0) continue;
    double rmin = 1e300, rmax = -1e300, zmin = 1e300, zmax = -1e300;
    for (int k = 0; k < 4; ++k) {
      const auto n = static_cast<std::size_t>(mesh.connectivity[4 * e + static_cast<std::size_t>(k)]);
      rmin = std::min(rmin, mesh.coordinates[2 * n]);
      rmax = std::max(rmax, mesh.coordinates[2 * n]);
      zmin = std::min(zmin, mesh.coordinates[2 * n + 1]);
      zmax = std::max(zmax, mesh.coordinates[2 * n + 1]);
    }
    v += 2.0 * std::numbers::pi * 0.5 * (rmin + rmax) * (rmax - rmin) * (zmax - zmin);
  }
  return v;
}

// Elements whose centre lies in the SPH zone r < radius, z > -depth (the hole must hold none).
std::size_t elements_in_zone(const Model& model, double radius, double depth) {
  std::size_t count = 0;
  for (std::size_t e = 0; e < model.mesh.element_count(); ++e) {
    double r = 0.0, z = 0.0;
    for (int k = 0; k < 4; ++k) {
      const auto n = static_cast<std::size_t>(model.mesh.connectivity[4 * e + static_cast<std::size_t>(k)]);
      r += 0.25 * model.mesh.coordinates[2 * n];
      z += 0.25 * model.mesh.coordinates[2 * n + 1];
    }
    if (r < radius && z > -depth) ++count;
  }
  return count;
}

TEST(BuriedStructure, PaperCaseReadsAsOneFusedMesh) {
  const BuriedStructureSpec spec = paper_coarse();
  const std::string text = buried_structure_case(spec, "test");
  const Model model = read_case_text(text, "generated.toml");
  const BuriedStructureLayout layout = layout_buried_structure(spec);
  EXPECT_EQ(model.run.mode, GeometryMode::axisymmetric);
  EXPECT_EQ(model.mesh.element_count(), layout.element_count);
  // Fused: no two nodes at the same place (adjacent blocks share theirs).
  EXPECT_FALSE(test::has_duplicate_nodes(model.mesh)) << "duplicate nodes: blocks not fused";
  // No nodes inside the box (its interior is empty).
  for (std::size_t n = 0; n < model.mesh.node_count(); ++n) {
    const double r = model.mesh.coordinates[2 * n], z = model.mesh.coordinates[2 * n + 1];
    EXPECT_FALSE(r > 6.1 + 1e-9 && r < 9.9 - 1e-9 && z < -0.1 - 1e-9 && z > -0.9 + 1e-9) << r << ", " << z;
  }

  // The charge: 100 kg of TNT as an equal-volume cylinder.
  const double charge_volume = volume_of(model, "charge");
  test::verify({"Buried-structure generator: charge volume", "100 kg / 1630 kg/m^3", 100.0 / 1630.0,
                charge_volume, 1e-7, true, "m^3"});
  // The concrete box: a ring of rectangular section with 0.1 m walls.
  const double r0 = 6.0, r1 = 10.0, t = 0.1;
  const auto ring = [](double a, double b, double h) { return std::numbers::pi * (b * b - a * a) * h; };
  const double box = ring(r0, r1, 1.0) - ring(r0 + t, r1 - t, 1.0 - 2 * t);
  test::verify({"Buried-structure generator: concrete volume", "ring section 4 m x 1 m, 0.1 m walls", box,
                volume_of(model, "concrete"), 1e-7, true, "m^3"});

  ASSERT_EQ(model.gauges.size(), 4u);
  EXPECT_EQ(model.gauges[2].points.size(), 9u);
  // The box's members, averaged (members.csv).
  ASSERT_EQ(model.gauges[3].points.size(), 4u);
  for (const auto& m : model.gauges[3].points) EXPECT_TRUE(m.member) << m.name;
  EXPECT_EQ(model.gauges[3].points[0].name, "front_wall");  // targets 1-9
  // Group B on the 45-degree line from the charge centre.
  for (const auto& p : model.gauges[1].points)
    EXPECT_NEAR(p.position[0], -0.5 - p.position[1], 1e-5) << p.name;
  ASSERT_EQ(model.detonations.size(), 1u);
}

TEST(BuriedStructure, GradedFineNearTheChargeAndTheStructure) {
  const BuriedStructureLayout L = layout_buried_structure(paper_coarse());
  double near = 0.0, far = 0.0, wall = 1e9;
  for (std::size_t k = 0; k + 1 < L.r_lines.size(); ++k) {
    const double a = L.r_lines[k], b = L.r_lines[k + 1];
    if (b <= 1.0) near = std::max(near, b - a);
    if (a >= 6.0 && b <= 6.1 + 1e-9) wall = std::min(wall, b - a);
    far = std::max(far, b - a);
  }
  // Block lines are not cells: check only that the wall is its own block and the grid reaches the edge.
  EXPECT_NEAR(wall, 0.1, 1e-9);
  EXPECT_NEAR(L.r_lines.back(), 14.0, 1e-12);
  EXPECT_NEAR(L.z_lines.front(), -9.0, 1e-12);
  EXPECT_GT(L.reflection_time, 0.005);
  EXPECT_GT(far, near);
}

TEST(BuriedStructure, BadInputNamesTheKey) {
  auto s = paper_coarse();
  s.standoff = 0.2;  // inside the charge (radius 0.245 m)
  s.near_radius = 0.25;
  expect_refused(s, "structure.standoff");
  s = paper_coarse();
  s.near_radius = 6.5;  // near-field (SPH) zone crossing the front wall
  expect_refused(s, "mesh.near_radius");
  s = paper_coarse();
  s.has_rebar = true;
  s.rebar_cover = -0.01;
  expect_refused(s, "rebar.cover");
  s = paper_coarse();
  s.burst_depth = 0.2;  // not buried
  expect_refused(s, "charge.depth");
  s = paper_coarse();
  s.domain_radius = 9.0;
  expect_refused(s, "domain.radius");
}

// Gravity: the case gets [run] gravity, a dynamic relaxation of the given period and Jaky's
// geostatic state on every soil part, FEM and SPH (none on the box or the charge).
TEST(BuriedStructure, GravityWritesGeostaticSoilAndRelaxation) {
  BuriedStructureSpec spec = test::with_sph_zone_and_rebar(paper_coarse(), 1.5, 0.025, 0.005);
  spec.run.gravity = 9.81;
  spec.run.relaxation_period = 0.21;
  const Model model = read_case_text(buried_structure_case(spec, "test"), "gravity.toml");
  EXPECT_EQ(model.run.gravity[1], -9.81);
  ASSERT_TRUE(model.run.relaxation.has_value());
  EXPECT_EQ(model.run.relaxation->period, 0.21);
  std::size_t soil = 0;
  for (const Part& part : model.parts) {
    const std::string& material = model.materials[static_cast<std::size_t>(part.material)].name;
    const bool soil_part = material == "soil";
    EXPECT_EQ(part.geostatic.has_value(), soil_part) << part.name;
    if (part.kind == PartKind::sph) {
      EXPECT_EQ(soil_part, part.name == "near_field") << part.name;
    }
    if (soil_part) {
      ++soil;
      EXPECT_EQ(part.geostatic->surface, 0.0);
      EXPECT_FALSE(part.geostatic->k0.has_value()) << "Jaky's K0";
    }
  }
  EXPECT_GT(soil, 10u);

  BuriedStructureSpec bad = paper_coarse();
  bad.run.gravity = 9.81;  // no period
  expect_refused(bad, "run.relaxation_period");
  bad = paper_coarse();
  bad.run.relaxation_period = 0.2;  // no gravity
  expect_refused(bad, "run.relaxation_period");
  bad = paper_coarse();
  bad.run.gravity = -9.81;
  bad.run.relaxation_period = 0.2;
  expect_refused(bad, "run.gravity");
}

// The paper's zoning (Fig. 6): an SPH zone around the charge, joined to the
// FEM soil, the charge as SPH explosive particles, reinforcement as bars.
TEST(BuriedStructure, SphZoneAndRebarCase) {
  const BuriedStructureSpec spec = test::with_sph_zone_and_rebar(paper_coarse(), 1.5, 0.025, 0.005);
  const BuriedStructureLayout L = layout_buried_structure(spec);
  const Model model = read_case_text(buried_structure_case(spec, "test"), "generated.toml");
  ASSERT_EQ(model.joins.size(), 1u);
  const test::SphZoneParticles p = test::sph_zone_particles(model);
  ASSERT_GE(p.charge, 0);
  ASSERT_GE(p.zone, 0);
  EXPECT_EQ(model.joins[0].sph_part, p.zone);
  const double charge_volume = p.charge_volume, zone_volume = p.zone_volume;
  EXPECT_EQ(p.charge_count, L.charge_particles);
  EXPECT_EQ(p.zone_count, L.zone_particles);
  // The charge's cell-centred disc holds the charge mass: its region radius is chosen for that
  // (to the 12 digits the case file carries).
  test::verify({"Buried-structure generator: SPH charge mass", "100 kg TNT (paper section 5)", 100.0,
                charge_volume * 1630.0, 1e-9, true, "kg"});
  // Charge + zone fill the zone's volume of revolution (pi R^2 (d + R)) to within the cells along the
  // charge's boundary, where the two lattices meet.
  const double zone_box = std::numbers::pi * 1.5 * 1.5 * 2.0;
  test::verify({"Buried-structure generator: SPH zone + charge particle volume", "pi R^2 (d + R)", zone_box,
                charge_volume + zone_volume, 0.01, true, "m^3"});
  // The hole: no soil element left with its centre in the zone, and no concrete cut.
  EXPECT_EQ(elements_in_zone(model, 1.5, 2.0), 0u);
  EXPECT_NEAR(volume_of(model, "concrete"),
              volume_of(read_case_text(buried_structure_case(paper_coarse(), "t"), "plain.toml"), "concrete"),
              1e-9);
  // Reinforcement: an inner and an outer mat in the front and back walls, the roof and the floor.
  EXPECT_EQ(model.bars.size(), 8u);
  EXPECT_NE(buried_structure_case(spec, "test").find("# rebar gauges (bars.csv): In-1=front_in.1"),
            std::string::npos);
}

TEST(BuriedStructure, SphZoneBadInputNamesTheKey) {
  auto s = paper_coarse();
  s.sph_radius = 5.95;  // reaches the front wall at r = 6 m
  expect_refused(s, "sph.radius");
  s.sph_radius = 0.3;  // the charge (radius 0.245 m) with less than two particle spacings of soil
  expect_refused(s, "sph.radius");
  s.sph_radius = -1.0;
  expect_refused(s, "sph.radius");
  s = paper_coarse();
  s.hourglass_coefficient = 0.0;
  expect_refused(s, "run.hourglass_coefficient");
  s = test::with_sph_zone_and_rebar(paper_coarse(), 3.5, 0.025, 0.005);
  s.sph_depth = 0.8;  // bottom above the charge's (0.5 + 0.245 m) and two spacings
  expect_refused(s, "sph.depth");
  s.sph_depth = -2.0;
  expect_refused(s, "sph.depth");
  s.sph_depth = s.domain_depth;  // the zone reaches the bottom edge
  expect_refused(s, "sph.depth");
}

// A zone wider than deep (sph.depth): the crater is wide and shallow (the wang2005 cases use
// r <= 3.5 m, down to 2 m). The particles fill exactly pi R^2 depth, and no element is left in it.
TEST(BuriedStructure, SphZoneWithItsOwnDepth) {
  BuriedStructureSpec spec = test::with_sph_zone_and_rebar(paper_coarse(), 3.5, 0.025, 0.005);
  spec.sph_depth = 2.0;
  const Model model = read_case_text(buried_structure_case(spec, "test"), "shallow.toml");
  // The generated case asks for the stiffness-form hourglass control.
  EXPECT_EQ(model.run.hourglass, HourglassForm::stiffness);
  EXPECT_DOUBLE_EQ(model.run.hourglass_coefficient, 0.1);
  const test::SphZoneParticles p = test::sph_zone_particles(model);
  ASSERT_GE(p.zone, 0);
  test::verify({"Buried-structure generator: SPH zone (sph.depth) + charge particle volume", "pi R^2 depth",
                std::numbers::pi * 3.5 * 3.5 * 2.0, p.charge_volume + p.zone_volume, 0.01, true, "m^3"});
  EXPECT_EQ(elements_in_zone(model, 3.5, 2.0), 0u);
  // The parameter file's key, and its line when refused.
  const auto r = test::generate_from("generate-bad", "shallow.params.toml",
                                     "[charge]\nmass = 100.0\n[sph]\nradius = 3.5\ndepth = 0.6\n");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("shallow.params.toml:5"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("key 'sph.depth'"), std::string::npos) << r.output;
}

// Through `camouflet generate`: status 2 and one line naming file, line and key.
TEST(BuriedStructure, GenerateRefusesAnSphZoneCrossingTheStructure) {
  const auto r =
      test::generate_from("generate-bad", "crossing.params.toml",
                          "[charge]\nmass = 100.0\n[structure]\nstandoff = 6.0\n[sph]\nradius = 5.95\n");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("crossing.params.toml:6"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("key 'sph.radius'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("crosses the structure"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(r.case_file));
}

TEST(BuriedStructure, ParameterFileKeysAndLines) {
  const std::string text =
      "[charge]\nmass = 100.0\ndepth = 0.5\n[structure]\nstandoff = 0.1\n[mesh]\nnear_radius = 0.3\n";
  const BuriedStructureSpec s = read_buried_structure_params_text(text, "p.toml");
  try {
    layout_buried_structure(s);
    ADD_FAILURE() << "accepted an overlapping structure";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "structure.standoff");
    EXPECT_EQ(e.where().line, 5);
    EXPECT_EQ(e.where().file, "p.toml");
  }
  try {
    read_buried_structure_params_text("[charge]\nmas = 1\n", "p.toml");
    ADD_FAILURE() << "accepted a misspelt key";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "charge.mas");
  }
}

// structure.interface = "slide": the box's concrete parts are detached from the soil along the
// faces they share (front wall, floor and rear wall; the roof is the ground surface), and the
// case carries the friction.
TEST(BuriedStructure, SlideInterfaceDetachesTheBox) {
  BuriedStructureSpec spec = paper_coarse();
  const Model fused = read_case_text(buried_structure_case(spec, "test"), "fused.toml");
  spec.slide_interface = true;
  spec.interface_friction = 0.4;
  const std::string text = buried_structure_case(spec, "test");
  EXPECT_NE(text.find("[[slide_surfaces]]"), std::string::npos);
  const Model model = read_case_text(text, "slide.toml");
  ASSERT_EQ(model.slide_surfaces.size(), 1u);
  const SlideSurface& slide = model.slide_surfaces[0];
  EXPECT_DOUBLE_EQ(slide.friction, 0.4);
  // The interface is the open line front wall - floor - rear wall (the roof is the ground): 1 m +
  // 4 m + 1 m of faces, one node more than faces doubled.
  ASSERT_EQ(slide.elements_a.size(), slide.elements_b.size());
  double length = 0.0;
  for (std::size_t k = 0; k < slide.elements_a.size(); ++k) {
    const auto* c = model.mesh.coordinates.data();
    const auto p = static_cast<std::size_t>(slide.faces_a[2 * k]), q = static_cast<std::size_t>(slide.faces_a[2 * k + 1]);
    length += std::hypot(c[2 * q] - c[2 * p], c[2 * q + 1] - c[2 * p + 1]);
    const bool on_box = (c[2 * p] == 6.0 && c[2 * q] == 6.0) || (c[2 * p] == 10.0 && c[2 * q] == 10.0) ||
                        (c[2 * p + 1] == -1.0 && c[2 * q + 1] == -1.0);
    EXPECT_TRUE(on_box) << c[2 * p] << ", " << c[2 * p + 1];
  }
  EXPECT_NEAR(length, 6.0, 1e-9);
  EXPECT_EQ(model.mesh.node_count(), fused.mesh.node_count() + slide.elements_a.size() + 1);
  EXPECT_EQ(model.mesh.element_count(), fused.mesh.element_count());
  for (std::size_t k = 0; k < slide.elements_a.size(); ++k) {
    const auto a = static_cast<std::size_t>(slide.elements_a[k]), b = static_cast<std::size_t>(slide.elements_b[k]);
    EXPECT_EQ(model.parts[static_cast<std::size_t>(model.mesh.element_part[a])].name.rfind("concrete", 0), 0u);
    EXPECT_EQ(model.parts[static_cast<std::size_t>(model.mesh.element_part[b])].name.rfind("soil", 0), 0u);
  }
  // A friction coefficient without a slide interface is refused, naming the key.
  try {
    read_buried_structure_params_text("[structure]\nfriction = 0.4\n", "p.toml");
    ADD_FAILURE() << "accepted a friction on a fused interface";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "structure.friction");
  }
  const BuriedStructureSpec read =
      read_buried_structure_params_text("[structure]\ninterface = \"slide\"\nfriction = 0.3\n", "p.toml");
  EXPECT_TRUE(read.slide_interface);
  EXPECT_DOUBLE_EQ(read.interface_friction, 0.3);
}

}  // namespace
}  // namespace camouflet
