// Johnson-Cook failure through the solver's erosion path
// (docs/theory/explosive-and-steel.md §5.1): a plane-strain 4340 steel bar
// pulled at one end, with a slightly weaker seed whose Johnson-Cook failure
// strain is small (eps_f = D1 = 0.05). Plastic flow localises in the seed,
// its damage reaches 1 and `erosion = { damage = 1 }` removes its elements:
// their stress is zero afterwards, the two halves spring back, and the
// energy balance with the eroded internal energy still closes.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/johnson_cook_failure.hpp"
#include "materials/linear_eos.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

std::shared_ptr<const Material> steel(const std::string& name, double yield, double d1, double d2,
                                      double d3) {
  JohnsonCookParameters s;  // 4340 steel, Johnson & Cook 1983
  s.shear_modulus = 77.5e9;
  s.yield_stress = yield;
  s.hardening_modulus = 510e6;
  s.hardening_exponent = 0.26;
  s.rate_coefficient = 0.014;
  s.thermal_exponent = 1.03;
  s.melt_temperature = 1793.0;
  s.specific_heat = 477.0;
  JohnsonCookFailureParameters f;
  f.d1 = d1;
  f.d2 = d2;
  f.d3 = d3;
  return std::make_shared<const Material>(name, std::make_shared<const LinearEos>(7830.0, 159e9),
                                          std::make_shared<const JohnsonCookStrength>(s),
                                          std::make_shared<const JohnsonCookFailure>(f));
}

}  // namespace

TEST(JohnsonCookErosion, FailedSeedErodesAndTheEnergyBalanceCloses) {
  test::use_threads(1);
  // Bar: Johnson & Cook 1985 fracture constants (eps_f = 0.98 in tension);
  // seed: 10 % weaker and failing at eps_p = 0.05.
  Model model = test::seeded_pulled_bar(steel("steel", 792e6, -0.80, 2.10, -0.50),
                                        steel("seed", 712e6, 0.05, 0.0, 0.0));
  model.run.end_time = 1.0;
  model.erosion = {{0.0, 1.0}, {0.0, 1.0}};  // erode at damage 1

  Solver<2> solver(model);
  std::vector<std::size_t> seed;
  for (std::size_t e = 0; e < solver.elements().size(); ++e)
    if (solver.elements().material[e] == 1) seed.push_back(e);
  double t_erosion = -1.0, seed_strain_at_erosion = 0.0, bar_strain = 0.0;
  while (solver.time() < 2e-3) {
    double before = 0.0;
    for (std::size_t e : seed)
      before = std::max(before, solver.batches()[1].plastic_strain[solver.elements().point[e]]);
    solver.step();
    if (t_erosion < 0.0 && solver.eroded_count() > 0) {
      t_erosion = solver.time();
      seed_strain_at_erosion = before;
    }
    if (t_erosion > 0.0 && solver.time() > t_erosion + 200e-6) break;
  }
  for (double e : solver.batches()[0].plastic_strain) bar_strain = std::max(bar_strain, e);
  const EnergyBalance& e = solver.energy();
  double seed_stress = 0.0;
  for (std::size_t el : seed) seed_stress = std::max(seed_stress, std::abs(solver.elements().stress[el].xx));
  std::printf(
      "JC erosion: %zu eroded at t = %.4g ms, seed eps_p before %.4f, bar eps_p %.4f; eroded %.4g J/m, "
      "boundary work %.4g J/m, energy error %.3g\n",
      solver.eroded_count(), t_erosion * 1e3, seed_strain_at_erosion, bar_strain, e.eroded, e.boundary_work,
      e.relative_error);

  ASSERT_GT(t_erosion, 0.0) << "the seed never failed";
  EXPECT_EQ(solver.eroded_count(), seed.size()) << "only the seed fails";
  // Erosion is decided at the end of the step in which D reaches 1, i.e.
  // within one step's plastic increment of eps_f.
  test::verify({"Johnson-Cook failure in the solver: plastic strain of the seed when it erodes",
                "eps_f = D1 = 0.05 (reached within the eroding step)", 0.05, seed_strain_at_erosion, 0.01,
                true, "-"});
  EXPECT_LT(bar_strain, 0.05) << "the bar outside the seed must not fail";
  EXPECT_EQ(seed_stress, 0.0);
  EXPECT_GT(e.eroded, 0.02 * e.boundary_work)
      << "the eroded energy must matter, or the balance proves nothing";
  test::verify({"Johnson-Cook failure in the solver: energy balance with eroded energy",
                "closed (relative error)", 0.0, e.relative_error, 0.01, false, "-"});
}
