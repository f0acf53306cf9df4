// TM 5-855-1 free-field ground shock: the SI conversion of the manual's
// imperial equations, and how its general form reproduces (or not) the
// coefficients printed in Wang et al. 2005 (docs/theory/tm5-855-1.md).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "common/verification.hpp"
#include "core/error.hpp"
#include "empirical/ground_shock.hpp"
#include "empirical/imperial_units.hpp"
#include "empirical/shock_peaks.hpp"

using namespace camouflet;
using namespace camouflet::empirical;
namespace imp = camouflet::empirical::imperial;

namespace {

// At W = 8 lb and R = 10 ft the manual's scaled range is exactly 5 ft/lb^(1/3),
// so each peak is a hand-checkable number in the manual's own units.
struct ImperialPoint {
  double charge_lb = 8.0;
  double range_ft = 10.0;
  double scaled = 5.0;  // ft/lb^(1/3)
};

}  // namespace

TEST(GroundShock, SiConversionReproducesTheManualsImperialEquations) {
  const Soil soil{1800.0, 1200.0};  // kg/m^3, m/s
  const double n = 2.3, f = 0.7;
  const ImperialPoint pt;
  const GroundShockLaw law = tm5_855_1(soil, n);
  const Charge charge{pt.charge_lb * imp::pound_kg, f};
  const ShockPeaks p = free_field_peaks(law, charge, pt.range_ft * imp::foot_m);

  const double c_fps = soil.seismic_velocity / imp::foot_m;
  const double rho_c_psi_per_fps = soil.density * soil.seismic_velocity * imp::foot_m / imp::psi_Pa;
  const double v_fps = f * 160.0 * std::pow(pt.scaled, -n);
  const double p_psi = f * rho_c_psi_per_fps * 160.0 * std::pow(pt.scaled, -n);
  const double a_g = f * 50.0 * c_fps * std::pow(pt.scaled, -(n + 1.0)) / std::cbrt(pt.charge_lb);
  const double d_ft = f * 500.0 / c_fps * std::pow(pt.scaled, -(n - 1.0)) * std::cbrt(pt.charge_lb);

  const std::string ref = "TM 5-855-1 ch. 5 in imperial units, W = 8 lb, R = 10 ft";
  test::verify(
      {"TM 5-855-1 SI conversion: peak velocity", ref, v_fps, p.velocity / imp::foot_m, 1e-12, true, "ft/s"});
  test::verify(
      {"TM 5-855-1 SI conversion: peak stress", ref, p_psi, p.stress / imp::psi_Pa, 1e-12, true, "psi"});
  test::verify({"TM 5-855-1 SI conversion: peak acceleration", ref, a_g,
                p.acceleration / imp::standard_gravity, 1e-12, true, "g"});
  test::verify({"TM 5-855-1 SI conversion: peak displacement", ref, d_ft, p.displacement / imp::foot_m, 1e-12,
                true, "ft"});
}

TEST(GroundShock, ScaledDistanceFactorIs2point52) {
  // Z in ft/lb^(1/3) per Z in m/kg^(1/3): the "2.52" of the SI restatements.
  const double k = std::cbrt(imp::pound_kg) / imp::foot_m;
  test::verify({"Scaled-distance conversion m/kg^(1/3) -> ft/lb^(1/3)", "2.52 (rounded, SI restatements)",
                2.52, k, 1e-3, true, "-"});
}

