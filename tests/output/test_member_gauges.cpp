// Member gauges: the mass-weighted mean over a set of elements (output/gauges.hpp).
// With consistent nodal masses the mean of a field linear in position is the
// field at the set's centre of mass, exactly, on any mesh: here distorted
// quads and hexes filling the unit square or cube (centre of mass 1/2), and an
// r-z ring section r in [1, 2], z in [0, 1] (centre of mass r = 14/9 with the
// ring weight 2 pi r, z = 1/2). Element quantities are mass-weighted means.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "output/gauges.hpp"
#include "snapshot_fixture.hpp"

namespace camouflet {
namespace {

using test::SnapshotFixture;

GaugePoint member(std::array<double, 3> lo, std::array<double, 3> hi, int material = -1) {
  GaugePoint g;
  g.name = "wall";
  g.member = true;
  g.member_material = material;
  g.region_min = lo;
  g.region_max = hi;
  return g;
}

void check_centre_of_mass(int dim, bool ring) {
  auto f = SnapshotFixture::distorted(dim, 4);
  f.density.assign(f.density.size(), 2400.0);
  f.damage.assign(f.damage.size(), 0.3);
  if (ring)
    for (std::size_t a = 0; a < f.position.size(); a += 2) f.position[a] += 1.0;
  f.set_linear_fields(0.0);
  FieldSnapshot s = f.view(0.0, 0);
  if (ring) s.mode = GeometryMode::axisymmetric;
  const LocatedGauge g = locate_gauge(member({-5, -5, -5}, {5, 5, 5}), s);
  std::vector<double> out;
  sample_gauge(g, s, out);
  ASSERT_EQ(out.size(), gauge_quantities(dim).size());
  std::array<double, 3> centre{0.5, 0.5, dim == 3 ? 0.5 : 0.0};
  if (ring) centre[0] = 14.0 / 9.0;
  const auto v = SnapshotFixture::velocity_at(centre);
  double worst_x = 0.0, worst_v = 0.0;
  for (int i = 0; i < dim; ++i) {
    worst_x = std::max(worst_x, std::abs(out[static_cast<std::size_t>(i)] - centre[static_cast<std::size_t>(i)]));
    worst_v = std::max(worst_v, std::abs(out[static_cast<std::size_t>(2 * dim + i)] - v[static_cast<std::size_t>(i)]));
  }
  const std::string what = ring ? "r-z ring section of distorted quads" : dim == 3 ? "distorted hexes" : "distorted quads";
  test::verify({"Member gauge over " + what + ": centre of mass (position column)",
                ring ? "r = 14/9, z = 1/2 (ring weight 2 pi r)" : "1/2 (uniform density)", 0.0, worst_x, 1e-12, false,
                "m"});
  test::verify({"Member gauge over " + what + ": mean of a linear velocity field",
                "the field at the centre of mass (consistent nodal masses)", 0.0, worst_v, 1e-11, false, "m/s"});
  EXPECT_NEAR(out[static_cast<std::size_t>(4 * dim + 8)], 0.3, 1e-14) << "mass-weighted mean damage";
}

TEST(MemberGauges, LinearFieldMeanIsItsValueAtTheCentreOfMass) {
  check_centre_of_mass(2, false);
  check_centre_of_mass(3, false);
  check_centre_of_mass(2, true);
}

TEST(MemberGauges, SelectsByMaterialAndBoxAndRefusesAnEmptyOne) {
  auto f = SnapshotFixture::distorted(2, 4);  // materials alternate 0, 1 by element
  f.set_linear_fields(0.0);
  const FieldSnapshot s = f.view(0.0, 0);
  const LocatedGauge all = locate_gauge(member({-1, -1, 0}, {2, 2, 0}), s);
  const LocatedGauge odd = locate_gauge(member({-1, -1, 0}, {2, 2, 0}, 1), s);
  EXPECT_EQ(all.member_elements.size(), 16u);
  EXPECT_EQ(odd.member_elements.size(), 8u);
  for (const auto& [e, w] : odd.member_elements) EXPECT_EQ(f.material[static_cast<std::size_t>(e)], 1);
  double sum = 0.0;
  for (const auto& [n, w] : odd.member_nodes) sum += w;
  EXPECT_NEAR(sum, 1.0, 1e-14);
  EXPECT_THROW(locate_gauge(member({3, 3, 0}, {4, 4, 0}), s), InputError);
}

}  // namespace
}  // namespace camouflet
