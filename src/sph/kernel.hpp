#pragma once
// SPH smoothing kernels W(r, h) with compact support 2h, in 2-D and 3-D.
//
// * cubic B-spline (default): Monaghan & Lattanzio 1985; Monaghan 1992,
//   Annu. Rev. Astron. Astrophys. 30, eq. (2.6). With q = r/h:
//     W = sigma [1 - 3/2 q^2 + 3/4 q^3]   0 <= q < 1
//       = sigma 1/4 (2 - q)^3            1 <= q < 2
//   sigma = 10 / (7 pi h^2) in 2-D, 1 / (pi h^3) in 3-D.
// * Wendland C2 (Wendland 1995; Dehnen & Aly 2012, Table 1), support 2h:
//     W = sigma (1 - q/2)^4 (2 q + 1)     0 <= q < 2
//   sigma = 7 / (4 pi h^2) in 2-D, 21 / (16 pi h^3) in 3-D.
//
// Both are evaluated inline: they sit in the innermost loop of every SPH sum.
#include <cmath>
#include <numbers>
#include <string>

#include "model/sph_options.hpp"

namespace camouflet::sph {

// "cubic_spline" / "wendland_c2"; throws std::invalid_argument for anything else
// (the case reader turns that into an InputError naming the key).
KernelKind kernel_from_name(const std::string& name);
const char* to_string(KernelKind kind);

// Support radius in units of h: W(r, h) = 0 for r >= support_factor * h.
inline constexpr double support_factor = 2.0;

template <int D>
struct Kernel {
  KernelKind kind = KernelKind::cubic_spline;

  double normalisation(double h) const {
    const double pi = std::numbers::pi;
    if (kind == KernelKind::cubic_spline) return D == 2 ? 10.0 / (7.0 * pi * h * h) : 1.0 / (pi * h * h * h);
    return D == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
  }

  // W(r, h), 1/m^D.
  double value(double r, double h) const {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double s = normalisation(h);
    if (kind == KernelKind::cubic_spline) {
      if (q < 1.0) return s * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
      const double t = 2.0 - q;
      return s * 0.25 * t * t * t;
    }
    const double t = 1.0 - 0.5 * q;
    return s * t * t * t * t * (2.0 * q + 1.0);
  }

  // dW/dr (1/m^(D+1)); the gradient is grad_i W_ij = dW/dr * (x_i - x_j) / r.
  double derivative(double r, double h) const {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double s = normalisation(h) / h;
    if (kind == KernelKind::cubic_spline) {
      if (q < 1.0) return s * (-3.0 * q + 2.25 * q * q);
      const double t = 2.0 - q;
      return -s * 0.75 * t * t;
    }
    // d/dq [(1 - q/2)^4 (2q + 1)] = -5 q (1 - q/2)^3
    const double t = 1.0 - 0.5 * q;
    return -s * 5.0 * q * t * t * t;
  }

  // dW/dr / r, finite at r = 0: the factor that multiplies (x_i - x_j) in the gradient.
  double gradient_factor(double r, double h) const {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double s = normalisation(h) / (h * h);
    if (kind == KernelKind::cubic_spline) {
      if (q < 1.0) return s * (-3.0 + 2.25 * q);
      const double t = 2.0 - q;
      return -s * 0.75 * t * t / q;
    }
    const double t = 1.0 - 0.5 * q;
    return -s * 5.0 * t * t * t;
  }

  // Shape w(q) = W(r, h) h^D / C (C: the constant of normalisation(h)): the
  // ratio W(r, h) / W(r', h) of two distances at one h is w(q) / w(q').
  double shape(double q) const {
    if (q >= 2.0) return 0.0;
    if (kind == KernelKind::cubic_spline) {
      if (q < 1.0) return 1.0 - 1.5 * q * q + 0.75 * q * q * q;
      const double t = 2.0 - q;
      return 0.25 * t * t * t;
    }
    const double t = 1.0 - 0.5 * q;
    return t * t * t * t * (2.0 * q + 1.0);
  }

  // What the pair sums need of one pair inside the support (r < 2h), from one
  // evaluation: gradient_factor(r, h) and shape(r / h). Written for the inner
  // loop: 1/h is given, one division (the outer cubic shell's 1/q) and no
  // data-dependent branch (both cubic pieces are evaluated and one selected).
  // T is double, or a GCC vector of doubles (one pair per lane, pair_lanes.hpp):
  // the same operations in the same order, so a lane gives the scalar's bits.
  template <class T>
  struct PairTermsOf {
    T gradient_factor;  // (dW/dr)/r, 1/m^(D+2)
    T shape;            // w(q), dimensionless
  };
  using PairTerms = PairTermsOf<double>;
  template <class T>
  PairTermsOf<T> pair_terms(T r, T inv_h) const {
    const T q = r * inv_h;
    const T ih2 = inv_h * inv_h;
    const T s = unit_normalisation() * (D == 2 ? ih2 * ih2 : ih2 * ih2 * inv_h);  // C / h^(D+2)
    if (kind == KernelKind::cubic_spline) {
      const T t = 2.0 - q;
      const auto inner = q < 1.0;
      const T g_inner = -3.0 + 2.25 * q;
      const T g_outer = -0.75 * t * t / q;
      const T w_inner = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
      const T w_outer = 0.25 * t * t * t;
      return {s * (inner ? g_inner : g_outer), inner ? w_inner : w_outer};
    }
    const T t = 1.0 - 0.5 * q;
    const T t3 = t * t * t;
    return {-s * 5.0 * t3, t3 * t * (2.0 * q + 1.0)};
  }

  // C of normalisation(h) = C / h^D.
  double unit_normalisation() const {
    const double pi = std::numbers::pi;
    if (kind == KernelKind::cubic_spline) return D == 2 ? 10.0 / (7.0 * pi) : 1.0 / pi;
    return D == 2 ? 7.0 / (4.0 * pi) : 21.0 / (16.0 * pi);
  }
};

// Symmetric pair smoothing length, so that the pair force is antisymmetric and
// graded particles conserve momentum (Monaghan 1992, section 6: h_ij = (h_i + h_j)/2).
inline double pair_smoothing_length(double h_i, double h_j) {
  return 0.5 * (h_i + h_j);
}

}  // namespace camouflet::sph
