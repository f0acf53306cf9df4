#include "mesh/simplex_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace camouflet {

namespace {

constexpr double tolerance = 1e-10;  // on barycentric coordinates: points on a face are inside

// Signed area (2-D) / volume (3-D) of a simplex, times 2 / 6.
double signed_measure(int dim, const std::array<double, 3>* v) {
  const double ax = v[1][0] - v[0][0], ay = v[1][1] - v[0][1], az = v[1][2] - v[0][2];
  const double bx = v[2][0] - v[0][0], by = v[2][1] - v[0][1], bz = v[2][2] - v[0][2];
  if (dim == 2) return ax * by - ay * bx;
  const double cx = v[3][0] - v[0][0], cy = v[3][1] - v[0][1], cz = v[3][2] - v[0][2];
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

}  // namespace

SimplexRegion::SimplexRegion(int dimension, std::vector<std::array<double, 3>> vertices)
    : dim_(dimension), corners_(std::move(vertices)) {
  if (dim_ != 2 && dim_ != 3) throw std::invalid_argument("SimplexRegion: dimension must be 2 or 3");
  const std::size_t per = static_cast<std::size_t>(dim_ + 1);
  if (corners_.empty() || corners_.size() % per != 0)
    throw std::invalid_argument("SimplexRegion: vertex count is not a multiple of dimension + 1");
  lo_.fill(std::numeric_limits<double>::infinity());
  hi_.fill(-std::numeric_limits<double>::infinity());
  for (const auto& v : corners_)
    for (int d = 0; d < dim_; ++d) lo_[d] = std::min(lo_[d], v[d]), hi_[d] = std::max(hi_[d], v[d]);
  if (dim_ == 2) lo_[2] = hi_[2] = 0.0;
  // About one simplex per bucket on average.
  const std::size_t n = size();
  double volume = 1.0;
  for (int d = 0; d < dim_; ++d) volume *= std::max(hi_[d] - lo_[d], 1e-300);
  const double edge = std::pow(volume / static_cast<double>(n), 1.0 / dim_);
  for (int d = 0; d < dim_; ++d) {
    cells_[d] = std::clamp(static_cast<long>((hi_[d] - lo_[d]) / edge), 1L, 1024L);
    cell_size_[d] = std::max(hi_[d] - lo_[d], 1e-300) / static_cast<double>(cells_[d]);
  }
  const std::size_t total = static_cast<std::size_t>(cells_[0] * cells_[1] * cells_[2]);
  // Counting sort of (bucket, simplex) over the buckets each simplex's box overlaps.
  std::vector<std::pair<std::size_t, std::uint32_t>> entries;
  for (std::size_t s = 0; s < n; ++s) {
    std::array<double, 3> blo{}, bhi{};
    blo.fill(std::numeric_limits<double>::infinity());
    bhi.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < per; ++k)
      for (int d = 0; d < dim_; ++d)
        blo[d] = std::min(blo[d], corners_[s * per + k][d]),
        bhi[d] = std::max(bhi[d], corners_[s * per + k][d]);
    const auto c0 = cell_of(blo.data()), c1 = cell_of(bhi.data());
    for (long k = c0[2]; k <= c1[2]; ++k)
      for (long j = c0[1]; j <= c1[1]; ++j)
        for (long i = c0[0]; i <= c1[0]; ++i)
          entries.emplace_back(static_cast<std::size_t>((k * cells_[1] + j) * cells_[0] + i),
                               static_cast<std::uint32_t>(s));
  }
  bucket_offset_.assign(total + 1, 0);
  for (const auto& e : entries) ++bucket_offset_[e.first + 1];
  for (std::size_t b = 0; b < total; ++b) bucket_offset_[b + 1] += bucket_offset_[b];
  bucket_.resize(entries.size());
  std::vector<std::size_t> fill(bucket_offset_.begin(), bucket_offset_.end() - 1);
  for (const auto& e : entries) bucket_[fill[e.first]++] = e.second;
}

std::array<long, 3> SimplexRegion::cell_of(const double* x) const {
  std::array<long, 3> c{0, 0, 0};
  for (int d = 0; d < dim_; ++d)
    c[d] = std::clamp(static_cast<long>(std::floor((x[d] - lo_[d]) / cell_size_[d])), 0L, cells_[d] - 1);
  return c;
}

bool SimplexRegion::in_simplex(std::size_t s, const double* x) const {
  const std::size_t per = static_cast<std::size_t>(dim_ + 1);
  std::array<double, 3> v[4]{};
  for (std::size_t k = 0; k < per; ++k) v[k] = corners_[s * per + k];
  const double whole = signed_measure(dim_, v);
  if (whole == 0.0) return false;  // degenerate simplex
  // Barycentric coordinate k: the measure with corner k replaced by x, over the whole.
  for (std::size_t k = 0; k < per; ++k) {
    std::array<double, 3> w[4] = {v[0], v[1], v[2], v[3]};
    w[k] = {x[0], x[1], dim_ == 3 ? x[2] : 0.0};
    if (signed_measure(dim_, w) / whole < -tolerance) return false;
  }
  return true;
}

bool SimplexRegion::contains(const double* x) const {
  for (int d = 0; d < dim_; ++d) {
    const double pad = tolerance * (hi_[d] - lo_[d]);
    if (x[d] < lo_[d] - pad || x[d] > hi_[d] + pad) return false;
  }
  const auto c = cell_of(x);
  const std::size_t b = static_cast<std::size_t>((c[2] * cells_[1] + c[1]) * cells_[0] + c[0]);
  for (std::size_t k = bucket_offset_[b]; k < bucket_offset_[b + 1]; ++k)
    if (in_simplex(bucket_[k], x)) return true;
  return false;
}

double SimplexRegion::measure() const {
  const std::size_t per = static_cast<std::size_t>(dim_ + 1);
  double sum = 0.0;
  for (std::size_t s = 0; s < size(); ++s) {
    std::array<double, 3> v[4]{};
    for (std::size_t k = 0; k < per; ++k) v[k] = corners_[s * per + k];
    sum += std::abs(signed_measure(dim_, v));
  }
  return sum / (dim_ == 2 ? 2.0 : 6.0);
}

}  // namespace camouflet