// The paper's coefficients against the manual's general form with the paper's
// soil (Table 1: 1920 kg/m^3, 1400 m/s). They are close but not equal: the
// tolerances below record the discrepancy found, see docs/theory/tm5-855-1.md.
TEST(GroundShock, GeneralFormNearlyReproducesThePapersVelocityAndAcceleration) {
  const std::string ref = "Wang et al. 2005 §5.5, printed";
  const double w_paper = 100.0;  // kg: the paper's accelerations include W^(-1/3)
  for (const auto& [n, velocity, acceleration_g] :
       {std::tuple{2.0, 7.38, 2338.0}, std::tuple{2.5, 4.62, 1464.0}}) {
    const GroundShockLaw law = tm5_855_1(wang2005_sandy_clay(), n);
    const double k_v = law.velocity.coefficient;
    const double k_a = law.acceleration.coefficient / std::cbrt(w_paper) / imp::standard_gravity;
    // General form gives 7.675 / 4.834 m/s: +4.0 % / +4.6 % above the printed values.
    test::verify({fmt::format("TM 5-855-1 general form vs paper: velocity coefficient, n = {}", n), ref,
                  velocity, k_v, 0.05, true, "m/s"});
    // General form gives 2373 / 1495 g: +1.5 % / +2.1 %.
    test::verify(
        {fmt::format("TM 5-855-1 general form vs paper: acceleration coefficient (W = 100 kg), n = {}", n),
         ref, acceleration_g, k_a, 0.025, true, "g"});
    EXPECT_GT(k_v, velocity);  // the paper's numbers are the lower ones, both n
    EXPECT_GT(k_a, acceleration_g);
  }
}

TEST(GroundShock, PapersStressFunctionsAreNotRhoCTimesItsVelocity) {
  // ρc·V with the paper's soil gives 20.6 / 13.0 MPa against the printed
  // Functions 2 / 1 (22 / 15 MPa): -6 % / -13 %. Recorded, not hidden.
  const std::string ref = "Wang et al. 2005 eqs. 38-39, printed";
  for (const auto& [n, printed_MPa, tolerance] : {std::tuple{2.0, 22.0, 0.07}, std::tuple{2.5, 15.0, 0.14}}) {
    const GroundShockLaw law = tm5_855_1(wang2005_sandy_clay(), n);
    test::verify({fmt::format("TM 5-855-1 general form vs paper: stress coefficient, n = {}", n), ref,
                  printed_MPa, law.stress.coefficient / 1e6, tolerance, true, "MPa"});
  }
}

TEST(GroundShock, PaperLawKeepsItsPrintedCoefficientsAtItsChargeMass) {
  const Charge charge{100.0, 0.6};
  const double z1_range = std::cbrt(charge.mass);  // Z = 1
  const ShockPeaks p2 = free_field_peaks(wang2005(2.0), charge, z1_range);
  const ShockPeaks p25 = free_field_peaks(wang2005(2.5), charge, z1_range);
  EXPECT_NEAR(p2.stress, 0.6 * 22e6, 1e-6);
  EXPECT_NEAR(p25.stress, 0.6 * 15e6, 1e-6);
  EXPECT_NEAR(p2.velocity, 0.6 * 7.38, 1e-12);
  EXPECT_NEAR(p25.velocity, 0.6 * 4.62, 1e-12);
  EXPECT_NEAR(p2.acceleration / imp::standard_gravity, 0.6 * 2338.0, 1e-9);
  EXPECT_NEAR(p25.acceleration / imp::standard_gravity, 0.6 * 1464.0, 1e-9);
  // Another charge at the same Z: velocity is unchanged, acceleration scales as W^(-1/3).
  const Charge eight_times{800.0, 0.6};
  const ShockPeaks q = free_field_peaks(wang2005(2.0), eight_times, std::cbrt(eight_times.mass));
  EXPECT_NEAR(q.velocity, p2.velocity, 1e-12);
  EXPECT_NEAR(q.acceleration, p2.acceleration / 2.0, 1e-9);
}

TEST(GroundShock, RefusesBadInput) {
  EXPECT_THROW(wang2005(2.3), InputError);
  EXPECT_THROW(tm5_855_1(Soil{-1.0, 1400.0}, 2.0), InputError);
  EXPECT_THROW(tm5_855_1(Soil{1920.0, 0.0}, 2.0), InputError);
  EXPECT_THROW(tm5_855_1(wang2005_sandy_clay(), 0.0), InputError);
  EXPECT_THROW(scaled_distance(0.0, 100.0), InputError);
  EXPECT_THROW(scaled_distance(5.0, -1.0), InputError);
  const GroundShockLaw law = wang2005(2.0);
  EXPECT_THROW(law.velocity.value(100.0, 1.2, 5.0), InputError);
  EXPECT_THROW(law.velocity.value(100.0, 0.0, 5.0), InputError);
}
