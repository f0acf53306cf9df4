#include "sph/artificial_stress.hpp"

#include <cmath>

#include "sph/symmetric_eigen.hpp"

namespace camouflet::sph {

bool no_tension(const SymTensor& s) {
  // No tensile principal stress when every Gershgorin disc lies in sigma <= 0
  // (a compressed particle): R = 0 without the eigen-decomposition.
  if (s.xx + std::abs(s.xy) + std::abs(s.zx) <= 0.0 && s.yy + std::abs(s.xy) + std::abs(s.yz) <= 0.0 &&
      s.zz + std::abs(s.zx) + std::abs(s.yz) <= 0.0)
    return true;
  // Nor when sigma is negative definite (Sylvester's criterion on -sigma: the
  // leading principal minors of sigma alternate in sign, - + -), which the
  // discs miss under shear. Only an eigenvalue within round-off of zero can
  // be judged otherwise than by the eigen-decomposition (R ~ 1e-16 |sigma| then).
  const double minor2 = s.xx * s.yy - s.xy * s.xy;
  const double det = s.xx * (s.yy * s.zz - s.yz * s.yz) - s.xy * (s.xy * s.zz - s.yz * s.zx) +
                     s.zx * (s.xy * s.yz - s.yy * s.zx);
  return s.xx < 0.0 && minor2 > 0.0 && det < 0.0;
}

SymTensor rotate_tensile_part(const double values[3], const double q[3][3], double epsilon, double scale) {
  double r_principal[3];
  bool any = false;
  for (int k = 0; k < 3; ++k) {
    r_principal[k] = values[k] > 0.0 ? -epsilon * values[k] * scale : 0.0;
    any = any || r_principal[k] != 0.0;
  }
  if (!any) return {};
  auto component = [&](int i, int j) {
    double v = 0.0;
    for (int k = 0; k < 3; ++k) v += q[i][k] * r_principal[k] * q[j][k];
    return v;
  };
  return {component(0, 0), component(1, 1), component(2, 2),
          component(0, 1), component(1, 2), component(2, 0)};
}

void symmetric_eigen(const SymTensor& s, double values[3], double vectors[3][3]) {
  const double components[6] = {s.xx, s.yy, s.zz, s.xy, s.yz, s.zx};
  symmetric_eigen_of(components, true, values, vectors);
}

template <>
SymTensor artificial_stress<2>(const SymTensor& s, double epsilon, double scale) {
  // In-plane principal stresses of [[xx, xy], [xy, yy]].
  const double mean = 0.5 * (s.xx + s.yy);
  const double half_diff = 0.5 * (s.xx - s.yy);
  const double radius = std::sqrt(half_diff * half_diff + s.xy * s.xy);
  const double s1 = mean + radius, s2 = mean - radius;
  const double r1 = s1 > 0.0 ? -epsilon * s1 * scale : 0.0;
  const double r2 = s2 > 0.0 ? -epsilon * s2 * scale : 0.0;
  if (r1 == 0.0 && r2 == 0.0) return {};
  const double angle = 0.5 * std::atan2(s.xy, half_diff);  // direction of s1
  const double c = std::cos(angle), sn = std::sin(angle);
  SymTensor r;
  r.xx = r1 * c * c + r2 * sn * sn;
  r.yy = r1 * sn * sn + r2 * c * c;
  r.xy = (r1 - r2) * c * sn;
  return r;
}

template <>
SymTensor artificial_stress<3>(const SymTensor& s, double epsilon, double scale) {
  if (no_tension(s)) return {};
  double values[3], q[3][3];
  symmetric_eigen(s, values, q);
  return rotate_tensile_part(values, q, epsilon, scale);
}

}  // namespace camouflet::sph
