#include "sph/neighbour_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sph/kernel.hpp"

namespace camouflet::sph {

namespace {

template <int D>
struct CellGrid {
  Vec<D> origin;
  double size = 1.0;
  std::array<std::int64_t, D> dims{};

  std::array<std::int64_t, D> cell_of(const Vec<D>& x) const {
    std::array<std::int64_t, D> c{};
    for (int d = 0; d < D; ++d) {
      c[d] = static_cast<std::int64_t>(std::floor((x[d] - origin[d]) / size));
      c[d] = std::clamp<std::int64_t>(c[d], 0, dims[d] - 1);
    }
    return c;
  }
  std::int64_t index(const std::array<std::int64_t, D>& c) const {
    std::int64_t k = 0;
    for (int d = D - 1; d >= 0; --d) k = k * dims[d] + c[d];
    return k;
  }
  std::int64_t count() const {
    std::int64_t n = 1;
    for (int d = 0; d < D; ++d) n *= dims[d];
    return n;
  }
};

template <int D>
double squared_distance(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int d = 0; d < D; ++d) s += (a[d] - b[d]) * (a[d] - b[d]);
  return s;
}

}  // namespace

template <int D>
void NeighbourSearch<D>::build(std::span<const Vec<D>> x, std::span<const double> h, std::size_t n_owned,
                               double skin) {
  const std::size_t n = x.size();
  if (h.size() != n || n_owned > n) throw std::invalid_argument("neighbour search: inconsistent array sizes");
  if (n >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("neighbour search: too many points");
  n_owned_ = n_owned;
  skin_ = skin;
  ++builds_;
  x_build_.assign(x.begin(), x.end());
  h_build_.assign(h.begin(), h.end());
  offset_.assign(n_owned + 1, 0);
  list_.clear();
  sorted_.clear();
  if (n == 0) return;

  CellGrid<D> grid;
  Vec<D> lo = x[0], hi = x[0];
  double h_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) {
      lo[d] = std::min(lo[d], x[i][d]);
      hi[d] = std::max(hi[d], x[i][d]);
    }
    h_max = std::max(h_max, h[i]);
  }
  grid.origin = lo;
  // Cells of half the largest interaction radius: the candidates of a point lie in the cells that
  // meet the cube of that radius around it, about 5^D half cells (15.6 radii cubed in 3-D)
  // against 3^D whole cells (27). docs/performance.md, "SPH partner sums by transpose, half cells".
  const double reach_max = support_factor * h_max + skin;
  grid.size = 0.5 * reach_max;
  if (!(grid.size > 0.0)) grid.size = 1.0;
  // Keep the grid at most a few cells per point (a few far-flung points must not blow it up).
  for (;;) {
    std::int64_t total = 1;
    for (int d = 0; d < D; ++d) {
      grid.dims[d] = std::max<std::int64_t>(1, static_cast<std::int64_t>((hi[d] - lo[d]) / grid.size) + 1);
      total *= grid.dims[d];
    }
    if (total <= 4 * static_cast<std::int64_t>(n) + 64) break;
    grid.size *= 1.5;
  }

  // Counting sort of the points by cell.
  const std::int64_t n_cells = grid.count();
  std::vector<std::int64_t> cell(n);
  std::vector<std::size_t> cell_start(static_cast<std::size_t>(n_cells) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = grid.index(grid.cell_of(x[i]));
    ++cell_start[static_cast<std::size_t>(cell[i]) + 1];
  }
  for (std::int64_t c = 0; c < n_cells; ++c) cell_start[c + 1] += cell_start[c];
  sorted_.resize(n);
  {
    std::vector<std::size_t> fill(cell_start.begin(), cell_start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      sorted_[fill[static_cast<std::size_t>(cell[i])]++] = static_cast<std::uint32_t>(i);
  }

  // Positions and smoothing lengths in cell order, so that the candidates of
  // a cell are read contiguously. The cells along x of each (y, z) row of the
  // block visited are consecutive in that order: one range per row.
  std::vector<Vec<D>> x_cell(n);
  std::vector<double> h_cell(n);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n; ++s) {
    x_cell[s] = x[sorted_[s]];
    h_cell[s] = h[sorted_[s]];
  }

  // Visits every candidate j of point i in the cells that meet the cube [x_i - reach_i,
  // x_i + reach_i], in cell order, reach_i the largest reach of i's pairs; rows of cells along x
  // whose distance from x_i in the other axes is beyond it are skipped. Every pair within reach is
  // visited.
  const auto cell_range = [&](int d, double xd, double reach, std::int64_t& first, std::int64_t& last) {
    const double lo_cell = std::floor((xd - reach - grid.origin[d]) / grid.size);
    const double hi_cell = std::floor((xd + reach - grid.origin[d]) / grid.size);
    first = std::clamp<std::int64_t>(static_cast<std::int64_t>(lo_cell), 0, grid.dims[d] - 1);
    last = std::clamp<std::int64_t>(static_cast<std::int64_t>(hi_cell), 0, grid.dims[d] - 1);
  };
  auto visit = [&](std::size_t i, auto&& on_pair) {
    const Vec<D> xi = x[i];
    const double hi = h[i];
    // Local pointers: on_pair may write memory, and the compiler would reload the vectors' pointers.
    const Vec<D>* xs = x_cell.data();
    const double* hs = h_cell.data();
    const std::uint32_t* js = sorted_.data();
    const std::size_t* starts = cell_start.data();
    // i's own largest reach (at most reach_max): h_ij <= (h_i + h_max) / 2, so a small particle among large
    // ones (graded fills, expanded products) scans a smaller box than the largest reach. (1 + 1e-12): the
    // cell bounds and the point's cell are rounded separately; no pair within reach may fall outside by an
    // ulp.
    const double reach_i = (1.0 + 1e-12) * (support_factor * pair_smoothing_length(hi, h_max) + skin);
    std::array<std::int64_t, D> first{}, last{};
    for (int d = 0; d < D; ++d) cell_range(d, xi[d], reach_i, first[d], last[d]);
    // The gap from x_i to cell c along axis d (0 if inside), squared.
    const auto gap2 = [&](int d, std::int64_t c) {
      const double a = grid.origin[d] + static_cast<double>(c) * grid.size;
      const double g = std::max({0.0, a - xi[d], xi[d] - (a + grid.size)});
      return g * g;
    };
    const double reach2 = reach_i * reach_i;
    std::array<std::int64_t, D> c{};
    const auto row = [&] {
      c[0] = first[0];
      const std::size_t begin = starts[grid.index(c)];
      c[0] = last[0];
      const std::size_t end = starts[grid.index(c) + 1];
      for (std::size_t s = begin; s < end; ++s) {
        const double reach = support_factor * pair_smoothing_length(hi, hs[s]) + skin;
        if (squared_distance(xi, xs[s]) < reach * reach && js[s] != i) on_pair(js[s]);
      }
    };
    if constexpr (D == 2) {
      for (c[1] = first[1]; c[1] <= last[1]; ++c[1])
        if (gap2(1, c[1]) < reach2) row();
    } else {
      for (c[2] = first[2]; c[2] <= last[2]; ++c[2]) {
        const double g2 = gap2(2, c[2]);
        if (!(g2 < reach2)) continue;
        for (c[1] = first[1]; c[1] <= last[1]; ++c[1])
          if (g2 + gap2(1, c[1]) < reach2) row();
      }
    }
  };

  // One pass over the candidates: each block of points collects its lists in
  // a buffer of its own, and the buffers are then copied into place (a count
  // pass and a fill pass visited every candidate twice). A row keeps the order
  // of the visit: sorting it by j took half of the build (~600 ns a particle,
  // 3-D, ~75 candidates; docs/performance.md, "SPH lists in cell order").
  constexpr std::size_t block = 256;
  const std::size_t n_blocks = (n_owned + block - 1) / block;
  std::vector<std::vector<std::uint32_t>> found(n_blocks);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t b = 0; b < n_blocks; ++b) {
    std::vector<std::uint32_t>& buffer = found[b];
    const std::size_t end = std::min(n_owned, (b + 1) * block);
    for (std::size_t i = b * block; i < end; ++i) {
      const std::size_t start = buffer.size();
      visit(i, [&](std::uint32_t j) { buffer.push_back(j); });
      offset_[i + 1] = buffer.size() - start;
    }
  }
  for (std::size_t i = 0; i < n_owned; ++i) offset_[i + 1] += offset_[i];
  list_.resize(offset_[n_owned]);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n_blocks; ++b)
    std::copy(found[b].begin(), found[b].end(),
              list_.begin() + static_cast<std::ptrdiff_t>(offset_[b * block]));
}

