// A plain-concrete bar pulled apart, for two element sizes:
// RHT has no regularisation, so the softening localises in one
// element row and the elongation it takes to break the bar, and the energy,
// scale with the element size. docs/theory/rht-concrete.md, section 4.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "materials/concrete_fixture.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr double length = 0.1;  // m, along x
constexpr double pull = 0.05;   // m/s, velocity of the right end
constexpr double f_t = 3.5e6;   // Pa

// The preset without rate enhancement (the pull is far above the reference
// rates), optionally with a weaker tensile strength to seed the crack.
std::shared_ptr<const Material> rate_free_concrete(double tensile_strength) {
  Parameters strength;
  strength.set_number("compressive_rate_exponent", 0.0);
  strength.set_number("tensile_rate_exponent", 0.0);
  strength.set_number("tensile_strength", tensile_strength);
  return test::concrete_35mpa({}, strength);
}

struct BarResult {
  double peak_stress = 0.0;          // Pa, largest mean axial stress of the weak row
  double elongation_at_peak = 0.0;   // m
  double elongation_at_break = 0.0;  // m, when the weak row's stress has fallen below 5 % of the peak
  double fracture_work = 0.0;        // J/m^2, integral of stress d(elongation) after the peak
};

// Plane strain; a bar one row of square cells of size h high (so both
// meshes have the same topology: one crack element); the middle cell is 2 %
// weaker in tension (the crack seed).
BarResult pull_bar(double h) {
  test::use_threads(1);
  const int cells_high = 1;
  const double height = h;
  const int cells_side = static_cast<int>(std::lround((length - h) / 2.0 / h));
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  model.run.end_time = 1.0;
  model.materials.push_back({"concrete", rate_free_concrete(f_t), {}});
  model.materials.push_back({"seed", rate_free_concrete(0.98 * f_t), {}});
  model.parts.push_back(Part{"left", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"seed", PartKind::fem, 1, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"right", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  const double x_seed = 0.5 * (length - h);
  add_block(model.mesh, {"left", 0, {0, 0, 0}, {x_seed, height, 0}, {cells_side, cells_high, 1}});
  add_block(model.mesh, {"seed", 1, {x_seed, 0, 0}, {h, height, 0}, {1, cells_high, 1}});
  add_block(model.mesh, {"right", 2, {x_seed + h, 0, 0}, {x_seed, height, 0}, {cells_side, cells_high, 1}});
  model.boundaries.push_back(test::velocity("left.xmin", 0, 0.0));
  model.boundaries.push_back(test::velocity("right.xmax", 0, pull));
  for (const char* bottom : {"left.ymin", "seed.ymin", "right.ymin"})
    model.boundaries.push_back(test::velocity(bottom, 1, 0.0));

  Solver<2> solver(model);
  std::vector<std::size_t> seed_elements;
  for (std::size_t e = 0; e < solver.elements().material.size(); ++e)
    if (solver.elements().material[e] == 1) seed_elements.push_back(e);
  BarResult r;
  double previous_stress = 0.0, previous_elongation = 0.0;
  while (solver.time() < 0.01) {
    solver.step();
    double stress = 0.0;
    for (std::size_t e : seed_elements) stress += solver.elements().stress[e].xx;
    stress /= static_cast<double>(seed_elements.size());
    const double elongation = pull * solver.time();
    if (stress > r.peak_stress) {
      r.peak_stress = stress;
      r.elongation_at_peak = elongation;
    } else if (r.peak_stress > 0.0) {
      r.fracture_work += 0.5 * (stress + previous_stress) * (elongation - previous_elongation);
    }
    previous_stress = stress;
    previous_elongation = elongation;
    if (std::getenv("BAR_DEBUG") && solver.cycle() % 200 == 0) {
      double dmax = 0;
      std::size_t emax = 0;
      const auto& b0 = solver.batches()[0];
      for (std::size_t i = 0; i < b0.size(); ++i)
        if (b0.damage[i] > dmax) {
          dmax = b0.damage[i];
          emax = i;
        }
      double ds = 0;
      for (double d : solver.batches()[1].damage) ds = std::max(ds, d);
      std::printf("t=%.3g el=%.3g seed_sxx=%.3g seedD=%.3f otherDmax=%.3f (pt %zu)\n", solver.time(),
                  elongation, stress, ds, dmax, emax);
    }
    if (r.peak_stress > 0.5 * f_t && stress < 0.05 * r.peak_stress && elongation > r.elongation_at_peak) {
      r.elongation_at_break = elongation;
      break;
    }
  }
  return r;
}

}  // namespace

TEST(RhtTensionBar, SofteningScalesWithTheElementSize) {
  const BarResult coarse = pull_bar(0.01);
  const BarResult fine = pull_bar(0.005);
  for (const auto& [r, name] : {std::pair{coarse, "h = 10 mm"}, std::pair{fine, "h = 5 mm"}}) {
    std::printf("%s: peak %.3f MPa at %.3g m, broken at %.3g m, fracture work %.1f J/m^2\n", name,
                r.peak_stress / 1e6, r.elongation_at_peak, r.elongation_at_break, r.fracture_work);
    test::verify(
        {std::string("RHT concrete bar in tension (plane strain, rate-free), ") + name + ": peak stress",
         "f_t = 3.5 MPa (Wang et al. 2005, Table 3), +-25 %", f_t, r.peak_stress, 0.25, true, "Pa"});
    EXPECT_GT(r.elongation_at_break, 0.0) << name << ": the bar did not break";
  }
  // No regularisation: the post-peak elongation is carried by one element
  // row, so it (and the fracture work) roughly halves with the element size.
  const double ratio = (coarse.elongation_at_break - coarse.elongation_at_peak) /
                       (fine.elongation_at_break - fine.elongation_at_peak);
  std::printf("post-peak elongation ratio coarse/fine = %.2f, fracture work ratio = %.2f\n", ratio,
              coarse.fracture_work / fine.fracture_work);
  test::record_check("RHT concrete bar in tension: mesh dependence of the softening",
                     "post-peak elongation proportional to the element size (no regularisation)",
                     fmt::format("coarse/fine post-peak elongation = {:.2f}, fracture work ratio = {:.2f}",
                                 ratio, coarse.fracture_work / fine.fracture_work),
                     ratio > 1.5 && ratio < 2.5);
  EXPECT_GT(ratio, 1.5);
  EXPECT_LT(ratio, 2.5);
}
