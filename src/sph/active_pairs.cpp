#include "sph/active_pairs.hpp"

#include <algorithm>
#include <cmath>

#include "sph/kernel.hpp"

namespace camouflet::sph {

template <int D>
void ActivePairs<D>::refresh(const NeighbourSearch<D>& search, const std::vector<Vec<D>>& x,
                             const std::vector<double>& h, std::size_t n) {
  const std::size_t total = x.size();
  if (builds_ == search.builds() && x_.size() == total) {
    // Same criterion as NeighbourSearch::needs_rebuild, against the extraction.
    double d2_max = 0.0, dh_max = 0.0;
#pragma omp parallel for schedule(static) reduction(max : d2_max, dh_max)
    for (std::size_t k = 0; k < total; ++k) {
      const Vec<D> d = x[k] - x_[k];
      d2_max = std::max(d2_max, dot(d, d));
      dh_max = std::max(dh_max, h[k] - h_[k]);
    }
    if (2.0 * std::sqrt(d2_max) + support_factor * dh_max <= margin_) return;
  }
  builds_ = search.builds();
  ++extractions_;
  x_.assign(x.begin(), x.end());
  h_.assign(h.begin(), h.end());
  offset_.assign(n + 1, 0);
  // The cell lists hold every pair within 2 h_ij + (their skin - the part of it used):
  // the thin skin can be no wider than that.
  const double skin = std::max(0.0, std::min(skin_, search.skin() - search.skin_used(x, h)));
  margin_ = skin;
  auto inside = [&](std::size_t i, std::uint32_t j) {
    const Vec<D> dx = x[i] - x[j];
    const double reach = support_factor * pair_smoothing_length(h[i], h[j]) + skin;
    return dot(dx, dx) < reach * reach;
  };
  // One pass over the cell lists: each block of particles collects its entries
  // in a buffer of its own, then the buffers are copied into place. Only the
  // part of a row with j > i is kept (the pair sums read no other): a pair's
  // distance is tested in the row of its smaller index only.
  constexpr std::size_t block = 256;
  const std::size_t n_blocks = (n + block - 1) / block;
  std::vector<std::vector<std::uint32_t>> found(n_blocks);
#pragma omp parallel for schedule(dynamic, 4)
  for (std::size_t b = 0; b < n_blocks; ++b) {
    std::vector<std::uint32_t>& buffer = found[b];
    const std::size_t end = std::min(n, (b + 1) * block);
    std::size_t candidates = 0;
    for (std::size_t i = b * block; i < end; ++i) candidates += search.neighbours(i).size();
    buffer.reserve(candidates / 2 + block);
    // A row in two parts, each in the cell lists' order: the particles j > i, then the points
    // without sums of their own (j >= n: ghosts, coupling points).
    std::vector<std::uint32_t> other_points;
    for (std::size_t i = b * block; i < end; ++i) {
      const std::size_t start = buffer.size();
      other_points.clear();
      for (const std::uint32_t j : search.neighbours(i)) {
        if (j <= i || !inside(i, j)) continue;
        if (j < n)
          buffer.push_back(j);
        else
          other_points.push_back(j);
      }
      buffer.insert(buffer.end(), other_points.begin(), other_points.end());
      offset_[i + 1] = buffer.size() - start;
    }
  }
  for (std::size_t i = 0; i < n; ++i) offset_[i + 1] += offset_[i];
  list_.resize(offset_[n]);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n_blocks; ++b)
    std::copy(found[b].begin(), found[b].end(), list_.begin() + static_cast<std::ptrdiff_t>(offset_[b * block]));
}

template class ActivePairs<2>;
template class ActivePairs<3>;

}  // namespace camouflet::sph
