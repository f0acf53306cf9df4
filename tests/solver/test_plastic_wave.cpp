// Uniaxial-strain impact on an elastic-perfectly-plastic (von Mises) bar.
// The velocity step splits into an elastic
// precursor at the Hugoniot elastic limit and a slower plastic wave:
//   sigma_HEL = (K + 4G/3) Y / (2G)          (uniaxial strain, yield at sqrt(3 J2) = Y)
//   c_plastic = sqrt(K / rho)                 (perfect plasticity: the deviator is frozen)
// (Meyers, Dynamic Behavior of Materials, 1994, s. 7.2).
#include <gtest/gtest.h>

#include <cmath>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

TEST(PlasticWave, ElasticPrecursorAndPlasticFront) {
  test::use_threads(1);
  ElasticConstants c;
  c.density = 2700.0;
  c.bulk_modulus = 70e9;
  c.shear_modulus = 32.3e9;
  c.yield_stress = 300e6;
  const double length = 1.0, cell = 1.25e-3, v0 = 45.0;
  const int cells = static_cast<int>(std::lround(length / cell));
  Model model = test::block_model(GeometryMode::plane_strain,
                                  {{"bar", 0, {0, 0, 0}, {length, cell, 0}, {cells, 1, 1}}}, c);
  model.boundaries.push_back(test::velocity("bar.xmin", 0, v0));
  model.boundaries.push_back(test::symmetry("bar.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("bar.ymax", {0, 1, 0}));
  const double cp = c.p_wave_speed(), cb = c.bulk_wave_speed();
  const double hel =
      (c.bulk_modulus + 4.0 * c.shear_modulus / 3.0) * c.yield_stress / (2.0 * c.shear_modulus);
  const double v_hel = hel / (c.density * cp);
  ASSERT_GT(v0, 1.3 * v_hel) << "the impact must exceed the elastic limit";

  Solver<2> solver(model);
  // Plastic front: where the particle velocity crosses the mean of v_HEL and v0,
  // located along the bar at two instants.
  const double v_mid = 0.5 * (v_hel + v0);
  const auto front = [&] {
    // Bottom-row nodes are ordered by x (block generator); scan from the far end.
    double x_front = 0.0;
    for (std::size_t n = 0; n + 1 < static_cast<std::size_t>(cells) + 1; ++n) {
      const double va = solver.velocity()[2 * n], vb = solver.velocity()[2 * (n + 1)];
      if (va >= v_mid && vb < v_mid) {
        const double xa = solver.position()[2 * n], xb = solver.position()[2 * (n + 1)];
        x_front = xa + (va - v_mid) / (va - vb) * (xb - xa);
      }
    }
    return x_front;
  };
  const double t1 = 0.3 * length / cp, t2 = 0.85 * length / cp;
  double x1 = 0.0;
  while (solver.time() < t2) {
    solver.limit_next_step((solver.time() < t1 ? t1 : t2) - solver.time());
    solver.step();
    if (std::abs(solver.time() - t1) < 1e-15) x1 = front();
  }
  const double x2 = front();
  ASSERT_GT(x1, 0.0);
  // Precursor plateau: elements between the plastic front and the elastic front (at cp t2).
  double sum = 0.0;
  int count = 0;
  const auto& el = solver.elements();
  for (std::size_t e = 0; e < el.size(); ++e) {
    const double xc = solver.position()[static_cast<std::size_t>(el.connectivity[e * 4]) * 2] + 0.5 * cell;
    if (xc > x2 + 0.2 * (cp * t2 - x2) && xc < cp * t2 - 0.2 * (cp * t2 - x2)) {
      sum += el.stress[e].xx;
      ++count;
    }
  }
  ASSERT_GT(count, 20);
  test::verify({"Elastic-plastic impact, uniaxial strain: elastic precursor stress",
                "Hugoniot elastic limit (K + 4G/3) Y / 2G (analytic)", -hel, sum / count, 0.03, true, "Pa"});
  test::verify({"Elastic-plastic impact, uniaxial strain: plastic wave speed",
                "bulk sound speed sqrt(K/rho) (analytic)", cb, (x2 - x1) / (t2 - t1), 0.02, true, "m/s"});
}
