// The material-point driver against closed forms, with a hypoelastic test
// material defined here: p = -K ln(V/V0) (exact in the driver's logarithmic
// strain) and s_dot = 2 G dev(D), so every path below has an exact answer.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "common/verification.hpp"
#include "materials/material_driver.hpp"

using namespace camouflet;

namespace {

constexpr double kBulk = 10.0e9;  // Pa
constexpr double kShear = 6.0e9;  // Pa
constexpr double kDensity = 2000.0;

class LogBulkEos : public EquationOfState {
 public:
  std::string type() const override { return "test_log_bulk"; }
  double reference_density() const override { return kDensity; }
  void evaluate(MaterialPoints& pts, const MaterialContext&, bool) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      pts.pressure[i] = kBulk * std::log(pts.density[i] / kDensity);
      pts.sound_speed[i] = std::sqrt(kBulk / pts.density[i]);
    }
  }
};

class HypoElastic : public StrengthModel {
 public:
  std::string type() const override { return "test_hypoelastic"; }
  void initialise(MaterialPoints& pts) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) pts.shear_modulus[i] = kShear;
  }
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override {
    for (std::size_t i = 0; i < pts.size(); ++i)
      pts.deviator[i] += 2.0 * kShear * ctx.dt * deviator(pts.strain_rate[i]);
  }
};

Material elastic() {
  return Material("elastic", std::make_shared<LogBulkEos>(), std::make_shared<HypoElastic>());
}

}  // namespace

TEST(MaterialDriver, UniaxialStrainFollowsConstrainedModulus) {
  DriverSpec spec;
  spec.path = LoadPath::uniaxial_strain;
  spec.strain_rate = -10.0;
  spec.final_strain = -0.01;
  spec.steps = 200;
  const auto rows = drive_material(elastic(), spec);
  ASSERT_EQ(rows.size(), 201u);
  const DriverRow& last = rows.back();
  test::verify({"Material driver, uniaxial strain: axial stress", "(K + 4G/3) eps (closed form)",
                (kBulk + 4.0 * kShear / 3.0) * spec.final_strain, last.stress.xx, 1e-9, true, "Pa"});
  test::verify({"Material driver, uniaxial strain: lateral stress", "(K - 2G/3) eps (closed form)",
                (kBulk - 2.0 * kShear / 3.0) * spec.final_strain, last.stress.yy, 1e-9, true, "Pa"});
  EXPECT_NEAR(last.axial_strain, -0.01, 1e-15);
  EXPECT_NEAR(last.time, 1e-3, 1e-15);
  EXPECT_NEAR(last.density, kDensity * std::exp(0.01), 1e-9);
}

TEST(MaterialDriver, UniaxialStressFollowsYoungsModulus) {
  DriverSpec spec;
  spec.path = LoadPath::uniaxial_stress;
  spec.strain_rate = -1.0;
  spec.final_strain = -0.005;
  spec.steps = 100;
  const auto rows = drive_material(elastic(), spec);
  const double young = 9.0 * kBulk * kShear / (3.0 * kBulk + kShear);
  const DriverRow& last = rows.back();
  test::verify({"Material driver, uniaxial stress: axial stress", "E eps (closed form)",
                young * spec.final_strain, last.stress.xx, 1e-7, true, "Pa"});
  test::verify({"Material driver, uniaxial stress: lateral stress held at zero", "0", 0.0, last.stress.yy,
                1e-6 * std::abs(last.stress.xx), false, "Pa"});
  EXPECT_NEAR(last.stress.zz, 0.0, 1e-6 * std::abs(last.stress.xx));
}

TEST(MaterialDriver, HydrostaticToPressureLandsOnTarget) {
  DriverSpec spec;
  spec.path = LoadPath::hydrostatic;
  spec.strain_rate = -1.0;
  spec.final_pressure = 50.0e6;
  spec.steps = 50;
  const auto rows = drive_material(elastic(), spec);
  const DriverRow& last = rows.back();
  test::verify({"Material driver, hydrostatic: final pressure", "requested pressure", 50.0e6, last.pressure,
                1e-9, true, "Pa"});
  test::verify({"Material driver, hydrostatic: volumetric strain", "-p / K (closed form)", -50.0e6 / kBulk,
                last.volumetric_strain, 1e-9, true, ""});
  EXPECT_NEAR(last.sqrt_j2, 0.0, 1e-3);
}

TEST(MaterialDriver, TriaxialHoldsConfinement) {
  DriverSpec spec;
  spec.path = LoadPath::triaxial;
  spec.strain_rate = -1.0;
  spec.final_strain = -0.002;
  spec.confining_pressure = 20.0e6;
  spec.steps = 40;
  const auto rows = drive_material(elastic(), spec);
  const DriverRow& last = rows.back();
  const double young = 9.0 * kBulk * kShear / (3.0 * kBulk + kShear);
  test::verify({"Material driver, triaxial: lateral stress", "-confining pressure", -20.0e6, last.stress.yy,
                1e-7, true, "Pa"});
  test::verify({"Material driver, triaxial: deviatoric stress", "E d(eps_axial) (closed form)",
                young * -0.002, last.stress.xx - last.stress.yy, 1e-6, true, "Pa"});
}

TEST(MaterialDriver, SimpleShearWithJaumannRate) {
  // Hypoelastic material under the Jaumann rate in simple shear:
  // sigma_xy = G sin(gamma), sigma_xx = -sigma_yy = G (1 - cos(gamma)).
  DriverSpec spec;
  spec.path = LoadPath::simple_shear;
  spec.strain_rate = 100.0;
  spec.final_strain = 1.0;
  spec.steps = 4000;
  const auto rows = drive_material(elastic(), spec);
  const DriverRow& last = rows.back();
  test::verify({"Material driver, simple shear (Jaumann): shear stress", "G sin(gamma) (closed form)",
                kShear * std::sin(1.0), last.stress.xy, 1e-3, true, "Pa"});
  test::verify({"Material driver, simple shear (Jaumann): normal stress", "G (1 - cos(gamma)) (closed form)",
                kShear * (1.0 - std::cos(1.0)), last.stress.xx, 1e-3, true, "Pa"});
  EXPECT_NEAR(last.pressure, 0.0, 1.0);
}

TEST(MaterialDriver, CsvHasHeaderAndOneLinePerRow) {
  DriverSpec spec;
  spec.steps = 3;
  const auto rows = drive_material(elastic(), spec);
  std::ostringstream out;
  write_driver_csv(out, rows);
  const std::string text = out.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 5);
  EXPECT_EQ(text.rfind("time_s,axial_strain,volumetric_strain,sigma_xx_pa", 0), 0u);
}

TEST(MaterialDriver, RejectsOppositeSigns) {
  DriverSpec spec;
  spec.strain_rate = 1.0;
  spec.final_strain = -0.01;
  EXPECT_THROW(drive_material(elastic(), spec), std::invalid_argument);
  EXPECT_THROW(parse_load_path("biaxial"), std::invalid_argument);
  EXPECT_EQ(parse_load_path("uniaxial-stress"), LoadPath::uniaxial_stress);
}
