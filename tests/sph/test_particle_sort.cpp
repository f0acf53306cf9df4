// Re-sorting particles in memory by neighbour-search cell (SphOptions::
// sort_interval): an impact of two elastic blocks stored in random order, run
// with and without re-sorting, must give the same state for every particle
// id up to round-off (only the order of the neighbour sums changes), with the
// snapshot in id order either way.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

Model shuffled_impact() {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  const auto solid = test::elastic_solid("steel", 7800.0, 1.6e11, 8.0e10);
  test::add_sph_part(model, "striker", solid, test::box_fill({0.0, 0.0, 0.0}, {0.04, 0.04, 0.0}, 0.002),
                     {200.0, 0.0, 0.0});
  test::add_sph_part(model, "target", solid, test::box_fill({0.0401, -0.02, 0.0}, {0.1, 0.06, 0.0}, 0.002));
  auto& p = model.particles;
  std::vector<std::size_t> order(p.count());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(11));
  ParticleSet s;
  for (const std::size_t i : order) {
    s.coordinates.insert(s.coordinates.end(), {p.coordinates[2 * i], p.coordinates[2 * i + 1]});
    s.volume.push_back(p.volume[i]);
    s.spacing.push_back(p.spacing[i]);
    s.particle_part.push_back(p.particle_part[i]);
  }
  model.particles = s;
  return model;
}

}  // namespace

TEST(SphParticleSort, SortedRunMatchesUnsortedByIdUpToRoundOff) {
  const Model model = shuffled_impact();
  SphOptions plain, sorted;
  plain.sort_interval = 0;
  sorted.sort_interval = 1;
  SphSystem<2> a(model, plain), b(model, sorted);
  const double t_end = 2e-5;  // the striker moves 4 mm = 2 spacings: several list rebuilds
  test::run_until(a, t_end, 0.3);
  test::run_until(b, t_end, 0.3);
  ASSERT_GT(b.sorts(), 0) << "no re-sort happened";
  const auto& pb = b.particles();
  std::size_t moved = 0;
  for (std::size_t i = 0; i < b.size(); ++i) moved += pb.id[i] != i;
  EXPECT_GT(moved, b.size() / 2) << "the memory order did not change";
  FieldSnapshot sa, sb;
  a.fill_snapshot(sa);
  b.fill_snapshot(sb);
  ASSERT_EQ(sa.particle_count(), sb.particle_count());
  double worst_x = 0.0, worst_v = 0.0, worst_s = 0.0, v_scale = 0.0, s_scale = 0.0;
  for (std::size_t k = 0; k < sa.particle_position.size(); ++k) {
    worst_x = std::max(worst_x, std::abs(sa.particle_position[k] - sb.particle_position[k]));
    worst_v = std::max(worst_v, std::abs(sa.particle_velocity[k] - sb.particle_velocity[k]));
    v_scale = std::max(v_scale, std::abs(sa.particle_velocity[k]));
  }
  for (std::size_t i = 0; i < sa.particle_count(); ++i) {
    worst_s = std::max(worst_s, std::abs(sa.particle_stress[i].xx - sb.particle_stress[i].xx));
    s_scale = std::max(s_scale, std::abs(sa.particle_stress[i].xx));
    EXPECT_EQ(sa.particle_material[i], sb.particle_material[i]);
  }
  std::printf("sorts %lld, moved %zu of %zu; worst |dx| %.3g m, |dv|/v %.3g, |dsigma|/sigma %.3g\n",
              static_cast<long long>(b.sorts()), moved, b.size(), worst_x, worst_v / v_scale,
              worst_s / s_scale);
  test::verify({"Particle re-sort by cell (impact, 1 600 particles in random order): positions by id",
                "the unsorted run (round-off only)", 0.0, worst_x, 1e-12, false, "m"});
  test::verify({"Particle re-sort by cell: velocities by id, relative to the largest",
                "the unsorted run (round-off only)", 0.0, worst_v / v_scale, 1e-9, false, "-"});
  test::verify({"Particle re-sort by cell: stress sigma_xx by id, relative to the largest",
                "the unsorted run (round-off only)", 0.0, worst_s / s_scale, 1e-8, false, "-"});
}
