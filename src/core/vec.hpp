#pragma once
// Small fixed-size vectors for node and particle positions, velocities and forces.
// Dimension D is a compile-time parameter (2 or 3); see docs/architecture.md.
#include <array>
#include <cmath>
#include <cstddef>

namespace camouflet {

template <int D>
struct Vec {
  std::array<double, D> c{};

  static constexpr int dimension = D;
  constexpr double& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  constexpr double operator[](int i) const { return c[static_cast<std::size_t>(i)]; }

  constexpr Vec& operator+=(const Vec& o) {
    for (int i = 0; i < D; ++i) (*this)[i] += o[i];
    return *this;
  }
  constexpr Vec& operator-=(const Vec& o) {
    for (int i = 0; i < D; ++i) (*this)[i] -= o[i];
    return *this;
  }
  constexpr Vec& operator*=(double s) {
    for (int i = 0; i < D; ++i) (*this)[i] *= s;
    return *this;
  }
};

template <int D>
constexpr Vec<D> operator+(Vec<D> a, const Vec<D>& b) { return a += b; }
template <int D>
constexpr Vec<D> operator-(Vec<D> a, const Vec<D>& b) { return a -= b; }
template <int D>
constexpr Vec<D> operator*(Vec<D> a, double s) { return a *= s; }
template <int D>
constexpr Vec<D> operator*(double s, Vec<D> a) { return a *= s; }

template <int D>
constexpr double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}
template <int D>
inline double norm(const Vec<D>& a) { return std::sqrt(dot(a, a)); }

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

}  // namespace camouflet
