// Kernel normalisation and gradient consistency (unit tests).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "common/verification.hpp"
#include "sph/artificial_stress.hpp"
#include "sph/kernel.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

// Integral of W over the plane (D = 2) or space (D = 3) by the midpoint rule in r.
template <int D>
double kernel_integral(KernelKind kind, double h) {
  Kernel<D> w{kind};
  const int n = 20000;
  const double dr = 2.0 * h / n;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) * dr;
    const double shell = D == 2 ? 2.0 * std::numbers::pi * r : 4.0 * std::numbers::pi * r * r;
    sum += w.value(r, h) * shell * dr;
  }
  return sum;
}

}  // namespace

TEST(SphKernel, IntegratesToOne) {
  for (auto kind : {KernelKind::cubic_spline, KernelKind::wendland_c2}) {
    const std::string name = to_string(kind);
    test::verify({"SPH kernel " + name + " 2-D: integral of W", "1 (normalisation)", 1.0,
                  kernel_integral<2>(kind, 0.37), 1e-6, true, "-"});
    test::verify({"SPH kernel " + name + " 3-D: integral of W", "1 (normalisation)", 1.0,
                  kernel_integral<3>(kind, 0.37), 1e-6, true, "-"});
  }
}

TEST(SphKernel, DerivativeMatchesFiniteDifference) {
  for (auto kind : {KernelKind::cubic_spline, KernelKind::wendland_c2}) {
    Kernel<3> w{kind};
    const double h = 0.5;
    for (double q = 0.05; q < 2.0; q += 0.1) {
      const double r = q * h, e = 1e-6 * h;
      const double fd = (w.value(r + e, h) - w.value(r - e, h)) / (2.0 * e);
      EXPECT_NEAR(w.derivative(r, h), fd, 1e-6 * std::abs(w.normalisation(h) / h))
          << to_string(kind) << " q=" << q;
      EXPECT_NEAR(w.gradient_factor(r, h) * r, w.derivative(r, h), 1e-9 * std::abs(w.normalisation(h) / h));
    }
    EXPECT_EQ(w.value(2.0 * h, h), 0.0);
    EXPECT_EQ(w.derivative(2.0 * h, h), 0.0);
  }
}

TEST(SphKernel, PairTermsMatchTheSeparateEvaluations) {
  // The fused evaluation of the pair loops (gradient factor and shape from one
  // q) must be the same function as gradient_factor() and value() / normalisation.
  for (auto kind : {KernelKind::cubic_spline, KernelKind::wendland_c2}) {
    Kernel<2> w2{kind};
    Kernel<3> w3{kind};
    const double h = 0.37;
    for (double q = 0.03; q < 2.0; q += 0.07) {
      const double r = q * h;
      const auto t2 = w2.pair_terms(r, 1.0 / h);
      const auto t3 = w3.pair_terms(r, 1.0 / h);
      EXPECT_NEAR(t2.gradient_factor, w2.gradient_factor(r, h), 1e-13 * std::abs(w2.gradient_factor(r, h)));
      EXPECT_NEAR(t3.gradient_factor, w3.gradient_factor(r, h), 1e-13 * std::abs(w3.gradient_factor(r, h)));
      EXPECT_NEAR(t3.shape, w3.value(r, h) / w3.normalisation(h), 1e-13) << to_string(kind) << " q=" << q;
      EXPECT_NEAR(t2.shape, w2.value(r, h) / w2.normalisation(h), 1e-13) << to_string(kind) << " q=" << q;
      EXPECT_NEAR(t3.shape, w3.shape(r / h), 1e-13);
    }
  }
}

TEST(SphKernel, LatticeSumsAreConsistent) {
  // On a square lattice of spacing dx with h = 1.2 dx: sum (m/rho) W = 1 (partition of unity)
  // and sum (m/rho) (x_j - x_i) (x) grad_i W = -I... here written as the moment that the
  // kernel-gradient correction inverts, which should be the identity for a full support.
  for (auto kind : {KernelKind::cubic_spline, KernelKind::wendland_c2}) {
    Kernel<2> w{kind};
    // Wendland C2 needs a wider support for the same lattice accuracy (Dehnen & Aly 2012, section 4).
    const double h_factor = kind == KernelKind::cubic_spline ? 1.2 : 1.5;
    const double dx = 0.01, h = h_factor * dx, vol = dx * dx;
    double shepard = 0.0, mxx = 0.0, mxy = 0.0;
    for (int i = -5; i <= 5; ++i)
      for (int j = -5; j <= 5; ++j) {
        const double x = i * dx, y = j * dx, r = std::hypot(x, y);
        shepard += vol * w.value(r, h);
        // x_i = 0, x_j = (x, y): grad_i W_ij = F (x_i - x_j) = -F (x, y)
        const double f = w.gradient_factor(r, h);
        mxx += vol * x * (-f * x);
        mxy += vol * x * (-f * y);
      }
    const std::string name = to_string(kind);
    test::verify({"SPH kernel " + name + ": lattice Shepard sum, h = " + std::to_string(h_factor) + " dx",
                  "1 (partition of unity)", 1.0, shepard, 0.02, true, "-"});
    test::verify(
        {"SPH kernel " + name + ": lattice gradient moment xx, h = " + std::to_string(h_factor) + " dx",
         "1 (linear consistency)", 1.0, mxx, 0.02, true, "-"});
    EXPECT_NEAR(mxy, 0.0, 1e-12);
  }
}

