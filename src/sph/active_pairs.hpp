#pragma once
// The second-level pair list of the SPH sums (a Verlet list of the Verlet
// list): the entries of the cell-search lists with |x_i - x_j| < 2 h_ij +
// skin when extracted, in list order within the parts of a row (upper_neighbours). The pair sums run over it:
// the cell lists carry a skin of ~0.3 h (rebuilt every ~10 steps), i.e. about twice the pairs inside the
// support, while this one is re-extracted (a cheap scan) only when 2 max|x - x_extracted| + 2 max(h -
// h_extracted) exceeds its thin skin. Any list that holds every pair inside the support gives the same sums
// to round-off, so the list is not part of a checkpoint: the scalar rows skip a pair outside the support
// (bit for bit), but the SIMD rows give it a masked lane, so another list can move a row's later pairs to
// other lanes and change the order of the additions (pair_lanes.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "sph/neighbour_search.hpp"

namespace camouflet::sph {

template <int D>
class ActivePairs {
 public:
  // The thin skin asked for (m); an extraction takes less where the cell lists have used
  // part of theirs.
  void set_skin(double skin) { skin_ = skin; }

  // Re-extracts from the cell lists of `search` (rows 0..n-1 of the points x, h: particles,
  // then ghosts and coupling points) when they were rebuilt, the points moved past the thin
  // skin, or forget() was called; otherwise keeps the list.
  void refresh(const NeighbourSearch<D>& search, const std::vector<Vec<D>>& x, const std::vector<double>& h,
               std::size_t n);
  // After a restore: the next refresh() extracts afresh.
  void forget() { builds_ = -1; }

  // The part of row i with j > i: every pair of particles once, and all of i's pairs with
  // points that have no sums of their own (ghosts, coupling points), these last (j >= n).
  // Within each part the order of the cell lists (neighbour_search.hpp), not sorted by j.
  std::span<const std::uint32_t> upper_neighbours(std::size_t i) const {
    return {list_.data() + offset_[i], offset_[i + 1] - offset_[i]};
  }
  // n + 1 entries: where row i's j > i entries start among all such entries (per-pair stores).
  const std::vector<std::size_t>& upper_index() const { return offset_; }
  // Extractions so far: what a per-pair store or a row partition belongs to.
  std::int64_t extractions() const { return extractions_; }

 private:
  std::vector<std::uint32_t> list_;  // the rows' j > i parts, one after another
  std::vector<std::size_t> offset_;  // n + 1: row i's part is list_[offset_[i], offset_[i + 1])
  std::vector<Vec<D>> x_;            // m, positions at the extraction
  std::vector<double> h_;            // m, smoothing lengths at the extraction
  std::int64_t builds_ = -1;         // cell-list build it was extracted from (-1: none)
  std::int64_t extractions_ = 0;
  double skin_ = 0.0;    // m, the thin skin asked for
  double margin_ = 0.0;  // m, the skin of the current extraction (<= skin_)
};

extern template class ActivePairs<2>;
extern template class ActivePairs<3>;

}  // namespace camouflet::sph
