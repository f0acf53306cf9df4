// Particle generation: volumes, grading, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <numeric>

#include "common/verification.hpp"
#include "mesh/particle_fill.hpp"
#include "sph/sph_options.hpp"

using namespace camouflet;

namespace {
double total_volume(const ParticleSet& s) {
  return std::accumulate(s.volume.begin(), s.volume.end(), 0.0);
}
}  // namespace

TEST(ParticleFill, UniformBoxVolumeIsExact3D) {
  ParticleSet set;
  ParticleFillSpec spec;
  spec.region.min = {0, 0, 0};
  spec.region.max = {0.3, 0.2, 0.1};
  spec.spacing = 0.021;  // not a divisor: the spacing is adjusted per axis to L / round(L / s)
  fill_particles(set, spec, GeometryMode::three_d);
  EXPECT_EQ(set.count(), 14u * 10u * 5u);
  test::verify({"Particle fill, 3-D box: sum of particle volumes", "box volume 0.006 m^3", 0.006,
                total_volume(set), 1e-12, true, "m^3"});
}

TEST(ParticleFill, AxisymmetricCylinderRingVolumes) {
  // An upright cylinder R = 0.5, L = 1 in r-z: rings 2 pi r A add up to pi R^2 L exactly.
  ParticleSet set;
  ParticleFillSpec spec;
  spec.region.shape = ParticleRegion::Shape::cylinder;
  spec.region.centre = {0, 0, 0};
  spec.region.radius = 0.5;
  spec.region.length = 1.0;
  spec.spacing = 0.05;
  fill_particles(set, spec, GeometryMode::axisymmetric);
  test::verify({"Particle fill, axisymmetric cylinder: sum of ring volumes", "pi R^2 L",
                std::numbers::pi * 0.25, total_volume(set), 1e-12, true, "m^3"});
  for (std::size_t i = 0; i < set.count(); ++i) EXPECT_GT(set.coordinates[2 * i], 0.0);
}

TEST(ParticleFill, GradedDiscSpacingAndVolume) {
  ParticleSet set;
  ParticleFillSpec spec;
  spec.region.shape = ParticleRegion::Shape::sphere;
  spec.region.centre = {0, 0, 0};
  spec.region.radius = 1.0;
  spec.spacing = 0.01;
  spec.graded = true;
  spec.grading_point = {0, 0, 0};
  spec.grading_ratio = 1.05;
  spec.max_spacing = 0.05;
  fill_particles(set, spec, GeometryMode::plane_strain);
  const auto [lo, hi] = std::minmax_element(set.spacing.begin(), set.spacing.end());
  EXPECT_NEAR(*lo, 0.01, 1e-12);
  EXPECT_LE(*hi, 0.05 * 1.5);  // strip cells are near-square: within 1.5x of the shell width
  // Spacing grows with distance from the grading point.
  double near = 0, far = 0;
  int n_near = 0, n_far = 0;
  for (std::size_t i = 0; i < set.count(); ++i) {
    const double r = std::hypot(set.coordinates[2 * i], set.coordinates[2 * i + 1]);
    if (r < 0.05) near += set.spacing[i], ++n_near;
    if (r > 0.9) far += set.spacing[i], ++n_far;
  }
  EXPECT_LT(near / n_near, 0.0125);
  EXPECT_GT(far / n_far, 0.045);
  test::verify({"Particle fill, graded disc (0.01 -> 0.05 m): sum of particle areas", "pi R^2",
                std::numbers::pi, total_volume(set), 0.02, true, "m^2"});
}

TEST(ParticleFill, PolygonAndSphere) {
  ParticleSet tri;
  ParticleFillSpec spec;
  spec.region.shape = ParticleRegion::Shape::polygon;
  spec.region.polygon = {{0, 0}, {1, 0}, {0, 1}};
  spec.spacing = 0.01;
  fill_particles(tri, spec, GeometryMode::plane_strain);
  test::verify({"Particle fill, triangle polygon: sum of particle areas", "area 0.5 m^2", 0.5,
                total_volume(tri), 0.02, true, "m^2"});
  ParticleSet ball;
  spec.region.shape = ParticleRegion::Shape::sphere;
  spec.region.centre = {1, 1, 1};
  spec.region.radius = 0.2;
  spec.spacing = 0.02;
  fill_particles(ball, spec, GeometryMode::three_d);
  test::verify({"Particle fill, 3-D sphere: sum of particle volumes", "4/3 pi R^3",
                4.0 / 3.0 * std::numbers::pi * 0.008, total_volume(ball), 0.05, true, "m^3"});
}

TEST(ParticleFill, BadInputNamesTheKey) {
  ParticleSet set;
  ParticleFillSpec spec;
  spec.where = SourceLocation{"case.toml", 12, 1, "parts.charge"};
  spec.region.max = {1, 1, 1};
  spec.spacing = 0.0;
  try {
    fill_particles(set, spec, GeometryMode::plane_strain);
    FAIL() << "spacing 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "parts.charge.spacing");
  }
  spec.spacing = 0.1;
  spec.region.shape = ParticleRegion::Shape::polygon;
  spec.region.polygon = {{0, 0}, {1e-3, 0}, {0, 1e-3}};  // far smaller than one particle
  EXPECT_THROW(fill_particles(set, spec, GeometryMode::plane_strain), InputError);
  spec.region.shape = ParticleRegion::Shape::box;
  spec.graded = true;
  spec.grading_ratio = 1.1;
  spec.max_spacing = 0.05;  // below the smallest spacing
  try {
    fill_particles(set, spec, GeometryMode::plane_strain);
    FAIL() << "max_spacing < spacing accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "parts.charge.max_spacing");
  }
  // Smoothing-length bounds inverted.
  Parameters block(SourceLocation{"case.toml", 3, 1, "sph"});
  block.set_number("h_min_factor", 2.0, SourceLocation{"case.toml", 4, 1, "sph.h_min_factor"});
  block.set_number("h_max_factor", 1.0, SourceLocation{"case.toml", 5, 1, "sph.h_max_factor"});
  try {
    sph::read_sph_options(block);
    FAIL() << "inverted smoothing-length bounds accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "sph.h_min_factor");
  }
}
