#pragma once
// Cell-linked-list neighbour search with a skin (Verlet lists on a cell grid).
//
// A pair (i, j) is listed when |x_i - x_j| < 2 h_ij + skin at the time of the
// build, h_ij = (h_i + h_j)/2. The lists stay valid, i.e. contain every pair
// inside the kernel support 2 h_ij, as long as
//     2 max|x - x_build| + 2 max(h - h_build) <= skin,
// because a pair's distance shrinks by at most twice the largest displacement
// and its support grows by at most twice the largest growth of h. The owner
// asks needs_rebuild() each cycle; rebuilding is O(N): particles are sorted by
// cell (cells of half the largest reach) with a counting sort, and only the
// cells within a point's own largest reach are searched.
//
// Lists are full (both i->j and j->i) and in the order of the build's visit:
// the cells within i's reach in ascending cell index, each cell's points in
// ascending index. That order is fixed by the positions at the build alone
// (any thread count gives the same lists); it is not sorted by j. The pair
// sums of SphSystem run over a thin-skin sub-list of them, each particle pair
// once (the j > i part), scattering into per-thread sums (sph_forces.cpp).
// Only the first n_owned points get lists; points after them (ghosts) are
// candidates only.
#include <cstdint>
#include <span>
#include <vector>

#include "core/state_visitor.hpp"
#include "core/vec.hpp"

namespace camouflet::sph {

template <int D>
class NeighbourSearch {
 public:
  // Builds the lists of the first n_owned points among all of x (ghosts after them).
  void build(std::span<const Vec<D>> x, std::span<const double> h, std::size_t n_owned, double skin);

  // True when a particle may have entered another's support since the build.
  bool needs_rebuild(std::span<const Vec<D>> x, std::span<const double> h) const;
  // How much of the skin the motion since the build has used (m):
  // 2 max|x - x_build| + 2 max(h - h_build); the lists hold every pair with
  // |x_i - x_j| < 2 h_ij + skin() - skin_used(x, h).
  double skin_used(std::span<const Vec<D>> x, std::span<const double> h) const;

  std::span<const std::uint32_t> neighbours(std::size_t i) const {
    return {list_.data() + offset_[i], offset_[i + 1] - offset_[i]};
  }
  std::size_t owned_count() const { return n_owned_; }
  std::size_t pair_count() const { return list_.size(); }
  double skin() const { return skin_; }
  std::int64_t builds() const { return builds_; }
  // Points in the order of the cells they sit in at the last build (cache-friendly order).
  const std::vector<std::uint32_t>& cell_order() const { return sorted_; }
  // The lists and their build state, so a restart sums neighbours in the same order (sph_state.cpp).
  void visit_state(StateVisitor& visitor);

 private:
  std::vector<std::size_t> offset_;
  std::vector<std::uint32_t> list_;
  std::vector<std::uint32_t> sorted_;
  std::vector<Vec<D>> x_build_;
  std::vector<double> h_build_;
  std::size_t n_owned_ = 0;
  double skin_ = 0.0;
  std::int64_t builds_ = 0;
};

// O(N^2) reference: for each of the first n_owned points, the sorted indices j
// with |x_i - x_j| < 2 h_ij + skin. For tests and debugging only.
template <int D>
std::vector<std::vector<std::uint32_t>> brute_force_neighbours(std::span<const Vec<D>> x,
                                                               std::span<const double> h, std::size_t n_owned,
                                                               double skin);

}  // namespace camouflet::sph
