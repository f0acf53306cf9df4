#pragma once
// The domain box test of the node and particle checks, inline for
// the node loops that apply it to every node each cycle (fem/fem_package.cpp,
// solver/solver_checks.cpp, sph/sph_package.cpp), and how their failure
// messages write a position.
#include <fmt/format.h>

#include <string>

#include "model/model.hpp"

namespace camouflet {

// The first coordinate (0-based) of x outside [run.domain_min, run.domain_max]
// (a NaN is outside), -1 if none.
template <int D>
inline int first_outside_domain(const RunControl& run, const double* x) {
  for (int i = 0; i < D; ++i)
    if (!(x[i] >= run.domain_min[static_cast<std::size_t>(i)] &&
          x[i] <= run.domain_max[static_cast<std::size_t>(i)]))
      return i;
  return -1;
}

// "(x, y[, z]) m" to 6 significant digits.
template <int D>
std::string position_text(const double* x) {
  std::string s = "(";
  for (int i = 0; i < D; ++i) s += fmt::format("{}{:.6g}", i ? ", " : "", x[i]);
  return s + ") m";
}

}  // namespace camouflet
