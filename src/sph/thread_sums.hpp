#pragma once
// Pair-symmetric particle sums under OpenMP without write conflicts: each
// thread scatters into its own copy of the per-particle sums, and the copies
// are added in thread order afterwards. With a static schedule the result is
// then bit-identical for a fixed thread count, and equal to round-off across
// thread counts (only the grouping of the additions differs).
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace camouflet::sph {

template <class T>
class ThreadSums {
 public:
  // Outside the parallel region: room for the largest team's copies of n sums
  // (allocates only when that grows).
  void prepare(std::size_t n) {
    n_ = n;
    const std::size_t need = static_cast<std::size_t>(omp_get_max_threads()) * n;
    if (data_.size() < need) data_.resize(need);
  }
  // Inside the region: the calling thread's copy, zeroed.
  T* own_zeroed() {
    T* own = data_.data() + static_cast<std::size_t>(omp_get_thread_num()) * n_;
    std::fill(own, own + n_, T{});
    return own;
  }
  // Copy t's sum of point i (t below the team size of the region that filled them).
  const T& at(int t, std::size_t i) const { return data_[static_cast<std::size_t>(t) * n_ + i]; }

 private:
  std::size_t n_ = 0;
  std::vector<T> data_;
};

}  // namespace camouflet::sph
