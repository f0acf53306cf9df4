#include "mesh/graded_axis.hpp"

#include <algorithm>
#include <cmath>

namespace camouflet::buried_detail {

namespace {

void add_graded(std::vector<Interval>& out, double a, double b, double h0, double h1) {
  const int n = cells_for(b - a, h0, h1);
  out.push_back({a, b, n, n > 1 ? h1 / h0 : 1.0});
}

}  // namespace

int cells_for(double length, double h0, double h1) {
  const double n =
      std::abs(h1 / h0 - 1.0) < 0.05 ? length / (0.5 * (h0 + h1)) : length * std::log(h1 / h0) / (h1 - h0);
  return std::max(1, static_cast<int>(std::ceil(n - 1e-6)));
}

std::vector<Interval> layout_axis(double lo, double hi, std::vector<double> lines,
                                  const std::vector<Zone>& zones, double gap_size, double far_size,
                                  bool far_at_lo) {
  lines.push_back(lo);
  lines.push_back(hi);
  for (const Zone& z : zones) {
    lines.push_back(std::clamp(z.lo, lo, hi));
    lines.push_back(std::clamp(z.hi, lo, hi));
  }
  std::sort(lines.begin(), lines.end());
  std::vector<double> unique;
  for (double x : lines)
    if (x >= lo && x <= hi && (unique.empty() || x - unique.back() > 1e-9)) unique.push_back(x);
  const auto zone_size = [&](double x) {
    double h = 0.0;
    for (const Zone& z : zones)
      if (x > z.lo && x < z.hi) h = h > 0.0 ? std::min(h, z.size) : z.size;
    return h;  // 0: in no zone
  };
  std::vector<Interval> out;
  for (std::size_t k = 0; k + 1 < unique.size(); ++k) {
    const double a = unique[k], b = unique[k + 1];
    const double inside = zone_size(0.5 * (a + b));
    if (inside > 0.0) {
      add_graded(out, a, b, inside, inside);
      continue;
    }
    const double eps = 1e-6 * (hi - lo);
    double hl = zone_size(a - eps), hr = zone_size(b + eps);
    if (!(hr > 0.0)) hr = gap_size;
    if (far_at_lo && a <= lo) {
      add_graded(out, a, b, std::max(hr, far_size), hr);
      continue;
    }
    if (!(hl > 0.0)) hl = gap_size;
    if (b >= hi) {
      add_graded(out, a, b, hl, std::max(hl, far_size));
      continue;
    }
    const double middle = std::min(gap_size, std::max({hl, hr, 0.25 * (b - a)}));
    if (middle <= 1.05 * std::max(hl, hr)) {
      add_graded(out, a, b, hl, hr);
    } else {
      const double m = 0.5 * (a + b);
      add_graded(out, a, m, hl, middle);
      add_graded(out, m, b, middle, hr);
    }
  }
  return out;
}

std::vector<double> ends_of(const std::vector<Interval>& axis) {
  std::vector<double> x{axis.front().a};
  for (const Interval& i : axis) x.push_back(i.b);
  return x;
}

}  // namespace camouflet::buried_detail
