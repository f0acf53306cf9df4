#include "model/element_locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace camouflet {

namespace {

int nodes_per_element(int dim) {
  return dim == 2 ? 4 : 8;
}

// Bounding box of element e, widened by `slack` of its extent per axis.
void element_box(int dim, std::span<const double> x, std::span<const std::int64_t> conn, std::int64_t e,
                 double slack, std::array<double, 3>& lo, std::array<double, 3>& hi) {
  const int npe = nodes_per_element(dim);
  lo.fill(std::numeric_limits<double>::max());
  hi.fill(-std::numeric_limits<double>::max());
  for (int a = 0; a < npe; ++a) {
    const auto n = static_cast<std::size_t>(conn[static_cast<std::size_t>(e * npe + a)]);
    for (int i = 0; i < dim; ++i) {
      lo[i] = std::min(lo[i], x[n * dim + i]);
      hi[i] = std::max(hi[i], x[n * dim + i]);
    }
  }
  for (int i = 0; i < dim; ++i) {
    const double w = slack * (hi[i] - lo[i]);
    lo[i] -= w;
    hi[i] += w;
  }
}

}  // namespace

ElementLocator::ElementLocator(int dim, std::span<const double> coordinates,
                               std::span<const std::int64_t> connectivity)
    : dim_(dim), coordinates_(coordinates), connectivity_(connectivity) {
  const int npe = nodes_per_element(dim);
  const auto n_elements = static_cast<std::int64_t>(connectivity.size() / static_cast<std::size_t>(npe));
  bin_start_.assign(2, 0);
  if (n_elements == 0) return;
  // The slack of the boxes covers a point up to max_tolerance outside an element in natural
  // coordinates (a natural unit is half the element's extent, so this is generous).
  const double slack = max_tolerance;
  std::array<double, 3> lo{}, hi{}, mesh_lo, mesh_hi;
  mesh_lo.fill(std::numeric_limits<double>::max());
  mesh_hi.fill(-std::numeric_limits<double>::max());
  double mean_extent = 0.0;
  for (std::int64_t e = 0; e < n_elements; ++e) {
    element_box(dim, coordinates, connectivity, e, slack, lo, hi);
    for (int i = 0; i < dim; ++i) {
      mesh_lo[i] = std::min(mesh_lo[i], lo[i]);
      mesh_hi[i] = std::max(mesh_hi[i], hi[i]);
      mean_extent += (hi[i] - lo[i]) / (dim * static_cast<double>(n_elements));
    }
  }
  // Bins of about the mean element extent, at most about 4 per element in all.
  double size = std::max(mean_extent, 1e-300);
  const double max_bins = 4.0 * static_cast<double>(n_elements) + 64.0;
  for (;;) {
    double bins = 1.0;
    for (int i = 0; i < dim; ++i) bins *= std::max(1.0, std::ceil((mesh_hi[i] - mesh_lo[i]) / size));
    if (bins <= max_bins) break;
    size *= 1.5;
  }
  for (int i = 0; i < dim; ++i) {
    lo_[i] = mesh_lo[i];
    cells_[i] =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil((mesh_hi[i] - mesh_lo[i]) / size)));
    cell_[i] = std::max((mesh_hi[i] - mesh_lo[i]) / static_cast<double>(cells_[i]), 1e-300);
  }
  const std::int64_t n_bins = cells_[0] * cells_[1] * cells_[2];
  // Two passes (count, then fill) over the bins each element's box overlaps; elements enter
  // their bins in ascending order, which keeps locate_point's choice of the lowest number.
  std::vector<std::int64_t> count(static_cast<std::size_t>(n_bins) + 1, 0);
  const auto visit = [&](std::int64_t e, auto&& f) {
    element_box(dim, coordinates, connectivity, e, slack, lo, hi);
    std::array<std::int64_t, 3> a{0, 0, 0}, b{0, 0, 0};
    for (int i = 0; i < dim; ++i) {
      a[i] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((lo[i] - lo_[i]) / cell_[i])), 0,
                                      cells_[i] - 1);
      b[i] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((hi[i] - lo_[i]) / cell_[i])), 0,
                                      cells_[i] - 1);
    }
    for (std::int64_t k = a[2]; k <= b[2]; ++k)
      for (std::int64_t j = a[1]; j <= b[1]; ++j)
        for (std::int64_t i = a[0]; i <= b[0]; ++i) f(bin_of({i, j, k}));
  };
  for (std::int64_t e = 0; e < n_elements; ++e) visit(e, [&](std::int64_t bin) { ++count[bin + 1]; });
  for (std::int64_t b = 0; b < n_bins; ++b) count[b + 1] += count[b];
  bin_start_ = count;
  bin_elements_.resize(static_cast<std::size_t>(count.back()));
  for (std::int64_t e = 0; e < n_elements; ++e)
    visit(e, [&](std::int64_t bin) { bin_elements_[count[bin]++] = e; });
}

std::int64_t ElementLocator::bin_of(const std::array<std::int64_t, 3>& index) const {
  return index[0] + cells_[0] * (index[1] + cells_[1] * index[2]);
}

std::optional<ElementLocation> ElementLocator::locate(std::span<const double> x, double tol) const {
  if (tol > max_tolerance) throw std::invalid_argument("ElementLocator: tolerance above max_tolerance");
  if (bin_elements_.empty()) return std::nullopt;
  std::array<std::int64_t, 3> index{0, 0, 0};
  for (int i = 0; i < dim_; ++i) {
    const double t = (x[static_cast<std::size_t>(i)] - lo_[i]) / cell_[i];
    if (!(t >= 0.0) || t > static_cast<double>(cells_[i])) return std::nullopt;  // outside every box
    index[i] = std::min<std::int64_t>(static_cast<std::int64_t>(t), cells_[i] - 1);
  }
  const std::int64_t bin = bin_of(index);
  for (std::int64_t k = bin_start_[bin]; k < bin_start_[bin + 1]; ++k)
    if (auto found = locate_in_element(dim_, coordinates_, connectivity_,
                                       bin_elements_[static_cast<std::size_t>(k)], x, tol))
      return found;
  return std::nullopt;
}

}  // namespace camouflet
