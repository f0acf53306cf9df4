#pragma once
// Symmetric 3x3 tensors (stress, strain rate) and the spin tensor.
//
// Every material point works in 3-D components whatever the model dimension:
// in 2-D the third direction is the out-of-plane one (plane strain) or the hoop
// direction theta (axisymmetric, coordinates r-z mapped to x-y). That keeps one
// material code path for plane strain, axisymmetric and 3-D (style.md #10).
#include <array>
#include <cmath>

namespace camouflet {

// Components in the order xx, yy, zz, xy, yz, zx. Tensile stress positive.
struct SymTensor {
  double xx = 0, yy = 0, zz = 0, xy = 0, yz = 0, zx = 0;

  constexpr double trace() const { return xx + yy + zz; }
  constexpr SymTensor& operator+=(const SymTensor& o) {
    xx += o.xx; yy += o.yy; zz += o.zz; xy += o.xy; yz += o.yz; zx += o.zx;
    return *this;
  }
  constexpr SymTensor& operator-=(const SymTensor& o) {
    xx -= o.xx; yy -= o.yy; zz -= o.zz; xy -= o.xy; yz -= o.yz; zx -= o.zx;
    return *this;
  }
  constexpr SymTensor& operator*=(double s) {
    xx *= s; yy *= s; zz *= s; xy *= s; yz *= s; zx *= s;
    return *this;
  }
  static constexpr SymTensor identity() { return {1, 1, 1, 0, 0, 0}; }
  static constexpr SymTensor isotropic(double v) { return {v, v, v, 0, 0, 0}; }
};

constexpr SymTensor operator+(SymTensor a, const SymTensor& b) { return a += b; }
constexpr SymTensor operator-(SymTensor a, const SymTensor& b) { return a -= b; }
constexpr SymTensor operator*(SymTensor a, double s) { return a *= s; }
constexpr SymTensor operator*(double s, SymTensor a) { return a *= s; }

// Full contraction a:b.
constexpr double contract(const SymTensor& a, const SymTensor& b) {
  return a.xx * b.xx + a.yy * b.yy + a.zz * b.zz + 2.0 * (a.xy * b.xy + a.yz * b.yz + a.zx * b.zx);
}

constexpr SymTensor deviator(const SymTensor& a) {
  const double m = a.trace() / 3.0;
  return {a.xx - m, a.yy - m, a.zz - m, a.xy, a.yz, a.zx};
}

// Second invariant of the deviator, J2 = s:s / 2.
constexpr double j2(const SymTensor& s_dev) { return 0.5 * contract(s_dev, s_dev); }

// Third invariant of the deviator, J3 = det(s).
constexpr double j3(const SymTensor& s) {
  return s.xx * (s.yy * s.zz - s.yz * s.yz) - s.xy * (s.xy * s.zz - s.yz * s.zx) +
         s.zx * (s.xy * s.yz - s.yy * s.zx);
}

// von Mises equivalent stress sqrt(3 J2).
inline double von_mises(const SymTensor& s_dev) { return std::sqrt(3.0 * j2(s_dev)); }

// Principal values (eigenvalues), descending. Closed form for symmetric 3x3.
std::array<double, 3> principal_values(const SymTensor& a);

// Spin W = (L - L^T)/2 stored by its three independent components
// W_xy, W_yz, W_zx (W_yx = -W_xy ...). In 2-D only W_xy is non-zero.
struct Spin {
  double xy = 0, yz = 0, zx = 0;
};

// Jaumann (co-rotational) increment of a symmetric tensor over dt:
// s_dot = W s - s W, as used by the objective stress rate.
// Inline: the material update calls it for every point and cycle (twice in
// the soil), and the call cost more than its 30 flops (docs/performance.md).
inline SymTensor jaumann_increment(const SymTensor& s, const Spin& w, double dt) {
  // W s - s W with W antisymmetric: W = [[0, a, -c], [-a, 0, b], [c, -b, 0]],
  // a = W_xy, b = W_yz, c = W_zx. Only the six independent entries, each the
  // sum over k of W_ik s_kj - s_ik W_kj in the order k = 0, 1, 2 with the
  // terms holding a zero of W dropped: the same roundings as the full 3x3
  // product.
  const double a = w.xy, b = w.yz, c = w.zx;
  const double rxx = (a * s.xy - s.xy * -a) + (-c * s.zx - s.zx * c);
  const double ryy = (-a * s.xy - s.xy * a) + (b * s.yz - s.yz * -b);
  const double rzz = (c * s.zx - s.zx * -c) + (-b * s.yz - s.yz * b);
  const double rxy = (a * s.yy - s.xx * a) + (-c * s.yz - s.zx * -b);
  const double ryz = ((-a * s.zx - s.xy * -c) - s.yy * b) + b * s.zz;
  const double rzx = (c * s.xx + (-b * s.xy - s.yz * -a)) - s.zz * c;
  return {dt * rxx, dt * ryy, dt * rzz, dt * rxy, dt * ryz, dt * rzx};
}

}  // namespace camouflet
