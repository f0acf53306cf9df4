// Re-sorted particles and restarts: a
// particle impact with re-sorting after every neighbour-list rebuild, stopped
// half way and restarted from its checkpoint, ends with gauge CSVs (one gauge
// following a particle, one interpolating at a fixed point) and a final state
// identical bit for bit to the uninterrupted run; the gauges equal those of
// the same run without re-sorting up to round-off (they see particles by id).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "common/verification.hpp"
#include "restart_helpers.hpp"
#include "solver/run.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

Model sorted_particle_model(std::int64_t max_cycles, int sort_interval) {
  Model model = test::colliding_particle_blocks(max_cycles);
  model.sph.sort_interval = sort_interval;
  GaugeGroup follow, fixed;
  follow.name = "follow";
  follow.points.push_back({"middle", {0.06, 0.02, 0.0}, {}});
  fixed.name = "fixed";
  GaugePoint point{"middle", {0.061, 0.019, 0.0}, {}};
  point.interpolate = true;
  fixed.points.push_back(point);
  model.gauges.push_back(follow);
  model.gauges.push_back(fixed);
  return model;
}

// Largest difference between two gauge CSVs of the same shape (numbers after the header).
double csv_difference(const std::string& a, const std::string& b) {
  std::istringstream ia(a), ib(b);
  std::string la, lb;
  std::getline(ia, la);
  std::getline(ib, lb);
  double worst = 0.0;
  while (std::getline(ia, la) && std::getline(ib, lb)) {
    std::istringstream ca(la), cb(lb);
    std::string va, vb;
    while (std::getline(ca, va, ',') && std::getline(cb, vb, ','))
      worst = std::max(worst, std::abs(std::strtod(va.c_str(), nullptr) - std::strtod(vb.c_str(), nullptr)));
  }
  return worst;
}

TEST(ParticleSortRestart, SortedRunRestartsBitIdenticalAndGaugesMatchUnsorted) {
  const fs::path root = test::fresh_test_output("particle-sort/run");
  const test::SplitRun run =
      test::run_split(root, [](std::int64_t max_cycles) { return sorted_particle_model(max_cycles, 1); });
  ASSERT_GT(run.reference.cycles, 20);
  EXPECT_EQ(run.first.cycles, run.half);
  EXPECT_EQ(run.second.cycles, run.reference.cycles);
  for (const char* csv : {"follow.csv", "fixed.csv"})
    EXPECT_EQ(test::read_text(root / "full" / csv), test::read_text(root / "split" / csv)) << csv;
  test::expect_same_final_state(root / "full", root / "split");

  // The same run without re-sorting: the gauges agree up to round-off.
  run_model(sorted_particle_model(std::numeric_limits<std::int64_t>::max(), 0),
            test::quiet_run_options(root / "unsorted"));
  const std::string follow_sorted = test::read_text(root / "full" / "follow.csv");
  ASSERT_EQ(follow_sorted.size() > 0, true);
  const double d_follow = csv_difference(follow_sorted, test::read_text(root / "unsorted" / "follow.csv"));
  const double d_fixed = csv_difference(test::read_text(root / "full" / "fixed.csv"),
                                        test::read_text(root / "unsorted" / "fixed.csv"));
  std::printf("gauge differences sorted vs unsorted: follow %.3g, fixed %.3g\n", d_follow, d_fixed);
  // Columns reach ~1e8 Pa (stress) and ~40 m/s: 1e-3 absolute is round-off of the stress columns.
  test::verify({"Particle re-sort: follow-the-particle gauge CSV vs the unsorted run",
                "identical up to round-off", 0.0, d_follow, 1e-3, false, "largest column difference"});
  test::verify({"Particle re-sort: kernel-interpolating gauge CSV vs the unsorted run",
                "identical up to round-off", 0.0, d_fixed, 1e-3, false, "largest column difference"});
}

}  // namespace
}  // namespace camouflet