template <int D>
bool NeighbourSearch<D>::needs_rebuild(std::span<const Vec<D>> x, std::span<const double> h) const {
  if (x.size() != x_build_.size() || builds_ == 0) return true;
  return skin_used(x, h) > skin_;
}

template <int D>
double NeighbourSearch<D>::skin_used(std::span<const Vec<D>> x, std::span<const double> h) const {
  if (x.size() != x_build_.size() || builds_ == 0) return std::numeric_limits<double>::infinity();
  // Called several times a cycle: parallel (a max is exact, so any thread count gives the same bits).
  double d2_max = 0.0, dh_max = 0.0;
#pragma omp parallel for schedule(static) reduction(max : d2_max, dh_max)
  for (std::size_t i = 0; i < x.size(); ++i) {
    d2_max = std::max(d2_max, squared_distance(x[i], x_build_[i]));
    dh_max = std::max(dh_max, h[i] - h_build_[i]);
  }
  return 2.0 * std::sqrt(d2_max) + support_factor * dh_max;
}

template <int D>
std::vector<std::vector<std::uint32_t>> brute_force_neighbours(std::span<const Vec<D>> x,
                                                               std::span<const double> h, std::size_t n_owned,
                                                               double skin) {
  std::vector<std::vector<std::uint32_t>> out(n_owned);
  for (std::size_t i = 0; i < n_owned; ++i)
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (i == j) continue;
      const double reach = support_factor * pair_smoothing_length(h[i], h[j]) + skin;
      if (squared_distance(x[i], x[j]) < reach * reach) out[i].push_back(static_cast<std::uint32_t>(j));
    }
  return out;
}

template class NeighbourSearch<2>;
template class NeighbourSearch<3>;
template std::vector<std::vector<std::uint32_t>> brute_force_neighbours<2>(std::span<const Vec<2>>,
                                                                           std::span<const double>,
                                                                           std::size_t, double);
template std::vector<std::vector<std::uint32_t>> brute_force_neighbours<3>(std::span<const Vec<3>>,
                                                                           std::span<const double>,
                                                                           std::size_t, double);

}  // namespace camouflet::sph
