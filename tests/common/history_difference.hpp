#pragma once
// Round-off comparisons of two runs of one case (thread counts, assembly
// orders): the largest entry-wise difference relative to the largest entry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace camouflet::test {

// Largest |a - b| over the histories, relative to the largest |a|.
inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double peak = 0.0, diff = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    peak = std::max(peak, std::abs(a[k]));
    diff = std::max(diff, std::abs(a[k] - b[k]));
  }
  return peak > 0.0 ? diff / peak : diff;
}

}  // namespace camouflet::test
