// The generator's SPH charge is resolved the same way for every mass: for
// 10, 50, 100 and 500 kg on the meshes of the wang2005 cases (coarse,
// default, paper in r-z; coarse3d), the case as read holds
// charge.particles_across_radius particles along the charge's radius (3-D:
// the cube's half side) and the asked mass within 1 %, so a sweep over the
// charge mass compares sources of one resolution.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "buried_structure_checks.hpp"
#include "case/buried_structure_params.hpp"
#include "case/case_reader.hpp"
#include "common/verification.hpp"
#include "mesh/buried_structure.hpp"

namespace camouflet {
namespace {

BuriedStructureSpec wang2005(const std::string& name) {
  return read_buried_structure_params(std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "cases" / "wang2005" /
                                      (name + ".params.toml"));
}

struct ChargeRow {
  std::size_t along_radius = 0;  // particles in the row next to the centre, outwards
  double mass = 0.0;             // kg, reference density x particle volume (3-D: both halves)
};

// The row of charge particles just above the charge centre (and, in 3-D, just
// off the symmetry plane), from the centre outwards along r (x).
ChargeRow charge_row(const Model& model, const BuriedStructureSpec& spec, double spacing) {
  const test::SphZoneParticles p = test::sph_zone_particles(model);
  const int dim = spec.three_d ? 3 : 2;
  const double zc = -spec.burst_depth;
  ChargeRow row;
  row.mass = (spec.three_d ? 2.0 : 1.0) * p.charge_volume * spec.explosive_density;
  for (std::size_t i = 0; i < model.particles.count(); ++i) {
    if (model.particles.particle_part[i] != p.charge) continue;
    const double* x = &model.particles.coordinates[static_cast<std::size_t>(dim) * i];
    const double z = x[dim - 1] - zc;
    const bool first_layer = z > 0.0 && z < spacing && (!spec.three_d || x[1] < spacing);
    if (first_layer && x[0] > 0.0) ++row.along_radius;
  }
  return row;
}

void check_masses(const std::string& name) {
  for (double mass : {10.0, 50.0, 100.0, 500.0}) {
    BuriedStructureSpec spec = wang2005(name);
    spec.charge_mass = mass;
    const BuriedStructureLayout L = layout_buried_structure(spec);
    const Model model = read_case_text(buried_structure_case(spec, "test"), name + ".toml");
    const ChargeRow row = charge_row(model, spec, L.charge_spacing);
    const std::string what = fmt::format("{} mesh, {} kg", name, mass);
    EXPECT_EQ(row.along_radius, static_cast<std::size_t>(spec.charge_particles_across)) << what;
    test::verify({fmt::format("Buried-structure generator: SPH charge mass, {}", what),
                  "the asked mass (within 1 %)", mass, row.mass, 0.01, true, "kg"});
  }
}

TEST(BuriedChargeResolution, AxisymmetricMeshesEveryMass) {
  for (const char* name : {"coarse", "default", "paper"}) check_masses(name);
}

TEST(BuriedChargeResolution, ThreeDimensionalMeshEveryMass) {
  check_masses("coarse3d");
}

// The count is the user's: 4 across the radius gives 4, and the mass stays
// the asked one although a 4-cell disc misses a circle's area by several per
// cent (the region radius absorbs it).
TEST(BuriedChargeResolution, CountIsTheKeysAndBadCountsAreRefused) {
  BuriedStructureSpec spec = wang2005("coarse");
  spec.charge_particles_across = 4;
  const BuriedStructureLayout L = layout_buried_structure(spec);
  EXPECT_NEAR(L.charge_model_mass, spec.charge_mass, 1e-6 * spec.charge_mass);
  EXPECT_NEAR(L.charge_fill_radius / L.charge_radius, 1.0, 0.03);
  EXPECT_NEAR(L.charge_spacing, L.charge_fill_radius / 4.0, 1e-12);
  spec.charge_particles_across = 0;
  test::expect_refused(spec, "charge.particles_across_radius");
  spec.charge_particles_across = 65;
  test::expect_refused(spec, "charge.particles_across_radius");
}

}  // namespace
}  // namespace camouflet
