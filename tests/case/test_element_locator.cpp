// The binned element locator (model/element_locator.hpp) answers as the
// search over every element (locate_point): the same element, the same
// natural coordinates, nothing outside the mesh, on distorted quads and hexes
// of unequal sizes, for points inside, on shared faces and nodes, and beyond.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "model/element_locator.hpp"
#include "model/isoparametric.hpp"

namespace camouflet {
namespace {

struct Grid {
  std::vector<double> x;
  std::vector<std::int64_t> conn;
};

// A structured grid of n^dim cells, graded (cells grow by 1.3 along each axis) and with its
// inner nodes moved by up to 0.2 of a cell, so elements are neither boxes nor equal.
Grid distorted_grid(int dim, int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<double> line(static_cast<std::size_t>(n) + 1, 0.0);
  for (int i = 1; i <= n; ++i) line[i] = line[i - 1] + std::pow(1.3, i);
  const int m = n + 1, nk = dim == 3 ? m : 1;
  Grid g;
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const int idx[3] = {i, j, k};
        for (int d = 0; d < dim; ++d) {
          const int a = idx[d];
          const bool inner = a > 0 && a < n;
          const double h = inner ? std::min(line[a + 1] - line[a], line[a] - line[a - 1]) : 0.0;
          g.x.push_back(line[a] + (inner ? jitter(rng) * h : 0.0));
        }
      }
  const auto node = [&](int i, int j, int k) { return static_cast<std::int64_t>(i + m * (j + m * k)); };
  for (int k = 0; k < (dim == 3 ? n : 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int layer = 0; layer < (dim == 3 ? 2 : 1); ++layer) {
          const int kk = k + layer;
          for (auto [a, b] : {std::pair{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}})
            g.conn.push_back(node(a, b, dim == 3 ? kk : 0));
        }
  return g;
}

void compare(int dim) {
  std::mt19937 rng(dim == 2 ? 12345u : 54321u);
  const int n = dim == 2 ? 24 : 8;
  const Grid g = distorted_grid(dim, n, rng);
  const ElementLocator locator(dim, g.x, g.conn);
  double extent = 0.0;
  for (int i = 1; i <= n; ++i) extent += std::pow(1.3, i);
  std::uniform_real_distribution<double> u(-0.05 * extent, 1.05 * extent);
  std::size_t inside = 0, outside = 0;
  std::vector<double> x(static_cast<std::size_t>(dim));
  for (int trial = 0; trial < 4000; ++trial) {
    if (trial % 4 == 0) {  // a mesh node: on shared faces, edges and corners
      const std::size_t node = rng() % (g.x.size() / static_cast<std::size_t>(dim));
      for (int d = 0; d < dim; ++d) x[d] = g.x[node * dim + d];
    } else {
      for (double& v : x) v = u(rng);
    }
    const auto expected = locate_point(dim, g.x, g.conn, x);
    const auto got = locator.locate(x);
    ASSERT_EQ(expected.has_value(), got.has_value()) << "trial " << trial;
    if (!expected) {
      ++outside;
      continue;
    }
    ++inside;
    EXPECT_EQ(got->element, expected->element) << "trial " << trial;
    for (int d = 0; d < dim; ++d) EXPECT_EQ(got->xi[d], expected->xi[d]);
  }
  // Both kinds of answer were exercised.
  EXPECT_GT(inside, 1000u);
  EXPECT_GT(outside, 100u);
}

TEST(ElementLocator, SameAnswerAsTheFullSearchForQuads) {
  compare(2);
}

TEST(ElementLocator, SameAnswerAsTheFullSearchForHexes) {
  compare(3);
}

TEST(ElementLocator, EmptyMeshHoldsNoPoint) {
  const std::vector<double> x;
  const std::vector<std::int64_t> conn;
  const ElementLocator locator(2, x, conn);
  const double p[2] = {0.0, 0.0};
  EXPECT_FALSE(locator.locate(p).has_value());
}

}  // namespace
}  // namespace camouflet
