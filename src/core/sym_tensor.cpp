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

SymTensor jaumann_increment(const SymTensor& s, const Spin& w, double dt) {
  // Full 3x3 products W s - s W with W antisymmetric: W = [[0, wxy, -wzx], [-wxy, 0, wyz], [wzx, -wyz, 0]].
  const double W[3][3] = {{0.0, w.xy, -w.zx}, {-w.xy, 0.0, w.yz}, {w.zx, -w.yz, 0.0}};
  const double S[3][3] = {{s.xx, s.xy, s.zx}, {s.xy, s.yy, s.yz}, {s.zx, s.yz, s.zz}};
  double R[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double v = 0.0;
      for (int k = 0; k < 3; ++k) v += W[i][k] * S[k][j] - S[i][k] * W[k][j];
      R[i][j] = v;
    }
  return {dt * R[0][0], dt * R[1][1], dt * R[2][2], dt * R[0][1], dt * R[1][2], dt * R[2][0]};
}

}  // namespace camouflet