TEST(SphArtificialStress, OnlyTensilePrincipalStressesAndFrameIndependent) {
  // Uniaxial tension sigma_1 = 2 rotated by 30 degrees in the plane, compression sigma_2 = -1.
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const double s1 = 2.0, s2 = -1.0;
  SymTensor sigma{s1 * c * c + s2 * s * s, s1 * s * s + s2 * c * c, -0.5, (s1 - s2) * c * s, 0, 0};
  const SymTensor r2 = artificial_stress<2>(sigma, 0.3, 1.0);
  // Expected: R = -0.3 * 2 * n n^T with n = (c, s).
  EXPECT_NEAR(r2.xx, -0.6 * c * c, 1e-12);
  EXPECT_NEAR(r2.yy, -0.6 * s * s, 1e-12);
  EXPECT_NEAR(r2.xy, -0.6 * c * s, 1e-12);
  // The 3-D version agrees on the in-plane block (the out-of-plane -0.5 is compressive).
  const SymTensor r3 = artificial_stress<3>(sigma, 0.3, 1.0);
  EXPECT_NEAR(r3.xx, r2.xx, 1e-10);
  EXPECT_NEAR(r3.yy, r2.yy, 1e-10);
  EXPECT_NEAR(r3.xy, r2.xy, 1e-10);
  EXPECT_NEAR(r3.zz, 0.0, 1e-10);
  // Pure compression: no artificial stress.
  const SymTensor r0 = artificial_stress<3>(SymTensor::isotropic(-5.0), 0.3, 1.0);
  EXPECT_EQ(r0.xx, 0.0);
}

TEST(SphArtificialStress, BatchedEigenSolvesGiveTheScalarBits) {
  // artificial_stress_3d runs the Jacobi solves on SIMD lanes: every result must
  // equal artificial_stress<3> bit for bit (tensile, compressed, sheared, tiny,
  // isotropic and diagonal tensors, and a count that leaves a partial group).
  std::vector<SymTensor> sigma;
  std::vector<double> scale;
  std::uint64_t state = 12345;
  auto uniform = [&] {  // splitmix64 -> [-1, 1)
    state += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
  };
  for (int k = 0; k < 203; ++k) {
    const double magnitude = std::pow(10.0, 12.0 * uniform() - 4.0);  // 1e-16 .. 1e8 Pa
    SymTensor s{uniform(), uniform(), uniform(), uniform(), uniform(), uniform()};
    if (k % 5 == 1) s.xy = s.yz = s.zx = 0.0;             // already diagonal
    if (k % 5 == 2) s = SymTensor::isotropic(uniform());  // isotropic
    if (k % 5 == 3) s.xx = s.yy = s.zz = -2.0;            // compressed with shear
    sigma.push_back(s * magnitude);
    scale.push_back(1.0 / (8960.0 * 8960.0) * (1.0 + uniform()));
  }
  std::vector<SymTensor> batched(sigma.size());
  artificial_stress_3d(sigma, scale, 0.3, batched);
  int tensile = 0;
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    const SymTensor expected = artificial_stress<3>(sigma[k], 0.3, scale[k]);
    tensile += expected.xx != 0.0 || expected.yy != 0.0 || expected.zz != 0.0;
    EXPECT_EQ(batched[k].xx, expected.xx) << k;
    EXPECT_EQ(batched[k].yy, expected.yy) << k;
    EXPECT_EQ(batched[k].zz, expected.zz) << k;
    EXPECT_EQ(batched[k].xy, expected.xy) << k;
    EXPECT_EQ(batched[k].yz, expected.yz) << k;
    EXPECT_EQ(batched[k].zx, expected.zx) << k;
  }
  EXPECT_GT(tensile, 50);  // the solve really ran on many lanes
}
