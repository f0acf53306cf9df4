// RHT concrete strength (Wang et al. 2005, eqs. 24-31; Riedel 2000) driven at
// one material point through Material::update: triaxial meridians, uniaxial
// compression and tension with softening, strain-rate enhancement.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "concrete_paths.hpp"
#include "materials/material_driver.hpp"

using namespace camouflet;
using camouflet::test::verify;

namespace {
const test::ConcreteReference ref;
constexpr double quasi_static = 1e-6;  // 1/s: below both reference rates, F_rate = 1
}  // namespace

TEST(RhtStrength, TriaxialCompressionPeaksOnTheCompressiveMeridian) {
  for (const double confinement : {5e6, 20e6, 50e6, 100e6}) {
    const test::PathResult r = test::run_axial_path(confinement, -quasi_static, -0.01, 1000);
    verify({fmt::format("RHT triaxial compression, confinement {} MPa: peak sqrt(3 J2)", confinement / 1e6),
            "compressive meridian Y_TXC(p) = f_c A (p* + f_t*)^N at the peak pressure (eq. 24)",
            ref.txc(r.pressure_at_peak), r.peak_q, 0.02, true, "Pa"});
  }
}

TEST(RhtStrength, TriaxialExtensionPeakMatchesTheTensileMeridianRatio) {
  // Confinement chosen so that the peak falls at p* close to 1/3.
  const test::PathResult r = test::run_axial_path(19.3e6, quasi_static, 0.004, 800);
  const double p_star = r.pressure_at_peak / ref.fc;
  std::printf("triaxial extension peak at p* = %.4f\n", p_star);
  EXPECT_NEAR(p_star, 1.0 / 3.0, 0.03);
  verify({"RHT triaxial extension at p* ~ 1/3: tensile/compressive meridian ratio",
          "Willam-Warnke R3(theta = 0) = Q2 = Q2,0 + BQ p*", ref.q20 + ref.bq * p_star,
          r.peak_q / ref.txc(r.pressure_at_peak), 0.02, true, "-"});
}

TEST(RhtStrength, UniaxialCompressionPeakAndSoftening) {
  const test::PathResult r = test::run_axial_path(0.0, -quasi_static, -0.03, 3000);
  const double expected = ref.uniaxial_compression();
  std::printf(
      "uniaxial compression: peak %.3f MPa (%.4f f_c; closed form %.4f f_c; Y_TXC(p* = 1/3) = %.4f f_c)\n",
      -r.axial_at_peak / 1e6, -r.axial_at_peak / ref.fc, expected / ref.fc, ref.txc(ref.fc / 3.0) / ref.fc);
  verify({"RHT uniaxial compression: peak stress",
          "sigma = Y_TXC(sigma/3) on the compressive meridian (eq. 24)", expected, -r.axial_at_peak, 0.02,
          true, "Pa"});
  // Fully damaged: the residual surface B p*^M (eq. 27) under uniaxial stress,
  // sigma* = (B 3^-M)^(1/(1-M)).
  EXPECT_GE(r.final_damage, 1.0);
  const double residual = ref.fc * std::pow(ref.b * std::pow(3.0, -ref.m), 1.0 / (1.0 - ref.m));
  verify({"RHT uniaxial compression: stress after full damage",
          "residual surface f_c B (p*)^M at sigma = 3p (eq. 27)", residual, -r.final_axial, 0.02, true,
          "Pa"});
}

TEST(RhtStrength, UniaxialTensionPeakAndSoftening) {
  const test::PathResult r = test::run_axial_path(0.0, quasi_static, 0.015, 1500, 1e-4);
  verify({"RHT uniaxial tension: peak stress", "f_t = 3.5 MPa (Wang et al. 2005, Table 3), +-25 %", ref.ft,
          r.axial_at_peak, 0.25, true, "Pa"});
  EXPECT_GE(r.final_damage, 1.0);
  verify({"RHT uniaxial tension: stress after full damage",
          "no residual strength in tension (eq. 27 for p* <= 0)", 0.0, r.final_axial / ref.ft, 0.02, false,
          "f_t"});
}

TEST(RhtStrength, RateEnhancementFollowsTheRateFactors) {
  for (const double rate : {1.0, 100.0}) {
    const test::PathResult c = test::run_axial_path(0.0, -rate, -0.005, 500);
    const double f_c = std::pow(c.rate_at_peak / 3e-5, 0.032);
    verify({fmt::format("RHT uniaxial compression at {} /s: peak stress", rate),
            "F_c(rate) x static strength, F_c = (rate / 3e-5)^0.032", f_c * ref.uniaxial_compression(),
            -c.axial_at_peak, 0.02, true, "Pa"});
    const test::PathResult t = test::run_axial_path(0.0, rate, 0.003, 600);
    const double f_t = std::pow(t.rate_at_peak / 3e-6, 0.036);
    verify({fmt::format("RHT uniaxial tension at {} /s: peak stress", rate),
            "F_t(rate) x f_t, F_t = (rate / 3e-6)^0.036", f_t * ref.ft, t.axial_at_peak, 0.02, true, "Pa"});
    std::printf("rate %g /s: F_c = %.4f (equivalent rate %.3g), F_t = %.4f (equivalent rate %.3g)\n", rate,
                f_c, c.rate_at_peak, f_t, t.rate_at_peak);
  }
}

TEST(RhtStrength, ElasticLimitIsCappedBetweenCrushAndCompaction) {
  // Triaxial compression at 3 GPa confinement, between p_e = 23.3 MPa and
  // p_s = 6 GPa: plastic flow starts at Y_el = 0.53 F_CAP(p) Y_TXC(p) (eq. 25),
  // F_CAP = sqrt(1 - ((p - p_e)/(p_s - p_e))^2).
  DriverSpec spec;
  spec.path = LoadPath::triaxial;
  spec.strain_rate = -quasi_static;
  spec.final_strain = -0.03;
  spec.confining_pressure = 3e9;
  spec.steps = 3000;
  const std::vector<DriverRow> rows = drive_material(*test::concrete_35mpa(), spec);
  std::size_t first_plastic = 0;
  for (std::size_t k = 1; k < rows.size() && first_plastic == 0; ++k)
    if (rows[k].plastic_strain > 0.0 && rows[k - 1].plastic_strain == 0.0 && rows[k].axial_strain != 0.0)
      first_plastic = k;
  ASSERT_GT(first_plastic, 0u);
  // The elastic limit lies between the last elastic and the first plastic row.
  const DriverRow& elastic = rows[first_plastic - 1];
  const double p = elastic.pressure;
  const double x = (p - 23.3e6) / (6e9 - 23.3e6);
  const double expected = 0.53 * std::sqrt(1.0 - x * x) * ref.txc(p);
  std::printf("elastic limit at p = %.3f GPa: F_CAP = %.4f, sqrt(3 J2) = %.1f MPa (last elastic row)\n",
              p / 1e9, std::sqrt(1.0 - x * x), std::sqrt(3.0) * elastic.sqrt_j2 / 1e6);
  verify({"RHT elastic limit at 3 GPa confinement (cap active)", "0.53 F_CAP(p) Y_TXC(p) (eq. 25)", expected,
          std::sqrt(3.0) * elastic.sqrt_j2, 0.02, true, "Pa"});
}
