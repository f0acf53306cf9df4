// SPH parts filled from a Gmsh physical surface/volume (particle
// parts): tiny checked-in meshes (tests/case/meshes) whose areas and volumes
// are known in closed form. The particle volumes (cells whose centres lie in
// the region) must add up to the region's measure within the boundary-cell
// error, in plane, r-z (Pappus) and 3-D, through the library and a case file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <numeric>

#include "case/case_reader.hpp"
#include "common/verification.hpp"
#include "mesh/gmsh_import.hpp"
#include "mesh/particle_fill.hpp"

namespace camouflet {
namespace {

const std::filesystem::path meshes = std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "tests/case/meshes";
const std::filesystem::path here = std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "tests/case/case.toml";

// "house": unit square (one quadrilateral) with a triangular roof up to (0.5, 1.5): area 1.25.
ParticleSet fill_house(GeometryMode mode, double spacing) {
  ParticleFillSpec spec;
  spec.region.shape = ParticleRegion::Shape::mesh;
  spec.region.mesh = std::make_shared<const SimplexRegion>(
      import_gmsh_region(2, meshes / "house.msh", "house", SourceLocation{}, SourceLocation{}));
  spec.spacing = spacing;
  ParticleSet particles;
  fill_particles(particles, spec, mode);
  return particles;
}

double total_volume(const ParticleSet& p) {
  return std::accumulate(p.volume.begin(), p.volume.end(), 0.0);
}

TEST(GmshFill, PlaneSurfaceOfQuadAndTriangle) {
  const auto region = import_gmsh_region(2, meshes / "house.msh", "house", {}, {});
  EXPECT_EQ(region.size(), 3u);  // quad -> 2 triangles, + the roof
  EXPECT_NEAR(region.measure(), 1.25, 1e-14);
  const ParticleSet p = fill_house(GeometryMode::plane_strain, 0.02);
  // Every particle inside the house: below the roof line y <= 1.5 - |x - 0.5|.
  double worst_outside = 0.0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.coordinates[2 * i], y = p.coordinates[2 * i + 1];
    worst_outside = std::max({worst_outside, y - (1.5 - std::abs(x - 0.5)), -x, x - 1.0, -y});
  }
  EXPECT_LE(worst_outside, 1e-12);  // cells centred on the roof line count as inside
  // The square part is lattice-aligned (exact); the roof's two slanted edges
  // cut cells: error ~ (edge length x dx / 2) x a random sign, well under 1 %.
  test::verify({"Gmsh-surface particle fill (quad + triangle, dx = 0.02): total particle area",
                "area of the physical surface, 1.25 m^2", 1.25, total_volume(p), 0.01, true, "m^2"});
}

TEST(GmshFill, AxisymmetricRingVolumesGivePappusVolume) {
  const ParticleSet p = fill_house(GeometryMode::axisymmetric, 0.02);
  // Revolved about r = 0: centroid radius 0.5 for square and roof alike -> V = 2 pi 0.5 1.25.
  const double exact = 1.25 * std::numbers::pi;
  test::verify({"Gmsh-surface particle fill in r-z (dx = 0.02): total ring volume",
                "Pappus: 2 pi r_c A = 1.25 pi m^3", exact, total_volume(p), 0.01, true, "m^3"});
}

TEST(GmshFill, TetrahedronVolumeAndHexBox) {
  ParticleFillSpec spec;
  spec.region.shape = ParticleRegion::Shape::mesh;
  spec.region.mesh = std::make_shared<const SimplexRegion>(
      import_gmsh_region(3, meshes / "corner_tet.msh", "corner", {}, {}));
  spec.spacing = 0.04;
  ParticleSet tet;
  fill_particles(tet, spec, GeometryMode::three_d);
  test::verify({"Gmsh-volume particle fill (one tetrahedron, dx = 0.04): total particle volume",
                "volume 1/6 m^3", 1.0 / 6.0, total_volume(tet), 0.03, true, "m^3"});
  // A hexahedron (2 x 1 x 3 box) cut into six tetrahedra: the lattice tiles it exactly.
  spec.region.mesh =
      std::make_shared<const SimplexRegion>(import_gmsh_region(3, meshes / "one_hex.msh", "cube", {}, {}));
  spec.spacing = 0.1;
  ParticleSet hex;
  fill_particles(hex, spec, GeometryMode::three_d);
  EXPECT_EQ(hex.count(), 20u * 10u * 30u);
  EXPECT_NEAR(total_volume(hex), 6.0, 1e-9);
}

const char* gmsh_fill_case = R"([run]
geometry = "plane_strain"
end_time = 1e-3
[materials.gas]
eos = { type = "ideal_gas", density = 1.0, gamma = 1.4, specific_energy = 1e5 }
[[parts]]
name = "house"
material = "gas"
kind = "sph"
fill = { shape = "gmsh", file = "meshes/house.msh", physical = "%s", spacing = 0.05 }
)";

std::string with_physical(const std::string& physical) {
  std::string text = gmsh_fill_case;
  text.replace(text.find("%s"), 2, physical);
  return text;
}

TEST(GmshFill, CaseFileFillsAndNamesBadPhysical) {
  const Model m = read_case_text(with_physical("house"), here);
  EXPECT_GT(m.particles.count(), 400u);
  try {
    read_case_text(with_physical("hous"), here);
    FAIL() << "unknown physical group accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("physical"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("did you mean 'house'"), std::string::npos) << e.what();
  }
  // A 1-D group (the eaves line) is no region.
  EXPECT_THROW(read_case_text(with_physical("eaves"), here), InputError);
}

}  // namespace
}  // namespace camouflet
