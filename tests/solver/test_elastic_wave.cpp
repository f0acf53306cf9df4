// Uniaxial-strain elastic P-wave in a long column:
// a velocity step v0 on one end; the front reaches a station at
// x = L_s after L_s / c_p, and behind it sigma_xx = -rho c_p v0.
#include <gtest/gtest.h>

#include <cmath>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

struct WaveResult {
  double arrival = 0.0;  // s, when the station's velocity first reaches v0 / 2
  double stress = 0.0;   // Pa, mean sigma_xx of the elements in the plateau
};

template <int D>
WaveResult run_column(const std::string& label) {
  test::use_threads(1);
  const ElasticConstants c;
  const double length = 1.0, cell = 2.5e-3, v0 = 1.0;
  const int cells = static_cast<int>(std::lround(length / cell));
  const GeometryMode mode = D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d;
  Model model = test::block_model(mode, {{"bar", 0, {0, 0, 0}, {length, cell, cell}, {cells, 1, 1}}}, c);
  model.boundaries.push_back(test::velocity("bar.xmin", 0, v0));
  model.boundaries.push_back(test::symmetry("bar.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("bar.ymax", {0, 1, 0}));
  if (D == 3) {
    model.boundaries.push_back(test::symmetry("bar.zmin", {0, 0, 1}));
    model.boundaries.push_back(test::symmetry("bar.zmax", {0, 0, 1}));
  }
  const double station = 0.6 * length;
  model.run.end_time = 0.8 * length / c.p_wave_speed();
  Solver<D> solver(model);

  // Station: the node on the axis nearest x = station.
  std::size_t gauge = 0;
  for (std::size_t n = 0; n < solver.node_count(); ++n)
    if (std::abs(solver.position()[n * D] - station) < std::abs(solver.position()[gauge * D] - station))
      gauge = n;
  const double x_gauge = solver.position()[gauge * D];

  WaveResult r;
  double t_prev = 0.0, v_prev = 0.0;
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    const double v = solver.velocity()[gauge * D];
    if (r.arrival == 0.0 && v >= 0.5 * v0)  // linear interpolation of the crossing
      r.arrival = t_prev + (0.5 * v0 - v_prev) / (v - v_prev) * (solver.time() - t_prev);
    t_prev = solver.time();
    v_prev = v;
  }
  // Plateau: elements between 0.1 L and 0.6 L (the front is at 0.8 L).
  double sum = 0.0;
  int count = 0;
  const auto& el = solver.elements();
  for (std::size_t e = 0; e < el.size(); ++e) {
    const double xc =
        solver.position()[static_cast<std::size_t>(el.connectivity[e * el.nodes]) * D] + 0.5 * cell;
    if (xc > 0.1 * length && xc < 0.6 * length) {
      sum += el.stress[e].xx;
      ++count;
    }
  }
  r.stress = sum / count;
  test::verify({label + ": arrival time at the station", "x / c_p (analytic)", x_gauge / c.p_wave_speed(),
                r.arrival, 0.01, true, "s"});
  test::verify({label + ": stress behind the front", "-rho c_p v0 (analytic)",
                -c.density * c.p_wave_speed() * v0, r.stress, 0.02, true, "Pa"});
  return r;
}

}  // namespace

TEST(ElasticWave, UniaxialStrainColumnPlaneStrain) {
  run_column<2>("Uniaxial-strain P-wave, 2-D");
}

TEST(ElasticWave, UniaxialStrainColumn3D) {
  run_column<3>("Uniaxial-strain P-wave, 3-D");
}
