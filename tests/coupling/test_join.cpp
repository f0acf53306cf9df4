// Joined SPH-FEM interface (issue 7, "What it must show" 1-3 and 6): a plane
// elastic P-pulse crosses FEM -> SPH -> FEM in one material. The join is not a
// material interface: reflections below 5 % of the incident amplitude,
// transmission within 5 %, total energy within 1 % over the crossing; graded
// particles (spacing ratio 2 against the elements) reflect below 10 %.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "common/verification.hpp"
#include "join_models.hpp"

using namespace camouflet;

namespace {

void check_crossing(const std::string& label, const test::JoinCrossing& r, double reflection_limit) {
  fmt::print(
      "{}: incident {:.4f}, reflected FEM->SPH {:.4f}, SPH->FEM {:.4f}, in particles {:.4f}, "
      "transmitted {:.4f}, energy change {:.4g}, join work {:.4g}\n",
      label, r.incident, r.reflected_fem_to_sph, r.reflected_sph_to_fem, r.in_particles, r.transmitted,
      r.energy_change, r.join_work);
  test::verify({label + ": reflection at the FEM->SPH join / incident", "0 (one material)", 0.0,
                r.reflected_fem_to_sph / r.incident, reflection_limit, false, "-"});
  test::verify({label + ": reflection at the SPH->FEM join / incident", "0 (one material)", 0.0,
                r.reflected_sph_to_fem / r.incident, reflection_limit, false, "-"});
  // The energy balance closes with the join work booked (E - E0 - W_join).
  test::verify({label + ": energy balance with the join work", "0", 0.0, r.energy_change - r.join_work, 0.01,
                false, "-"});
}

}  // namespace

TEST(SphFemJoin, PlanePulsePlaneStrain) {
  check_crossing("Joined SPH zone, P-pulse, plane strain",
                 test::join_crossing<2>(GeometryMode::plane_strain, 5e-3, 5e-3), 0.05);
}

TEST(SphFemJoin, PlanePulseAxisymmetric) {
  check_crossing("Joined SPH zone, P-pulse, axisymmetric",
                 test::join_crossing<2>(GeometryMode::axisymmetric, 5e-3, 5e-3), 0.05);
}

TEST(SphFemJoin, PlanePulse3D) {
  check_crossing("Joined SPH zone, P-pulse, 3-D", test::join_crossing<3>(GeometryMode::three_d, 5e-3, 5e-3),
                 0.05);
}

TEST(SphFemJoin, GradedParticlesSpacingRatio2) {
  check_crossing("Joined SPH zone, particles at half the element size (ratio 2), plane strain",
                 test::join_crossing<2>(GeometryMode::plane_strain, 5e-3, 2.5e-3), 0.10);
}

TEST(SphFemJoin, SpacingRatioBeyondLimitIsRefused) {
  try {
    test::join_crossing<2>(GeometryMode::plane_strain, 6e-3, 2e-3);
    FAIL() << "a spacing ratio of 3 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("spacing"), std::string::npos) << e.what();
  }
}

TEST(SphFemJoin, RegionOutsideTheMeshIsRefused) {
  Model model =
      test::block_model(GeometryMode::plane_strain, {{"bar", 0, {0, 0, 0}, {1, 1, 0}, {10, 10, 1}}}, {});
  Part zone;
  zone.name = "zone";
  zone.kind = PartKind::sph;
  zone.material = 0;
  model.parts.push_back(zone);
  ParticleFillSpec fill;
  fill.part = 1;
  fill.spacing = 0.1;
  fill.region.min = {2, 2, 0};
  fill.region.max = {3, 3, 0};
  try {
    make_joined_zone(model, fill);
    FAIL() << "a join between non-adjacent parts was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("region"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not adjacent"), std::string::npos) << e.what();
  }
}
