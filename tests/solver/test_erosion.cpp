// Element erosion: a plane-strain bar pulled until its weakest
// element necks past the geometric-strain threshold. That element is eroded
// (stress zeroed, mass kept on its nodes), the two halves spring back, and
// the energy balance, with the eroded element's internal energy moved to
// EnergyBalance::eroded, stays closed. docs/theory/reinforcement.md, section 3.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "fem/shape.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr double threshold = 0.15;  // geometric strain at erosion

struct ErosionResult {
  std::size_t eroded = 0;
  double strain_at_erosion = 0.0;  // log-strain equivalent of the seed element's shape at erosion
  double eroded_energy = 0.0, boundary_work = 0.0, energy_error = 0.0, mass_change = 0.0;
  double seed_stress_after = 0.0;
};

ErosionResult pull_to_erosion() {
  test::use_threads(1);
  test::ElasticConstants steel{7800.0, 160e9, 80e9, 300e6};
  test::ElasticConstants weak = steel;
  weak.yield_stress = 270e6;
  Model model =
      test::seeded_pulled_bar(test::elastic_material(steel, "steel"), test::elastic_material(weak, "seed"));
  model.run.end_time = 1.0;
  model.erosion = {{threshold, 0.0}, {threshold, 0.0}};

  Solver<2> solver(model);
  const double mass0 = std::accumulate(solver.node_mass().begin(), solver.node_mass().end(), 0.0);
  std::vector<std::size_t> seed;
  for (std::size_t e = 0; e < solver.elements().size(); ++e)
    if (solver.elements().material[e] == 1) seed.push_back(e);
  // Hencky (logarithmic) strain equivalent of each seed element from its
  // deformation gradient F = dx/dX at the centre (one-point gradients of the
  // initial geometry): principal stretches from C = F^T F; the largest over
  // the seed (the first to erode).
  const std::vector<double> x0 = solver.position();
  auto shape_strain = [&]() {
    double largest = 0.0;
    for (std::size_t e : seed) {
      const std::int64_t* c = &solver.elements().connectivity[e * 4];
      double xi[2][4], b[2][4];
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 2; ++i) xi[i][a] = x0[static_cast<std::size_t>(c[a] * 2 + i)];
      Shape<2>::gradients(xi, b);
      double f[2][2] = {};
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          for (int a = 0; a < 4; ++a)
            f[i][j] += solver.position()[static_cast<std::size_t>(c[a] * 2 + i)] * b[j][a];
      const double c11 = f[0][0] * f[0][0] + f[1][0] * f[1][0], c22 = f[0][1] * f[0][1] + f[1][1] * f[1][1];
      const double c12 = f[0][0] * f[0][1] + f[1][0] * f[1][1];
      const double mean = 0.5 * (c11 + c22), radius = std::sqrt(0.25 * (c11 - c22) * (c11 - c22) + c12 * c12);
      const double e1 = 0.5 * std::log(mean + radius), e2 = 0.5 * std::log(mean - radius);
      largest = std::max(largest, std::sqrt(2.0 / 3.0 * (e1 * e1 + e2 * e2)));
    }
    return largest;
  };
  ErosionResult r;
  double t_erosion = -1.0;
  while (solver.time() < 2e-3) {
    const double before = shape_strain();
    solver.step();
    if (t_erosion < 0.0 && solver.eroded_count() > 0) {
      t_erosion = solver.time();
      r.strain_at_erosion = before;  // erosion is decided at the end of the step from its start shape + D dt
    }
    if (t_erosion > 0.0 && solver.time() > t_erosion + 200e-6) break;
  }
  r.eroded = solver.eroded_count();
  r.eroded_energy = solver.energy().eroded;
  r.boundary_work = solver.energy().boundary_work;
  r.energy_error = solver.energy().relative_error;
  r.mass_change = std::accumulate(solver.node_mass().begin(), solver.node_mass().end(), 0.0) / mass0 - 1.0;
  for (std::size_t e : seed)
    r.seed_stress_after = std::max(r.seed_stress_after, std::abs(solver.elements().stress[e].xx));
  std::printf(
      "eroded %zu at t = %.4g ms, shape strain %.4f; eroded energy %.4g J/m of %.4g J/m boundary work; "
      "energy error %.3g\n",
      r.eroded, t_erosion * 1e3, r.strain_at_erosion, r.eroded_energy, r.boundary_work, r.energy_error);
  return r;
}

}  // namespace

TEST(Erosion, GeometricStrainErodesTheNeckAndKeepsTheEnergyBalanceClosed) {
  const ErosionResult r = pull_to_erosion();
  EXPECT_EQ(r.eroded, 2u) << "only the seed's two elements reach the threshold";
  test::verify({"Erosion by geometric strain: strain of the eroded element",
                "threshold 0.15 (Hencky strain of the element, sqrt(2/3 eps:eps))", threshold,
                r.strain_at_erosion, 0.05, true, "-"});
  EXPECT_EQ(r.seed_stress_after, 0.0);
  EXPECT_NEAR(r.mass_change, 0.0, 1e-14) << "eroded mass stays on the nodes";
  // The eroded energy must matter, or the closed balance proves nothing.
  EXPECT_GT(r.eroded_energy, 0.05 * r.boundary_work);
  test::verify({"Erosion by geometric strain: energy balance with eroded energy", "closed (relative error)",
                0.0, r.energy_error, 0.01, false, "-"});
}
