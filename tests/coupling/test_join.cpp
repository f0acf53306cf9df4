// Joined SPH-FEM interface: a plane
// elastic P-pulse crosses FEM -> SPH -> FEM in one material. The join is not a
// material interface: reflections below 5 % of the incident amplitude,
// transmission within 5 %, total energy within 1 % over the crossing, also with
// graded particles (spacing ratio 2 against the elements, where the reflection is held below
// 10 %).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "common/verification.hpp"
#include "join_models.hpp"

using namespace camouflet;

namespace {

// The viscosity switch (SphOptions::viscosity_switch, Morris & Monaghan 1997): alpha relaxes to
// 0.1 in the smooth pulse instead of damping it with alpha = 1 (0.91 of the amplitude left
// after 10 particles with alpha = 1, 0.99 with the switch).
sph::SphOptions with_switch() {
  sph::SphOptions sph;
  sph.viscosity_switch = true;
  return sph;
}

struct Limits {
  double reflection = 0.05;
  double energy = 0.01;      // energy change within 1 %
  bool transmission = true;  // transmission within 5 % both ways
  std::string energy_reference = "0 (within 1 %)";
};

void check_crossing(const std::string& label, const test::JoinCrossing& r, const Limits& limits) {
  const double fem_to_sph = r.after_fem_to_sph / r.before_fem_to_sph;
  const double sph_to_fem = r.after_sph_to_fem / r.before_sph_to_fem;
  fmt::print(
      "{}: incident {:.4f}, reflected FEM->SPH {:.4f}, SPH->FEM {:.4f}, in particles {:.4f}, "
      "transmitted {:.4f}, transmission FEM->SPH {:.4f}, SPH->FEM {:.4f}, energy change {:.4g}, join work "
      "{:.4g}\n",
      label, r.incident, r.reflected_fem_to_sph, r.reflected_sph_to_fem, r.in_particles, r.transmitted,
      fem_to_sph, sph_to_fem, r.energy_change, r.join_work);
  test::verify({label + ": reflection at the FEM->SPH join / incident", "0 (one material)", 0.0,
                r.reflected_fem_to_sph / r.incident, limits.reflection, false, "-"});
  test::verify({label + ": reflection at the SPH->FEM join / incident", "0 (one material)", 0.0,
                r.reflected_sph_to_fem / r.incident, limits.reflection, false, "-"});
  if (limits.transmission) {
    // Peak 10 cells after the join over the peak 10 cells before it.
    test::verify({label + ": transmission FEM->SPH (peak 0.05 m after / 0.05 m before the join)", "1", 1.0,
                  fem_to_sph, 0.05, false, "-"});
    test::verify({label + ": transmission SPH->FEM (peak 0.05 m after / 0.05 m before the join)", "1", 1.0,
                  sph_to_fem, 0.05, false, "-"});
  }
  // Total energy (kinetic + internal + hourglass) over both crossings, before the pulse reaches
  // the transmitting far end.
  test::verify({label + ": total energy change over the two crossings / pulse energy",
                limits.energy_reference, 0.0, r.energy_change, limits.energy, false, "-"});
  // The energy balance closes with the join work booked (E - E0 - W_join).
  test::verify({label + ": energy balance with the join work", "0", 0.0, r.energy_change - r.join_work, 0.01,
                false, "-"});
}

}  // namespace

TEST(SphFemJoin, PlanePulsePlaneStrain) {
  check_crossing("Joined SPH zone, P-pulse, plane strain",
                 test::join_crossing<2>(GeometryMode::plane_strain, 5e-3, 5e-3, with_switch()), {});
}

TEST(SphFemJoin, PlanePulseAxisymmetric) {
  // The column lies along the axis, between the axis and a roller at r = 4 cells: the images of
  // the coupling points across the roller carry their element's ring weight (sph_fem_join.cpp).
  // Energy bound 1.5 %, not the usual 1 %: the faces take the pair reactions with the
  // coupling point's own ring radius, R = -2 pi r_j A_i A_j (sigma_i + sigma_j) . grad W, which next
  // to the axis (and to a roller) is not minus the particles' pair force, so the join gives up
  // momentum and energy there (measured -1.07 % over the two crossings, -0.67 % with R = -F). The
  // whole of this 4-cell column lies in that band; R = -F drove the face nodes next to the axis
  // through the elements below them in the buried-structure case (docs/theory/coupling.md).
  Limits limits;
  limits.energy = 0.015;
  limits.energy_reference = "0 (1 % elsewhere; 1.5 % for this column within 4 cells of the axis)";
  check_crossing("Joined SPH zone, P-pulse, axisymmetric",
                 test::join_crossing<2>(GeometryMode::axisymmetric, 5e-3, 5e-3, with_switch()), limits);
}

TEST(SphFemJoin, PlanePulseAxisymmetricAnnulus) {
  // The same crossing in an annulus r in [0.05, 0.07] m between two rollers, away from the axis:
  // every lateral side is a mirror plane at r > 0, where a ring-weighted image differs most from
  // a plane one.
  test::ColumnSection annulus;
  annulus.inner = 0.05;
  check_crossing("Joined SPH zone, P-pulse, axisymmetric annulus r = 0.05-0.07 m",
                 test::join_crossing<2>(GeometryMode::axisymmetric, 5e-3, 5e-3, with_switch(), annulus), {});
}

TEST(SphFemJoin, PlanePulse3D) {
  check_crossing("Joined SPH zone, P-pulse, 3-D",
                 test::join_crossing<3>(GeometryMode::three_d, 5e-3, 5e-3, with_switch()), {});
}

TEST(SphFemJoin, GradedParticlesSpacingRatio2) {
  // With graded particles the reflection must stay below 10 %. Each element beside the particles enters as
  // 2 x 2 sub-points (sph_fem_join.cpp), so the particles see their own lattice continued: the
  // equal-spacing limits hold (reflection 5 %, transmission 5 %, energy 1 %).
  check_crossing("Joined SPH zone, particles at half the element size (ratio 2), plane strain",
                 test::join_crossing<2>(GeometryMode::plane_strain, 5e-3, 2.5e-3, with_switch()), {});
}

TEST(SphFemJoin, GradedParticlesSpacingRatio1p5) {
  // A ratio between the integers: 2 x 2 sub-points at 2/3 of the particle spacing. Open: the
  // lattices do not continue each other and the crossing loses ~3 % (docs/theory/coupling.md);
  // the record keeps the measured value against a 5 % bound so that a regression shows.
  Limits limits;
  limits.energy = 0.05;
  limits.energy_reference = "0 (the 1 % bound is for equal spacing; open at ratio 1.5, bound 5 %)";
  check_crossing("Joined SPH zone, particles at 2/3 of the element size (ratio 1.5), plane strain",
                 test::join_crossing<2>(GeometryMode::plane_strain, 5e-3, 5e-3 / 1.5, with_switch()), limits);
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
  const ParticleFillSpec fill = test::zone_box(model, 0.1, {2, 2, 0}, {3, 3, 0});
  try {
    make_joined_zone(model, fill);
    FAIL() << "a join between non-adjacent parts was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("region"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not adjacent"), std::string::npos) << e.what();
  }
}
