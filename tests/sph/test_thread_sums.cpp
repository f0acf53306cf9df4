// Row blocks of the pair-symmetric sums (sph/thread_sums.hpp): every scatter
// lands inside its block's window, one block reproduces the serial loop bit
// for bit, more blocks agree with it to round-off and do not depend on the
// number of threads that run them, and the blocks share the cost evenly.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "common/verification.hpp"
#include "sph/thread_sums.hpp"

using namespace camouflet;
using camouflet::sph::BlockSums;
using camouflet::sph::RowBlocks;

namespace {

// Pair lists like the SPH j > i lists: row i's partners lie within `reach`
// rows after it (cell order), a few rows have many (dense regions), and some
// entries (j >= n) stand for ghosts, which get no sums.
struct Lists {
  std::size_t n = 0;
  std::vector<std::size_t> prefix;  // n + 1
  std::vector<std::uint32_t> j;
  std::vector<double> term;  // pair term: +term to i, -0.7 term to j
};

Lists make_lists(std::size_t n, std::size_t reach, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Lists l;
  l.n = n;
  l.prefix.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t partners = (i % 97 < 10) ? 40 : 12;  // uneven cost
    std::vector<std::uint32_t> row;
    for (std::size_t k = 0; k < partners; ++k) {
      const std::size_t j = i + 1 + rng() % reach;
      if (j < n) row.push_back(static_cast<std::uint32_t>(j));
    }
    if (i % 13 == 0) row.push_back(static_cast<std::uint32_t>(n + i % 50));  // a ghost
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    for (const std::uint32_t j : row) {
      l.j.push_back(j);
      l.term.push_back(value(rng));
    }
    l.prefix[i + 1] = l.j.size();
  }
  return l;
}

// The serial scatter loop the blocks replace.
std::vector<double> serial_sums(const Lists& l) {
  std::vector<double> s(l.n, 0.0);
  for (std::size_t i = 0; i < l.n; ++i) {
    double mine = 0.0;
    for (std::size_t e = l.prefix[i]; e < l.prefix[i + 1]; ++e) {
      mine += l.term[e];
      if (l.j[e] < l.n) s[l.j[e]] -= 0.7 * l.term[e];
    }
    s[i] += mine;
  }
  return s;
}

struct Outcome {
  std::vector<double> sums;
  std::size_t outside_window = 0;
};

Outcome block_sums(const Lists& l, std::size_t blocks, int threads) {
  RowBlocks rb;
  auto reach = [&](std::size_t i) {
    std::size_t end = i + 1;
    for (std::size_t e = l.prefix[i]; e < l.prefix[i + 1]; ++e)
      if (l.j[e] < l.n) end = std::max<std::size_t>(end, l.j[e] + 1);
    return end;
  };
  rb.build(blocks, l.n, l.prefix.data(), 4, reach);
  BlockSums<double> sums;
  sums.prepare(rb, l.n);
  Outcome out;
  out.sums.assign(l.n, 0.0);
  std::size_t outside = 0;
  const std::size_t nb = rb.count();
#pragma omp parallel num_threads(threads) reduction(+ : outside)
  {
#pragma omp for schedule(static, 1)
    for (std::size_t k = 0; k < nb; ++k) {
      double* const own = sums.zeroed(rb, k);
      for (std::size_t i = rb.begin(k); i < rb.end(k); ++i) {
        double mine = 0.0;
        for (std::size_t e = l.prefix[i]; e < l.prefix[i + 1]; ++e) {
          mine += l.term[e];
          if (l.j[e] >= l.n) continue;
          if (l.j[e] >= rb.window_end(k)) {
            ++outside;
            continue;
          }
          own[l.j[e]] -= 0.7 * l.term[e];
        }
        own[i] += mine;
      }
    }
    auto add = [](double& total, double part) { total += part; };
#pragma omp for schedule(static, 1)
    for (std::size_t k = 0; k < nb; ++k)
      for (std::size_t i = rb.begin(k); i < rb.end(k); ++i) out.sums[i] = sums.total(rb, k, i, add);
  }
  out.outside_window = outside;
  return out;
}

double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double peak = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    peak = std::max(peak, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return diff / peak;
}

}  // namespace

TEST(SphThreadSums, OneBlockIsTheSerialLoopBitForBit) {
  const Lists l = make_lists(5000, 300, 1);
  const Outcome one = block_sums(l, 1, 1);
  EXPECT_EQ(one.outside_window, 0u);
  EXPECT_EQ(one.sums, serial_sums(l));
}

TEST(SphThreadSums, BlocksAgreeWithTheSerialLoopToRoundOff) {
  const Lists l = make_lists(5000, 300, 2);
  const std::vector<double> serial = serial_sums(l);
  double worst = 0.0;
  for (const std::size_t blocks : {2u, 3u, 7u, 16u}) {
    const Outcome a = block_sums(l, blocks, 1);
    EXPECT_EQ(a.outside_window, 0u) << blocks << " blocks";
    worst = std::max(worst, max_relative_difference(a.sums, serial));
    // Which threads run the blocks does not matter: bit-identical.
    const Outcome b = block_sums(l, blocks, 2);
    EXPECT_EQ(a.sums, b.sums) << blocks << " blocks on 1 and 2 threads";
  }
  // ~15 terms of O(1) per row, added in another grouping: a few ulps of the largest sum.
  test::verify({"Block-wise pair sums (thread_sums.hpp), 2-16 blocks: max difference from the serial loop",
                "serial scatter loop (round-off)", 0.0, worst, 1e-13, false, "relative to peak"});
}

TEST(SphThreadSums, BlocksShareTheCostEvenly) {
  const Lists l = make_lists(5000, 300, 3);
  RowBlocks rb;
  rb.build(4, l.n, l.prefix.data(), 4, [](std::size_t i) { return i + 1; });
  ASSERT_EQ(rb.count(), 4u);
  const double total = static_cast<double>(l.prefix[l.n] + 4 * l.n);
  for (std::size_t k = 0; k < 4; ++k) {
    const double cost =
        static_cast<double>(l.prefix[rb.end(k)] - l.prefix[rb.begin(k)] + 4 * (rb.end(k) - rb.begin(k)));
    // Within one row's cost (at most 41 pairs + 4) of an equal share.
    EXPECT_NEAR(cost, total / 4.0, 45.0) << "block " << k;
  }
  // More blocks than rows: one row each, the rest empty.
  RowBlocks tiny;
  tiny.build(8, 3, l.prefix.data(), 4, [](std::size_t i) { return i + 1; });
  EXPECT_EQ(tiny.count(), 3u);
  EXPECT_EQ(tiny.end(2), 3u);
}
