#pragma once
// One axis of a tensor-product block grid (the buried-structure generators,
// src/mesh/buried_structure*.cpp): block lines at every material boundary and
// zone end, uniform cells inside the zones of a given size (near the charge,
// in the structure), geometric grading in the gaps between them, growing to a
// far size at the model's edges. docs/buried-structure.md, "The generator".
#include <vector>

namespace camouflet::buried_detail {

// A stretch of one axis meshed with a uniform target size (m).
struct Zone {
  double lo, hi, size;
};

// One interval of an axis: [a, b], its cells and grading (last/first cell size).
struct Interval {
  double a, b;
  int cells;
  double grading;
};

// Cells of a size growing linearly from h0 to h1 over `length`: the integral of dx / h(x).
int cells_for(double length, double h0, double h1);

// Lays out one axis from `lo` to `hi`: breakpoints at every zone end and
// material line, uniform cells inside zones, geometric grading in the gaps
// (up to `gap_size` in their middle), growing to `far_size` at `hi` (and at
// `lo` too when `far_at_lo`, for an axis whose both ends are far edges).
std::vector<Interval> layout_axis(double lo, double hi, std::vector<double> lines,
                                  const std::vector<Zone>& zones, double gap_size, double far_size,
                                  bool far_at_lo = false);

// The block lines of an axis: its start and the end of every interval.
std::vector<double> ends_of(const std::vector<Interval>& axis);

}  // namespace camouflet::buried_detail
