// Cell-list neighbour search against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "common/verification.hpp"
#include "mesh/particle_fill.hpp"
#include "sph/neighbour_search.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

// Row i of the lists as a sorted set (the lists keep the cells' order, neighbour_search.hpp).
template <int D>
std::vector<std::uint32_t> sorted_row(const NeighbourSearch<D>& search, std::size_t i) {
  std::vector<std::uint32_t> row(search.neighbours(i).begin(), search.neighbours(i).end());
  std::sort(row.begin(), row.end());
  return row;
}

template <int D>
std::size_t count_mismatches(const std::vector<Vec<D>>& x, const std::vector<double>& h, std::size_t n_owned,
                             double skin) {
  NeighbourSearch<D> search;
  search.build(x, h, n_owned, skin);
  const auto reference = brute_force_neighbours<D>(x, h, n_owned, skin);
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < n_owned; ++i) {
    if (sorted_row(search, i) != reference[i]) ++mismatches;
  }
  EXPECT_GT(search.pair_count(), n_owned * 4);  // the sets are not trivially empty
  return mismatches;
}

template <int D>
void random_set(std::vector<Vec<D>>& x, std::vector<double>& h, std::size_t n, double spread, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, 1.0), size(0.5, 1.5);
  const double h0 = 1.2 * std::pow(1.0 / n, 1.0 / D);
  x.resize(n);
  h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) x[i][d] = pos(rng) * (d == 0 ? spread : 1.0);
    h[i] = h0 * size(rng);
  }
}

}  // namespace

TEST(SphNeighbourSearch, RandomSet2DMatchesBruteForce) {
  std::vector<Vec<2>> x;
  std::vector<double> h;
  random_set<2>(x, h, 3000, 1.0, 1);
  const double mismatches = static_cast<double>(count_mismatches<2>(x, h, x.size(), 0.2 * h[0]));
  test::verify({"Neighbour search, 2-D random set (3000 points): lists differing from brute force",
                "brute-force O(N^2) search", 0.0, mismatches, 0.0, false, "particles"});
}

TEST(SphNeighbourSearch, GradedSet2DWithGhostsMatchesBruteForce) {
  ParticleSet set;
  ParticleFillSpec spec;
  spec.region.shape = ParticleRegion::Shape::box;
  spec.region.min = {0, 0, 0};
  spec.region.max = {1, 1, 0};
  spec.spacing = 0.005;
  spec.graded = true;
  spec.grading_point = {0.2, 0.3, 0};
  spec.grading_ratio = 1.1;
  spec.max_spacing = 0.04;
  fill_particles(set, spec, GeometryMode::plane_strain);
  std::vector<Vec<2>> x(set.count());
  std::vector<double> h(set.count());
  for (std::size_t i = 0; i < set.count(); ++i) {
    x[i] = Vec<2>{{set.coordinates[2 * i], set.coordinates[2 * i + 1]}};
    h[i] = 1.2 * set.spacing[i];
  }
  // The last 10 % are treated as ghosts (candidates without lists of their own).
  const std::size_t owned = x.size() - x.size() / 10;
  const double mismatches = static_cast<double>(count_mismatches<2>(x, h, owned, 0.001));
  test::verify(
      {"Neighbour search, 2-D graded set (ratio 1.1, 8x spacing range): lists differing from brute force",
       "brute-force O(N^2) search", 0.0, mismatches, 0.0, false, "particles"});
}

TEST(SphNeighbourSearch, RandomSet3DMatchesBruteForce) {
  std::vector<Vec<3>> x;
  std::vector<double> h;
  random_set<3>(x, h, 4000, 2.0, 7);
  const double mismatches = static_cast<double>(count_mismatches<3>(x, h, x.size(), 0.1 * h[0]));
  test::verify({"Neighbour search, 3-D random set (4000 points): lists differing from brute force",
                "brute-force O(N^2) search", 0.0, mismatches, 0.0, false, "particles"});
}

// A few far-flung points stretch the bounding box until the grid must grow its cells past half
// the largest reach (the cap of a few cells per point): the visit then spans more cells per axis.
TEST(SphNeighbourSearch, StretchedGrid3DMatchesBruteForce) {
  std::vector<Vec<3>> x;
  std::vector<double> h;
  random_set<3>(x, h, 3000, 1.0, 11);
  for (int k = 0; k < 6; ++k) {  // a small cluster 50 units away, each within reach of the others
    x.push_back(Vec<3>{{50.0 + 0.02 * k, 0.5, 0.5 + 0.01 * k}});
    h.push_back(h[0]);
  }
  const double mismatches = static_cast<double>(count_mismatches<3>(x, h, x.size(), 0.1 * h[0]));
  test::verify(
      {"Neighbour search, 3-D set stretched by a far cluster (grid cells grown): lists differing "
       "from brute force",
       "brute-force O(N^2) search", 0.0, mismatches, 0.0, false, "particles"});
}

TEST(SphNeighbourSearch, SkinKeepsListsValidUntilRebuild) {
  std::vector<Vec<3>> x;
  std::vector<double> h;
  random_set<3>(x, h, 2000, 1.0, 3);
  const double skin = 0.2 * h[0];
  NeighbourSearch<3> search;
  search.build(x, h, x.size(), skin);
  // Move every point by less than skin/4 (so 2 max displacement < skin): no rebuild needed,
  // and every pair now inside the support 2 h_ij must still be listed.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (auto& p : x)
    for (int k = 0; k < 3; ++k) p[k] += d(rng) * skin / (4.0 * std::sqrt(3.0));
  EXPECT_FALSE(search.needs_rebuild(x, h));
  const auto inside = brute_force_neighbours<3>(x, h, x.size(), 0.0);
  std::size_t missing = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::vector<std::uint32_t> got = sorted_row(search, i);
    for (auto j : inside[i])
      if (!std::binary_search(got.begin(), got.end(), j)) ++missing;
  }
  EXPECT_EQ(missing, 0u);
  // A displacement beyond skin/2 asks for a rebuild.
  x[5][0] += 0.6 * skin;
  EXPECT_TRUE(search.needs_rebuild(x, h));
}
