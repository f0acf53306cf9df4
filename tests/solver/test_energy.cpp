// Energy conservation: a free elastic block
// set vibrating by an initial velocity field keeps kinetic + internal +
// hourglass energy constant within 0.1 % over 10,000 cycles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

template <int D>
void run_free_vibration(HourglassForm form, const std::string& label) {
  test::use_threads(1);
  const ElasticConstants c;
  const GeometryMode mode = D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d;
  Model model = test::block_model(mode, {{"block", 0, {0, 0, 0}, {1, 0.8, 0.6}, {4, 3, 3}}}, c);
  model.run.hourglass = form;
  model.run.end_time = 1e9;
  Solver<D> solver(model);
  // A breathing-and-shearing velocity field with zero net momentum (m/s),
  // imposed after construction: the reference energy is its kinetic energy.
  auto& v = solver.velocity();
  for (std::size_t n = 0; n < solver.node_count(); ++n) {
    const double x = solver.position()[n * D] - 0.5, y = solver.position()[n * D + 1] - 0.4;
    v[n * D] = std::sin(std::numbers::pi * x) + 0.5 * y;
    v[n * D + 1] = -0.7 * std::sin(std::numbers::pi * y / 0.8) - 0.3 * x;
  }
  const double e0 = [&] {
    double k = 0.0;
    for (std::size_t n = 0; n < solver.node_count(); ++n)
      for (int i = 0; i < D; ++i) k += 0.5 * solver.node_mass()[n] * v[n * D + i] * v[n * D + i];
    return k;
  }();
  double worst = 0.0, peak_internal = 0.0;
  for (int k = 0; k < 10000; ++k) {
    solver.step();
    const EnergyBalance& e = solver.energy();
    const double total = e.kinetic + e.internal + e.hourglass;
    worst = std::max(worst, std::abs(total - e0) / e0);
    peak_internal = std::max(peak_internal, e.internal);
  }
  EXPECT_GT(peak_internal, 0.2 * e0) << "the block must actually exchange kinetic and strain energy";
  test::verify({label + ": largest drift of total energy over 10,000 cycles", "conservation (exact)", 0.0,
                worst, 1e-3, false, "relative"});
}

}  // namespace

TEST(EnergyBalance, FreeVibrationPlaneStrainViscousHourglass) {
  run_free_vibration<2>(HourglassForm::viscous, "Free elastic block, 2-D, viscous hourglass");
}

TEST(EnergyBalance, FreeVibrationHexStiffnessHourglass) {
  run_free_vibration<3>(HourglassForm::stiffness, "Free elastic block, 3-D, stiffness hourglass");
}
