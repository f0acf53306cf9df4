// P-alpha compaction of the 35 MPa concrete (Wang et al. 2005, eqs. 32-35,
// Table 3): hydrostatic loading through Material::update, checked against the
// closed-form P-alpha law, and elastic unloading.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/verification.hpp"
#include "concrete_fixture.hpp"
#include "point_driver.hpp"

using namespace camouflet;
using camouflet::test::verify;

namespace {

constexpr double rho0 = 2314.0, rho_s = 2750.0, p_e = 23.3e6, p_s = 6.0e9, n_exp = 3.0;
constexpr double a1 = 35.27e9, a2 = 39.58e9, a3 = 9.04e9, b0 = 1.22, b1 = 1.22;

// The published crush law alpha(p), alpha_0 = rho_s / rho_0 (not the code's alpha_e).
double alpha_law(double p) {
  const double alpha0 = rho_s / rho0;
  if (p <= p_e) return alpha0;
  if (p >= p_s) return 1.0;
  return 1.0 + (alpha0 - 1.0) * std::pow((p_s - p) / (p_s - p_e), n_exp);
}

// Density on the compaction curve at pressure p and specific energy e:
// Carroll-Holt p = f(mu, e)/alpha with f the polynomial solid EOS, solved for mu by bisection.
double density_on_crush_curve(double p, double e) {
  const double alpha = alpha_law(p);
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double mu = 0.5 * (lo + hi);
    const double f = a1 * mu + a2 * mu * mu + a3 * mu * mu * mu + (b0 + b1 * mu) * rho_s * e;
    (f > alpha * p ? hi : lo) = mu;
  }
  return rho_s * (1.0 + 0.5 * (lo + hi)) / alpha;
}

}  // namespace

TEST(PAlphaEos, InitialStateIsStressFreeWithPorousSoundSpeed) {
  test::PointDriver d(test::concrete_35mpa());
  EXPECT_NEAR(d.pressure(), 0.0, 1.0);  // Pa
  verify({"P-alpha concrete, reference state: bulk sound speed", "porous_sound_speed (Autodyn CONC-35MPA)",
          2920.0, d.points().sound_speed[0], 0.005, true, "m/s"});
}

TEST(PAlphaEos, HydrostaticCompactionFollowsTheCrushLaw) {
  test::PointDriver d(test::concrete_35mpa());
  const std::vector<double> targets{0.1e9, 1.0e9, 3.0e9, 6.0e9};
  const std::vector<double> quoted_density{2328.0, 2477.0, 2686.0, 2750.0};
  std::size_t next = 0;
  double p_prev = d.pressure(), rho_prev = d.density(), e_prev = d.points().specific_energy[0];
  const double alpha_slot = static_cast<double>(d.points().history.slot("plastic_distension"));
  double alpha_prev = d.points().history.column(static_cast<std::size_t>(alpha_slot))[0];
  while (next < targets.size()) {
    d.strain_step(SymTensor::isotropic(-2e-5), 1e-6);
    const double p = d.pressure(), rho = d.density(), e = d.points().specific_energy[0];
    const double alpha = d.points().history.column(static_cast<std::size_t>(alpha_slot))[0];
    ASSERT_LE(alpha, alpha_prev + 1e-15) << "compaction must be irreversible";
    alpha_prev = alpha;
    while (next < targets.size() && p >= targets[next]) {
      const double w = (targets[next] - p_prev) / (p - p_prev);
      const double rho_at = rho_prev + w * (rho - rho_prev);
      const double e_at = e_prev + w * (e - e_prev);
      const double reference = density_on_crush_curve(targets[next], e_at);
      verify({fmt::format("P-alpha hydrostatic compaction: density at {} GPa", targets[next] / 1e9),
              "closed-form P-alpha law alpha(p) with the polynomial solid EOS (Wang et al. 2005 eqs. 34-35)",
              reference, rho_at, 0.005, true, "kg/m^3"});
      std::printf(
          "p = %.1f GPa: rho = %.1f (closed form %.1f; quoted %.0f = rho_s/alpha(p), "
          "without the matrix compression), e = %.0f J/kg\n",
          targets[next] / 1e9, rho_at, reference, quoted_density[next], e_at);
      ++next;
    }
    p_prev = p;
    rho_prev = rho;
    e_prev = e;
    ASSERT_LT(rho, 4000.0);
  }
}

TEST(PAlphaEos, UnloadingIsElasticAndKeepsTheCompaction) {
  test::PointDriver d(test::concrete_35mpa());
  const std::size_t slot = d.points().history.slot("plastic_distension");
  while (d.pressure() < 1.0e9) d.strain_step(SymTensor::isotropic(-2e-5), 1e-6);
  const double alpha_p = d.points().history.column(slot)[0];
  const double p_top = d.pressure(), rho_top = d.density();
  // Unload in small steps to zero pressure, then reload to the same density.
  int steps = 0;
  while (d.pressure() > 0.0 && steps < 100000) {
    d.strain_step(SymTensor::isotropic(1e-5), 1e-6);
    ++steps;
  }
  EXPECT_DOUBLE_EQ(d.points().history.column(slot)[0], alpha_p) << "unloading must not change alpha_p";
  const double rho_unloaded = d.density();
  verify({"P-alpha unloading from 1 GPa: permanent densification kept", "density above rho_0 after unloading",
          1.0, rho_unloaded > rho0 + 50.0 ? 1.0 : 0.0, 0.0, false, "-"});
  for (int k = 0; k < steps; ++k) d.strain_step(SymTensor::isotropic(-1e-5), 1e-6);
  EXPECT_NEAR(d.density(), rho_top, 1e-9 * rho_top);
  verify({"P-alpha unload-reload cycle from 1 GPa: pressure recovered", "reversible elastic branch", p_top,
          d.pressure(), 0.01, true, "Pa"});
}
