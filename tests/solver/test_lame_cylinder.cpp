// Axisymmetric correctness: a thick-walled
// cylinder in r-z, a < r < b, axial motion suppressed (plane strain along z),
// under an internal pressure ramped smoothly over several breathing periods,
// against the Lame solution (Timoshenko & Goodier, Theory of Elasticity, s. 28):
//   u = A r + B / r,  B = p a^2 b^2 / (2 G (b^2 - a^2)),  A = p a^2 / (2 (lambda + G) (b^2 - a^2)),
//   sigma_tt = p a^2 (1 + b^2 / r^2) / (b^2 - a^2).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

// form: "volume", "area", or "mixed" (the inner half of the wall in the area form as its own
// part, the outer half in the volume form: the nodes where they meet take both).
void check_lame(const std::string& momentum) {
  test::use_threads(1);
  const ElasticConstants c;
  const double a = 0.1, b = 0.2, p = 1.0e6;
  const int cells = 20;
  const double h = (b - a) / cells;
  const bool mixed = momentum == "mixed";
  Model model = mixed ? test::block_model(
                            GeometryMode::axisymmetric,
                            {{"tube", 0, {a, 0, 0}, {0.5 * (b - a), h, 0}, {cells / 2, 1, 1}},
                             {"outer", 1, {0.5 * (a + b), 0, 0}, {0.5 * (b - a), h, 0}, {cells / 2, 1, 1}}},
                            c)
                      : test::block_model(GeometryMode::axisymmetric,
                                          {{"tube", 0, {a, 0, 0}, {b - a, h, 0}, {cells, 1, 1}}}, c);
  for (const char* block : {"tube", "outer"}) {
    if (!mixed && std::string(block) == "outer") continue;
    model.boundaries.push_back(test::symmetry(std::string(block) + ".ymin", {0, 1, 0}));
    model.boundaries.push_back(test::symmetry(std::string(block) + ".ymax", {0, 1, 0}));
  }
  if (mixed) {
    Part outer = model.parts.front();
    outer.name = "outer";
    model.parts.push_back(outer);
    model.parts.front().area_weighted_momentum = true;
  }

  // Breathing period ~ 2 pi r / c_p; ramp as (1 - cos) over ~8 periods, then hold and average.
  const double period = 2.0 * std::numbers::pi * 0.5 * (a + b) / c.p_wave_speed();
  const double ramp = 8.0 * period, hold = 2.0 * period;
  TimeHistory history;
  for (int k = 0; k <= 40; ++k) {
    const double t = ramp * k / 40.0;
    history.time.push_back(t);
    history.value.push_back(0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp)));
  }
  model.boundaries.push_back(test::pressure("tube.xmin", p, history));
  model.run.end_time = ramp + hold;
  model.run.area_weighted_momentum = momentum == "area";
  const std::string form = momentum == "area" ? ", area-weighted momentum"
                           : mixed            ? ", inner half in the area form, outer half in the volume form"
                                              : "";

  Solver<2> solver(model);
  std::size_t inner = 0;  // a node on r = a
  for (std::size_t n = 0; n < solver.node_count(); ++n)
    if (solver.position()[2 * n] < solver.position()[2 * inner]) inner = n;
  double u_sum = 0.0, hoop_sum = 0.0, weight = 0.0;
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    if (solver.time() > ramp) {  // time average over the hold removes the residual ringing
      const double dt = solver.time_step_limit().dt;
      u_sum += solver.displacement()[2 * inner] * dt;
      hoop_sum += solver.elements().stress.front().zz * dt;
      weight += dt;
    }
  }
  const double lambda = c.lame_lambda(), g = c.shear_modulus;
  const double B = p * a * a * b * b / (2.0 * g * (b * b - a * a));
  const double A = p * a * a / (2.0 * (lambda + g) * (b * b - a * a));
  const double r1 = a + 0.5 * h;  // centre of the innermost element
  test::verify({"Lame thick cylinder (axisymmetric" + form + "): radial displacement at r = a",
                "Lame solution A a + B / a", A * a + B / a, u_sum / weight, 0.02, true, "m"});
  test::verify({"Lame thick cylinder (axisymmetric" + form + "): hoop stress in the innermost element",
                "Lame solution p a^2 (1 + b^2/r^2) / (b^2 - a^2)",
                p * a * a * (1.0 + b * b / (r1 * r1)) / (b * b - a * a), hoop_sum / weight, 0.02, true,
                "Pa"});
}

}  // namespace

TEST(LameCylinder, AxisymmetricThickCylinderUnderInternalPressure) {
  check_lame("volume");
}

// The same in the area-weighted form: the pressure load's nodal shares are
// planar times the ring factor, as the element forces they meet.
TEST(LameCylinder, AxisymmetricAreaWeightedThickCylinderUnderInternalPressure) {
  check_lame("area");
}

// Parts of both forms in one mesh (a part's own `axisymmetric_momentum`): each element's force in
// its own form, the area form's times the node's ring factor, so that both are forces on the ring.
TEST(LameCylinder, AxisymmetricMixedFormsThickCylinderUnderInternalPressure) {
  check_lame("mixed");
}
