#pragma once
// A package's points as a coupling reads them (docs/architecture.md, "Packages"): read-only
// spans over its arrays, by 0-based index, D components per point for position and velocity.
// Taken afresh at each use: a view is not kept across stages, so a package may resize its
// arrays (erosion, a re-sort, a restart) without leaving a coupling a stale pointer. The
// distributed-memory work will add the points' global ids here.
#include <cstddef>
#include <span>

namespace camouflet {

template <int D>
struct PointView {
  std::span<const double> position;  // m, n * D
  std::span<const double> velocity;  // m/s, n * D (v(n-1/2) or v(n+1/2), as the stage has it)
  std::span<const double> mass;      // kg, n (plane strain: per metre of depth)
  std::size_t count() const { return mass.size(); }
};

}  // namespace camouflet
