// Lagrangian gauges on distorted elements: bilinear (trilinear) interpolation
// reproduces any field linear in position exactly, so position and velocity
// sampled at a gauge must equal the linear field at the gauge's point to
// round-off; stress comes from the element that contains the gauge.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "model/isoparametric.hpp"
#include "output/gauges.hpp"
#include "snapshot_fixture.hpp"

namespace camouflet {
namespace {

using test::SnapshotFixture;

void check_linear_field(int dim) {
  auto f = SnapshotFixture::distorted(dim, 3);
  f.set_linear_fields(0.0);
  const FieldSnapshot s = f.view(0.0, 0);
  const auto quantities = gauge_quantities(dim);
  double worst_position = 0.0, worst_velocity = 0.0;
  // Points spread over the cube, including ones on element faces.
  for (int k = 0; k < 7; ++k) {
    GaugePoint g;
    g.name = "g";
    g.position = {0.05 + 0.13 * k, 0.93 - 0.12 * k, dim == 3 ? 0.2 + 0.1 * k : 0.0};
    if (k == 3) g.position = {0.5, 1.0 / 3.0, dim == 3 ? 0.5 : 0.0};
    const LocatedGauge located = locate_gauge(g, s);
    ASSERT_GE(located.element, 0);
    std::vector<double> out;
    sample_gauge(located, s, out);
    ASSERT_EQ(out.size(), quantities.size());
    const auto v = SnapshotFixture::velocity_at(g.position);
    for (int i = 0; i < dim; ++i) {
      worst_position = std::max(worst_position, std::abs(out[static_cast<std::size_t>(i)] - g.position[i]));
      worst_velocity = std::max(worst_velocity, std::abs(out[static_cast<std::size_t>(2 * dim + i)] -
                                                         v[static_cast<std::size_t>(i)]));
    }
    // Stress, pressure and plastic strain are the containing element's.
    const auto e = static_cast<std::size_t>(located.element);
    EXPECT_EQ(out[static_cast<std::size_t>(4 * dim)], f.stress[e].xx);
    EXPECT_EQ(out[static_cast<std::size_t>(4 * dim + 6)], f.pressure[e]);
    EXPECT_EQ(out[static_cast<std::size_t>(4 * dim + 7)], f.plastic[e]);
  }
  const std::string name = dim == 3 ? "hex8" : "quad4";
  test::verify({"Gauge interpolation on distorted " + name + ": position",
                "exact (isoparametric inverse map)", 0.0, worst_position, 1e-12, false, "m"});
  test::verify({"Gauge interpolation on distorted " + name + ": linear velocity field",
                "exact (linear field in bilinear/trilinear space)", 0.0, worst_velocity, 1e-11, false,
                "m/s"});
}

TEST(Gauges, LinearFieldExactOnDistortedQuads) {
  check_linear_field(2);
}
TEST(Gauges, LinearFieldExactOnDistortedHexes) {
  check_linear_field(3);
}

TEST(Gauges, OutsideMeshNamesGaugeKey) {
  auto f = SnapshotFixture::distorted(2, 2);
  const FieldSnapshot s = f.view(0.0, 0);
  GaugePoint g;
  g.name = "far";
  g.position = {1.5, 0.5, 0.0};
  g.where = SourceLocation{"case.toml", 42, 0, "gauges[0].points[1].position"};
  try {
    locate_gauge(g, s);
    FAIL() << "gauge outside the mesh accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 42);
    EXPECT_NE(std::string(e.what()).find("gauges[0].points[1].position"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("outside the mesh"), std::string::npos) << e.what();
  }
}

TEST(Gauges, ParticleGaugeFollowsNearestParticle) {
  FieldSnapshot s;
  s.dimension = 2;
  const std::vector<double> pos{0.0, 0.0, 1.0, 0.0, 2.0, 0.0};
  const std::vector<double> h{0.6, 0.6, 0.6};
  const std::vector<double> vel{1.0, 0.0, 2.0, 0.0, 3.0, 0.0};
  s.particle_position = pos;
  s.particle_smoothing_length = h;
  s.particle_velocity = vel;
  GaugePoint g;
  g.name = "p";
  g.position = {1.2, 0.1, 0.0};
  const auto located = locate_gauge(g, s);
  EXPECT_EQ(located.particle, 1);
  std::vector<double> out;
  sample_gauge(located, s, out);
  EXPECT_EQ(out[4], 2.0);  // velocity_x of particle 1
  g.position = {5.0, 0.0, 0.0};
  EXPECT_THROW(locate_gauge(g, s), InputError);
}

TEST(Isoparametric, CornerJacobianSignsInvertedQuad) {
  // Counter-clockwise unit square: positive; clockwise order: negative.
  const double ccw[] = {0, 0, 1, 0, 1, 1, 0, 1};
  const double cw[] = {0, 0, 0, 1, 1, 1, 1, 0};
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(jacobian_determinant(2, ccw, corner_natural(2, a)), 0.25, 1e-15);
    EXPECT_NEAR(jacobian_determinant(2, cw, corner_natural(2, a)), -0.25, 1e-15);
  }
}

}  // namespace
}  // namespace camouflet
