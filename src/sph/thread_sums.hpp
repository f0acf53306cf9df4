#pragma once
// Pair-symmetric particle sums under OpenMP without write conflicts.
//
// The rows (particles) of a pair-once loop are split into contiguous blocks
// of about equal cost (pairs + a per-row share), a few per thread. A row i only
// scatters to partners j > i, so block k's sums reach only the rows from its
// first row up to the largest partner of its rows: its *window*. Each block
// accumulates into its own copy of the sums over its window only, and row i's
// total adds, in block order, the copies of the blocks whose windows hold it
// (its own block and the few earlier blocks that reach past their end). The
// zeroing and the reduction are then O(n) in total instead of O(threads x n),
// and each thread touches mostly its own rows (docs/performance.md, "SPH
// threads at dbbebad").
//
// The blocks depend only on the lists and on the number of blocks, not on
// which thread runs a block: a fixed thread count is bit-identical run to run,
// and thread counts differ only in the grouping of the additions (round-off).
// With one block every row's sum is accumulated exactly as a serial loop does.
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace camouflet::sph {

class RowBlocks {
 public:
  // Splits rows [0, n) into `blocks` contiguous ranges of about equal cost,
  // cost of the rows below i = pair_prefix[i] + row_cost i (pair_prefix: n + 1
  // non-decreasing entries), and records their windows: reach(i) is one past
  // the largest row that row i scatters to (at least i + 1).
  template <class Reach>
  void build(std::size_t blocks, std::size_t n, const std::size_t* pair_prefix, std::size_t row_cost,
             Reach reach) {
    blocks = std::max<std::size_t>(1, std::min(blocks, std::max<std::size_t>(n, 1)));
    begin_.assign(blocks + 1, n);
    begin_[0] = 0;
    const double total = static_cast<double>(pair_prefix[n] + row_cost * n);
    std::size_t row = 0;
    for (std::size_t k = 1; k < blocks; ++k) {
      const double target = total * static_cast<double>(k) / static_cast<double>(blocks);
      while (row < n && static_cast<double>(pair_prefix[row] + row_cost * row) < target) ++row;
      begin_[k] = row;
    }
    window_.assign(blocks, 0);
#pragma omp parallel for schedule(static, 1)
    for (std::size_t k = 0; k < blocks; ++k) {
      std::size_t end = begin_[k];
      for (std::size_t i = begin_[k]; i < begin_[k + 1]; ++i) end = std::max(end, reach(i));
      window_[k] = end;
    }
    // Per block m, the earlier blocks whose windows reach into it, in block order.
    earlier_first_.assign(blocks + 1, 0);
    earlier_.clear();
    for (std::size_t m = 0; m < blocks; ++m) {
      for (std::size_t k = 0; k < m; ++k)
        if (window_[k] > begin_[m]) earlier_.push_back(k);
      earlier_first_[m + 1] = earlier_.size();
    }
  }
  std::size_t count() const {
    return window_.size();
  }
  std::size_t begin(std::size_t k) const {
    return begin_[k];
  }
  std::size_t end(std::size_t k) const {
    return begin_[k + 1];
  }
  std::size_t window_end(std::size_t k) const {
    return window_[k];
  }
  const std::size_t* earlier_begin(std::size_t m) const {
    return earlier_.data() + earlier_first_[m];
  }
  const std::size_t* earlier_end(std::size_t m) const {
    return earlier_.data() + earlier_first_[m + 1];
  }

 private:
  std::vector<std::size_t> begin_;   // blocks + 1: block k has rows [begin_[k], begin_[k + 1])
  std::vector<std::size_t> window_;  // block k's sums reach rows [begin_[k], window_[k])
  std::vector<std::size_t> earlier_first_, earlier_;
};

// Every block's copy of the sums, indexed by row. A copy spans all n rows, so
// that a row indexes it directly, but only its block's window is ever zeroed,
// written or read; the storage is allocated without initialising it, so the
// pages outside the windows are never touched and cost no memory (T is an
// aggregate of doubles and ints: the allocation creates its objects, C++20).
template <class T>
class BlockSums {
 public:
  // Outside the parallel region: room for every block's copy (allocates only when that grows).
  void prepare(const RowBlocks& blocks, std::size_t n) {
    n_ = n;
    const std::size_t need = blocks.count() * n;
    if (need > capacity_) {
      data_.reset(static_cast<T*>(::operator new (need * sizeof(T), std::align_val_t{64})));
      capacity_ = need;
    }
  }
  // Block k's copy, its window zeroed (by the thread that runs block k).
  T* zeroed(const RowBlocks& blocks, std::size_t k) {
    T* own = data_.get() + k * n_;
    std::fill(own + blocks.begin(k), own + blocks.window_end(k), T{});
    return own;
  }
  // Row i of block m: the copies holding it added in block order, add(total, part).
  template <class Add>
  T total(const RowBlocks& blocks, std::size_t m, std::size_t i, Add add) const {
    const T* data = data_.get();
    const T& own = data[m * n_ + i];
    const std::size_t* k = blocks.earlier_begin(m);
    const std::size_t* const last = blocks.earlier_end(m);
    while (k != last && blocks.window_end(*k) <= i) ++k;
    if (k == last) return own;
    T sum = data[*k * n_ + i];
    for (++k; k != last; ++k)
      if (blocks.window_end(*k) > i) add(sum, data[*k * n_ + i]);
    add(sum, own);
    return sum;
  }

 private:
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
  struct Release {
    void operator()(T* p) const { ::operator delete (p, std::align_val_t{64}); }
  };
  std::size_t n_ = 0, capacity_ = 0;
  std::unique_ptr<T, Release> data_;
};

// Inside a parallel region: every block's rows, row(i, own) into the block's copy of the sums
// (its window zeroed first), blocks handed out one at a time.
template <class T, class Row>
void for_each_row_block(const RowBlocks& blocks, BlockSums<T>& sums, Row row) {
  const std::size_t n_blocks = blocks.count();
#pragma omp for schedule(dynamic, 1)
  for (std::size_t k = 0; k < n_blocks; ++k) {
    T* const own = sums.zeroed(blocks, k);
    for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i) row(i, own);
  }
}

// Inside a parallel region, after for_each_row_block's implied barrier: each row's total over
// the copies that hold it, add(total, part) in block order, handed to done(i, total).
template <class T, class Add, class Done>
void for_each_row_total(const RowBlocks& blocks, const BlockSums<T>& sums, Add add, Done done) {
  const std::size_t n_blocks = blocks.count();
#pragma omp for schedule(dynamic, 1)
  for (std::size_t k = 0; k < n_blocks; ++k)
    for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i) done(i, sums.total(blocks, k, i, add));
}

}  // namespace camouflet::sph
