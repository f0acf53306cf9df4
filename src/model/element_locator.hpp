#pragma once
// Locating many points in one mesh: the elements' bounding boxes binned in a
// uniform grid, so a query tests the few elements of its bin instead of every
// element (locate_point). The answer is locate_point's: the lowest-numbered
// element whose closure holds the point.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/isoparametric.hpp"

namespace camouflet {

class ElementLocator {
 public:
  // Keeps views of `coordinates` and `connectivity`: they must outlive the locator.
  ElementLocator(int dim, std::span<const double> coordinates, std::span<const std::int64_t> connectivity);

  // As locate_point(dim, coordinates, connectivity, x, tol); tol at most max_tolerance.
  std::optional<ElementLocation> locate(std::span<const double> x, double tol = 1e-8) const;

  // The natural-coordinate tolerance the bins allow for (boxes are widened by it).
  static constexpr double max_tolerance = 1e-6;

 private:
  int dim_;
  std::span<const double> coordinates_;
  std::span<const std::int64_t> connectivity_;
  std::array<double, 3> lo_{}, cell_{};
  std::array<std::int64_t, 3> cells_{1, 1, 1};
  std::vector<std::int64_t> bin_start_;  // bin b holds bin_elements_[bin_start_[b] .. bin_start_[b + 1])
  std::vector<std::int64_t> bin_elements_;

  std::int64_t bin_of(const std::array<std::int64_t, 3>& index) const;
};

}  // namespace camouflet
