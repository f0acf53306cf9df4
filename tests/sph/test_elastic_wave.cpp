// Elastic P-wave in an SPH solid column: the column
// moves at -v0 onto a rigid wall at x = 0; the compression front runs back
// at c_p = sqrt((K + 4G/3) / rho) (uniaxial strain: symmetry planes at y = 0
// and y = H keep the lateral strain zero). The front (where the particle
// velocity is -v0/2) is located at two times; its speed is compared with c_p,
// and the stress behind it with the acoustic value rho c_p v0.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

constexpr double rho = 7800.0, bulk = 160e9, shear = 80e9, v0 = 1.0, length = 1.0;

// Front position: along the bottom row, the first particle from the wall whose velocity is below -v0/2,
// linearly interpolated with its predecessor.
double front_position(const SphSystem<2>& sph, double dx) {
  const auto& p = sph.particles();
  std::vector<std::pair<double, double>> row;
  for (std::size_t i = 0; i < sph.size(); ++i)
    if (p.position[i][1] < dx) row.emplace_back(p.position[i][0], p.velocity[i][0]);
  std::sort(row.begin(), row.end());
  for (std::size_t k = 1; k < row.size(); ++k)
    if (row[k].second < -0.5 * v0) {
      const auto [x0, u0] = row[k - 1];
      const auto [x1, u1] = row[k];
      return x0 + (x1 - x0) * (-0.5 * v0 - u0) / (u1 - u0);
    }
  return 0.0;
}

}  // namespace

TEST(SphElasticWave, PWaveSpeedInColumn) {
  const double dx = length / 200;
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  test::add_sph_part(model, "steel", test::elastic_solid("steel", rho, bulk, shear),
                     test::box_fill({0, 0, 0}, {length, 4 * dx, 0}, dx), {-v0, 0, 0});
  const std::vector<MirrorPlane> planes{
      {0, 0.0, PlaneKind::symmetry}, {1, 0.0, PlaneKind::symmetry}, {1, 4 * dx, PlaneKind::symmetry}};
  SphSystem<2> sph(model, SphOptions{}, planes);
  const double cp = std::sqrt((bulk + 4.0 * shear / 3.0) / rho);
  const double t1 = 0.25 * length / cp, t2 = 0.65 * length / cp;
  test::run_until(sph, t1, 0.3);
  const double x1 = front_position(sph, dx);
  // Stress behind the front (mid-way between wall and front), acoustic: sigma_xx = -rho c_p v0.
  double sxx = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    const double x = sph.particles().position[i][0];
    if (x > 0.3 * x1 && x < 0.7 * x1) sxx += sph.particles().stress[i].xx, ++count;
  }
  sxx /= count;
  // Continue from t1 to t2 (run_until restarts its clock: step the difference).
  test::run_until(sph, t2 - t1, 0.3);
  const double x2 = front_position(sph, dx);
  const double speed = (x2 - x1) / (t2 - t1);
  test::verify({"SPH elastic P-wave, 2-D column (steel, dx = L/200): front speed",
                "c_p = sqrt((K + 4G/3)/rho)", cp, speed, 0.03, true, "m/s"});
  test::verify({"SPH elastic P-wave, 2-D column: axial stress behind the front",
                "-rho c_p v0 (acoustic impedance)", -rho * cp * v0, sxx, 0.03, true, "Pa"});
  std::printf("P-wave: speed %.1f (c_p %.1f), sigma_xx %.4g (expected %.4g)\n", speed, cp, sxx,
              -rho * cp * v0);
}
