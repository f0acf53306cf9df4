// Soil Drucker-Prager strength with strain-rate factor (eqs. 20-23) and bond
// damage (eqs. 17-19) driven through Material::update.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "materials/material_driver.hpp"
#include "soil_test_support.hpp"

namespace camouflet::test {
namespace {

// Hydrostatic compression to the confining pressure, then constant-volume
// triaxial compression: deviatoric strain rate e_dot diag(-1, 1/2, 1/2), for
// which eps_dot_eff = e_dot (eq. 22). The pressure stays at the confinement.
TEST(SoilDruckerPrager, TriaxialPeakLiesOnTheRateDependentSurface) {
  const HandSoil h;
  const double alpha = 0.25, k = 0.2e6, beta = 0.1, rate0 = 0.01 / 60.0;
  for (double confinement : {0.5e6, 2e6, 10e6}) {
    for (double rate : {1.0, 100.0}) {
      PointDriver point(soil_material(soil_eos_block(), soil_strength_block(), Parameters{}));
      double p_abs = 0.0;
      const double v = h.loading(h.pore_pressure_at(confinement + h.p0), 0.0, p_abs);
      const int steps = 100;
      const double t_load = 1e-3;
      for (int s = 0; s < steps; ++s)
        point.step(SymTensor::isotropic(std::log(v) / (3.0 * t_load)), t_load / steps);
      const double p = point.pts.pressure[0];
      EXPECT_NEAR(p, confinement, 1e-6 * confinement);
      // Shear to 30 % axial strain: far past the elastic limit at either rate.
      const double dt = 0.3 / rate / 600.0;
      double peak = 0.0;
      for (int s = 0; s < 600; ++s) {
        point.step(SymTensor{-rate, 0.5 * rate, 0.5 * rate, 0, 0, 0}, dt);
        peak = std::max(peak, std::sqrt(j2(point.pts.deviator[0])));
      }
      EXPECT_NEAR(point.pts.pressure[0], p, 1e-9 * p);  // no dilatancy, constant volume
      const double expected = (alpha * 3.0 * p + k) * (1.0 + beta * std::log(rate / rate0));
      verify({fmt::format("Soil Drucker-Prager triaxial, p = {:.1f} MPa, strain rate {:g}/s: peak sqrt(J2)",
                          confinement / 1e6, rate),
              "(alpha I1 + k)(1 + beta ln(eps_dot/eps_dot0)) (eq. 21)", expected, peak, 0.01, true, "Pa"});
      EXPECT_GT(point.pts.plastic_strain[0], 0.0);
    }
  }
}

// True triaxial compression with the material-point driver: hydrostatic to
// the confining pressure, then axial compression with the lateral stress held.
// With alpha = 0.25 the triaxial stress path (slope sqrt 3 in p-sqrt(J2))
// meets the surface only while 3 alpha R < sqrt 3, i.e. for strain rates
// below 81 /s, and needs very large strains close to it: the two rates are
// chosen well inside that range.
TEST(SoilDruckerPrager, DrivenTriaxialPeakLiesOnTheSurface) {
  const double alpha = 0.25, k = 0.2e6, beta = 0.1, rate0 = 0.01 / 60.0;
  const auto material = soil_material(soil_eos_block(), soil_strength_block(), Parameters{});
  single_point_threads();
  for (double confinement : {0.2e6, 1e6, 5e6}) {
    for (double rate : {1e-3, 0.1}) {
      DriverSpec spec;
      spec.path = LoadPath::triaxial;
      spec.strain_rate = -rate;
      spec.final_strain = -0.5;
      spec.confining_pressure = confinement;
      spec.steps = 300;
      const auto rows = drive_material(*material, spec);
      std::size_t peak = 1;
      for (std::size_t r = 1; r < rows.size(); ++r)
        if (rows[r].sqrt_j2 > rows[peak].sqrt_j2) peak = r;
      // Effective strain rate of that step from the axial and volumetric increments:
      // D = diag(a, d, d) gives eps_dot_eff = 2/3 |a - d| (eq. 22).
      const DriverRow& now = rows[peak];
      const DriverRow& before = rows[peak - 1];
      const double dt = now.time - before.time;
      const double d_axial = now.axial_strain - before.axial_strain;
      const double d_vol = now.volumetric_strain - before.volumetric_strain;
      const double effective_rate = std::abs(3.0 * d_axial - d_vol) / (3.0 * dt);
      const double expected =
          (alpha * 3.0 * now.pressure + k) * std::max(1.0, 1.0 + beta * std::log(effective_rate / rate0));
      verify(
          {fmt::format("Soil triaxial compression (driver), confinement {:.1f} MPa, axial rate {:g}/s: peak "
                       "sqrt(J2)",
                       confinement / 1e6, rate),
           "(alpha I1 + k)(1 + beta ln(eps_dot_eff/eps_dot0)) (eq. 21)", expected, now.sqrt_j2, 0.01, true,
           "Pa"});
      EXPECT_GT(rows.back().plastic_strain, 0.0) << "the path must reach the yield surface";
      EXPECT_NEAR(0.5 * (rows.back().stress.yy + rows.back().stress.zz), -confinement, 1e-6 * confinement);
    }
  }
}

// Quasi-static (below the reference rate) the rate factor is 1, never below.
TEST(SoilDruckerPrager, RateFactorNeverBelowOne) {
  const auto s = make_soil_drucker_prager(*std::make_unique<Parameters>(soil_strength_block()));
  verify({"Soil Drucker-Prager: yield limit at a rate below the reference", "alpha I1 + k (rate factor 1)",
          0.25 * 3.0 * 1e6 + 0.2e6, s->yield_limit(1e6, 1e-6, 0.0), 1e-14, true, "Pa"});
  EXPECT_EQ(s->yield_limit(-1e6, 10.0, 0.0), 0.0);  // beyond the apex: no shear strength
}

// Beyond the tension cut-off the deviator vanishes.
TEST(SoilDruckerPrager, DeviatorVanishesInTension) {
  PointDriver point(soil_material(soil_eos_block(), soil_strength_block(), Parameters{}));
  for (int s = 0; s < 50; ++s)
    point.step(SymTensor{0.02, 0.01, -0.005, 0.004, 0, 0}, 1.0);  // expansion + shear
  EXPECT_NEAR(point.pts.pressure[0], -0.2e6 / 0.75, 1e-6);
  verify({"Soil at the tension cut-off: deviator", "zero beyond the Drucker-Prager apex", 0.0,
          std::sqrt(j2(point.pts.deviator[0])), 1e-6, false, "Pa"});
}

// Eq. 18 along a combined shear / extension path, with eps_eff from the
// principal values of the accumulated strain (eq. 19).
TEST(SoilBondDamage, FollowsEquation18) {
  for (double g : {1.0, 2.0}) {
    Parameters damage = soil_damage_block();
    damage.set_number("exponent", g);
    PointDriver point(soil_material(soil_eos_block(), Parameters{}, damage));
    const SymTensor rate{-0.3, 0.1, 0.05, 0.4, 0.0, 0.1};  // 1/s
    const double dt = 1e-3;
    SymTensor strain{};
    double worst = 0.0, last_eff = 0.0;
    for (int s = 0; s < 600; ++s) {
      point.step(rate, dt);
      strain += rate * dt;
      const auto e = principal_values(strain);
      const double eff = std::sqrt(2.0) / 3.0 *
                         std::sqrt((e[0] - e[1]) * (e[0] - e[1]) + (e[1] - e[2]) * (e[1] - e[2]) +
                                   (e[2] - e[0]) * (e[2] - e[0]));
      const double expected = 1.0 - std::exp(-std::pow(5.0 * eff, g) / g);
      worst = std::max(worst, std::abs(point.pts.damage[0] - expected));
      last_eff = eff;
    }
    verify({fmt::format("Soil bond damage, g = {:g}: D vs eq. 18 up to eps_eff = {:.2f}", g, last_eff),
            "D = 1 - exp(-(b eps_eff)^g / g), principal strains", 0.0, worst, 1e-6, false, ""});
  }
}

// The bond pressure in the EOS is E0 (1 - D) Delta V_p / V_p (eq. 17).
TEST(SoilBondDamage, ReducesTheBondPressureAsEquation17) {
  const auto eos = soil_eos();
  const HandSoil h;
  Material m("soil", eos);
  for (double d : {0.0, 0.3, 0.9}) {
    MaterialPoints pts;
    m.setup(pts, 1);
    pts.damage[0] = d;
    pts.density[0] = 1.03 * eos->reference_density();
    eos->evaluate(pts, MaterialContext{}, true);
    const double vp = pts.history.column(pts.history.slot("soil_pore_volume"))[0];
    const double pb = pts.history.column(pts.history.slot("soil_pore_pressure"))[0];
    const double dvp = (h.aw + h.ag) - vp;
    const double bond = pts.pressure[0] - pb - h.fKp * dvp;  // p = p_b + p_a + p_c (eq. 12)
    verify({fmt::format("Soil bond pressure with damage D = {:.1f}", d), "E0 (1 - D) dV_p / V_p (eq. 17)",
            h.E0 * (1.0 - d) * dvp / vp, bond, 1e-6, true, "Pa"});
  }
}

}  // namespace
}  // namespace camouflet::test
