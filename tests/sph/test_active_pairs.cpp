// The thin-skin pair list (active_pairs.hpp): what its upper part of a row holds and in
// which order. The pair sums take each particle pair once from it, and the booking of the axis
// images' work (SphSystem::book_axis_image_work) finds a row's ghosts by looking at its last entry
// only: ghosts and coupling points must come after every particle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "sph/active_pairs.hpp"
#include "sph/kernel.hpp"
#include "sph/neighbour_search.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

// n particles in the unit square or cube, then `ghosts` points beyond x = 0 (mirror images of the
// particles next to that face), h varying by a factor of 3.
template <int D>
void particles_and_ghosts(std::size_t n, std::vector<Vec<D>>& x, std::vector<double>& h,
                          std::size_t& ghosts) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 1.0), size(0.5, 1.5);
  const double h0 = 1.2 * std::pow(1.0 / static_cast<double>(n), 1.0 / D);
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> p;
    for (int d = 0; d < D; ++d) p[d] = pos(rng);
    x.push_back(p);
    h.push_back(h0 * size(rng));
  }
  ghosts = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (x[i][0] < support_factor * h[i]) {
      Vec<D> image = x[i];
      image[0] = -image[0];
      x.push_back(image);
      h.push_back(h[i]);
      ++ghosts;
    }
}

template <int D>
void check_upper_rows(std::size_t n) {
  std::vector<Vec<D>> x;
  std::vector<double> h;
  std::size_t ghosts = 0;
  particles_and_ghosts<D>(n, x, h, ghosts);
  ASSERT_GT(ghosts, n / 50) << "the set has ghosts to order";
  const double cell_skin = 0.3 * h[0], thin_skin = 0.1 * h[0];
  NeighbourSearch<D> search;
  search.build(x, h, n, cell_skin);
  ActivePairs<D> active;
  active.set_skin(thin_skin);
  active.refresh(search, x, h, n);

  std::size_t rows_with_both = 0, entries = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto upper = active.upper_neighbours(i);
    entries += upper.size();
    ASSERT_EQ(active.upper_index()[i + 1] - active.upper_index()[i], upper.size()) << "row " << i;
    bool past_particles = false, had_particle = false;
    std::set<std::uint32_t> held;
    for (const std::uint32_t j : upper) {
      ASSERT_GT(j, i) << "row " << i << " holds a pair from below the diagonal";
      if (j >= n) {
        past_particles = true;
      } else {
        ASSERT_FALSE(past_particles) << "row " << i << ": particle " << j << " after a ghost";
        had_particle = true;
      }
      ASSERT_TRUE(held.insert(j).second) << "row " << i << " holds " << j << " twice";
    }
    if (had_particle && past_particles) ++rows_with_both;
    // Every pair inside the support is held; none beyond the support and the thin skin.
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      const double distance = std::sqrt(dot(x[i] - x[j], x[i] - x[j]));
      const double support = support_factor * pair_smoothing_length(h[i], h[j]);
      const bool in_list = held.count(static_cast<std::uint32_t>(j)) > 0;
      if (distance < support) {
        EXPECT_TRUE(in_list) << "row " << i << " misses " << j << " inside the support";
      }
      if (distance >= support + thin_skin) {
        EXPECT_FALSE(in_list) << "row " << i << " holds " << j << " beyond the thin skin";
      }
    }
  }
  EXPECT_EQ(active.upper_index()[n], entries);
  EXPECT_GT(rows_with_both, ghosts / 4) << "rows with particles and ghosts both, where the order matters";
}

}  // namespace

TEST(SphActivePairs, UpperRowsHoldEachPairOnceWithGhostsLast2D) {
  check_upper_rows<2>(2000);
}

TEST(SphActivePairs, UpperRowsHoldEachPairOnceWithGhostsLast3D) {
  check_upper_rows<3>(3000);
}
