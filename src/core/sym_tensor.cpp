#include "core/sym_tensor.hpp"

#include <algorithm>
#include <functional>
#include <numbers>

namespace camouflet {

std::array<double, 3> principal_values(const SymTensor& a) {
  const double p1 = a.xy * a.xy + a.yz * a.yz + a.zx * a.zx;
  const double q = a.trace() / 3.0;
  if (p1 <= 1e-300 * (1.0 + q * q)) {
    std::array<double, 3> e{a.xx, a.yy, a.zz};
    std::sort(e.begin(), e.end(), std::greater<>());
    return e;
  }
  const double p2 = (a.xx - q) * (a.xx - q) + (a.yy - q) * (a.yy - q) + (a.zz - q) * (a.zz - q) + 2.0 * p1;
  const double p = std::sqrt(p2 / 6.0);
  const SymTensor b = (1.0 / p) * (a - SymTensor::isotropic(q));
  const double r = std::clamp(0.5 * j3(b), -1.0, 1.0);  // det(b)/2 lies in [-1,1] up to round-off
  const double phi = std::acos(r) / 3.0;
  const double e1 = q + 2.0 * p * std::cos(phi);
  const double e3 = q + 2.0 * p * std::cos(phi + 2.0 * std::numbers::pi / 3.0);
  const double e2 = 3.0 * q - e1 - e3;
  return {e1, e2, e3};
}

}  // namespace camouflet
