// A 1-D planar detonation under mesh refinement: a column lit at a rigid wall
// (x = 0, t = 0), one plane-strain element across with rollers, at three cell
// sizes a factor 2 apart (0.2, 0.1, 0.05 mm over 4 cm), for a gamma-law
// explosive (JWL with C1 = C2 = 0, gamma = 3, exact Taylor wave) and for the
// paper's TNT. The burn must stay well behaved as the cells shrink:
// * the plateau at rest next to the wall (x/t < D/2) at the exact pressure of
//   the CJ isentrope at u = 0 (Fickett & Davis 1979, sec. 2A), within 1 %;
// * the half-P_CJ front within one cell of D t at every output time;
// * the peak pressure bounded: within 5 % of P_CJ in the far half of the run,
//   and no more than 5 % above the near half's (no growth with travel);
// * the time step never below 20 % of the CFL step of the unburnt explosive.
// docs/theory/explosive-and-steel.md, "Burn under refinement".
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/fem_models.hpp"
#include "detonation_column.hpp"
#include "common/verification.hpp"
#include "materials/jwl_eos.hpp"
#include "materials/registry.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr double column_length = 0.04;  // m

// gamma = 3 (omega = 2), rho0 = 1600 kg/m^3, Q = 4 MJ/kg: D = sqrt(2 (gamma^2 - 1) Q) = 8000 m/s,
// P_CJ = rho0 D^2 / (gamma + 1) = 25.6 GPa.
std::shared_ptr<const Material> gamma_law_explosive() {
  Parameters eos;
  eos.set_string("type", "jwl");
  eos.set_number("density", 1600.0);
  eos.set_number("c1", 0.0);
  eos.set_number("c2", 0.0);
  eos.set_number("r1", 1.0);
  eos.set_number("r2", 1.0);
  eos.set_number("omega", 2.0);
  eos.set_number("e0", 1600.0 * 4.0e6);
  return make_material("gamma3", "", {}, eos, Parameters{}, Parameters{});
}

std::shared_ptr<const Material> tnt() {
  return make_material("tnt", "tnt_wang2005", {}, Parameters{}, Parameters{}, Parameters{});
}

// The products at rest behind the Taylor wave: from the CJ state down the
// isentrope (de = p d rho / rho^2) until the Riemann invariant has spent the
// CJ particle velocity, u_CJ = integral of c d rho / rho (RK4 in rho).
double plateau_pressure(const JwlEos& eos) {
  const CjState& cj = eos.cj_state();
  const double rho0 = eos.parameters().density;
  double rho = cj.density;
  double e = eos.parameters().e0 / rho0 + 0.5 * cj.pressure * (1.0 / rho0 - 1.0 / cj.density);
  double spent = 0.0;
  const double h = -1e-5 * cj.density;
  const auto de = [&](double r, double ee) { return eos.products_pressure(r, ee) / (r * r); };
  const auto du = [&](double r, double ee) { return std::sqrt(eos.products_sound_speed_squared(r, ee)) / r; };
  while (true) {
    const double k1 = de(rho, e), k2 = de(rho + 0.5 * h, e + 0.5 * h * k1), k3 = de(rho + 0.5 * h, e + 0.5 * h * k2),
                 k4 = de(rho + h, e + h * k3);
    const double step_u = -h / 6.0 * (du(rho, e) + 4.0 * du(rho + 0.5 * h, e + 0.5 * h * k1) + du(rho + h, e + h * k3));
    if (spent + step_u >= cj.particle_velocity) {
      const double f = (cj.particle_velocity - spent) / step_u;
      return eos.products_pressure(rho + f * h, e + f * h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
    }
    spent += step_u;
    e += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    rho += h;
  }
}

struct RefinementResult {
  double dx = 0.0;                // m
  double plateau = 0.0;           // Pa, mean over x/t in [0.1, 0.4] D at the end
  double worst_front_lag = 0.0;   // cells, largest |D t - x_front| / dx over the output times
  double peak_near = 0.0;         // Pa, highest pressure seen by the elements at 20-45 % of the column
  double peak_far = 0.0;          // Pa, the same at 55-80 %
  double min_dt_ratio = 0.0;      // smallest dt / (cfl dx / c_unburnt)
  double energy_error = 0.0;
};

RefinementResult run_column(const std::shared_ptr<const Material>& explosive, int cells) {
  const double dx = column_length / cells;
  Model model = test::detonation_column_model("he", explosive, column_length, cells);
  const auto& eos = dynamic_cast<const JwlEos&>(explosive->eos());
  const double d = eos.detonation_velocity(), p_cj = eos.cj_state().pressure;
  const double rho0 = eos.parameters().density;
  const double c_unburnt = std::sqrt(eos.products_sound_speed_squared(rho0, eos.parameters().e0 / rho0));
  const double dt_unburnt = model.run.cfl * dx / c_unburnt;
  model.run.end_time = 0.9 * column_length / d;

  Solver<2> solver(model);
  RefinementResult r;
  r.dx = dx;
  r.min_dt_ratio = std::numeric_limits<double>::infinity();
  std::vector<double> peak(static_cast<std::size_t>(cells), 0.0), xc(static_cast<std::size_t>(cells));
  const auto centres = [&] {
    const auto& conn = solver.elements().connectivity;
    for (std::size_t e = 0; e < xc.size(); ++e) {
      xc[e] = 0.0;
      for (std::size_t a = 0; a < 4; ++a) xc[e] += 0.25 * solver.position()[static_cast<std::size_t>(conn[4 * e + a]) * 2];
    }
  };
  int next_output = 1;
  while (solver.time() < model.run.end_time) {
    if (solver.cycle() > 40 * cells) throw std::runtime_error("detonation column: too many cycles");
    // The front is read at the first cycle past each output time (landing on
    // it would cut a step short and take the growth limit's steps after it).
    const double output_time = 0.1 * next_output * model.run.end_time;
    if (solver.time() > 0.0) r.min_dt_ratio = std::min(r.min_dt_ratio, solver.time_step_limit().dt / dt_unburnt);
    solver.step();
    const std::vector<double>& p = solver.batches()[0].pressure;
    for (std::size_t e = 0; e < peak.size(); ++e) peak[e] = std::max(peak[e], p[e]);
    if (solver.time() >= output_time) {
      // The front: the farthest crossing of P_CJ / 2, between element centres.
      centres();
      double x_front = 0.0;
      for (std::size_t e = 0; e + 1 < xc.size(); ++e)
        if (p[e] >= 0.5 * p_cj && p[e + 1] < 0.5 * p_cj)
          x_front = xc[e] + (p[e] - 0.5 * p_cj) / (p[e] - p[e + 1]) * (xc[e + 1] - xc[e]);
      r.worst_front_lag = std::max(r.worst_front_lag, std::abs(d * solver.time() - x_front) / dx);
      ++next_output;
    }
  }
  // Rest region: x/t in [0.1, 0.4] D.
  centres();
  double sum = 0.0;
  int count = 0;
  for (std::size_t e = 0; e < xc.size(); ++e)
    if (xc[e] > 0.1 * d * solver.time() && xc[e] < 0.4 * d * solver.time()) {
      sum += solver.batches()[0].pressure[e];
      ++count;
    }
  r.plateau = sum / count;
  for (std::size_t e = 0; e < peak.size(); ++e) {
    const double f = (static_cast<double>(e) + 0.5) / cells;
    if (f > 0.2 && f < 0.45) r.peak_near = std::max(r.peak_near, peak[e]);
    if (f > 0.55 && f < 0.8) r.peak_far = std::max(r.peak_far, peak[e]);
  }
  r.energy_error = solver.energy().relative_error;
  return r;
}

void check_refinement(const std::string& name, const std::shared_ptr<const Material>& explosive) {
  test::use_threads(1);
  const auto& eos = dynamic_cast<const JwlEos&>(explosive->eos());
  const double p_cj = eos.cj_state().pressure, plateau = plateau_pressure(eos);
  for (int cells : {200, 400, 800}) {
    const RefinementResult r = run_column(explosive, cells);
    const std::string res = fmt::format("{}, FEM {:.2f} mm cells", name, r.dx * 1e3);
    fmt::print("{}: plateau {:.4g} Pa (exact {:.4g}), front lag {:.2f} cells, peaks {:.3f} / {:.3f} P_CJ, "
               "min dt {:.3f} of the unburnt CFL step, energy error {:.2e}\n",
               res, r.plateau, plateau, r.worst_front_lag, r.peak_near / p_cj, r.peak_far / p_cj, r.min_dt_ratio,
               r.energy_error);
    test::verify({"1-D detonation from a wall (" + res + "): plateau pressure at rest behind the Taylor wave",
                  "CJ isentrope at u = 0 (Fickett & Davis 1979)", plateau, r.plateau, 0.01, true, "Pa"});
    test::verify({"1-D detonation from a wall (" + res + "): largest |D t - x(P_CJ/2)| over 10 output times",
                  "within one cell", 0.0, r.worst_front_lag, 1.0, false, "cells"});
    // Programmed burn has no von Neumann spike: the CJ pressure is the top of the wave.
    test::verify({"1-D detonation from a wall (" + res + "): peak pressure at 55-80 % of the column / P_CJ",
                  "the CJ pressure within 5 %", 1.0, r.peak_far / p_cj, 0.05, true, ""});
    test::verify({"1-D detonation from a wall (" + res + "): peak pressure at 55-80 % / at 20-45 % of the column",
                  "no growth with travel (at most 1.05)", 1.0, r.peak_far / r.peak_near, 0.05, false, ""});
    test::verify({"1-D detonation from a wall (" + res + "): smallest time step / CFL step of the unburnt explosive",
                  "at least 0.2", 1.0, r.min_dt_ratio, 0.8, false, ""});
    EXPECT_LT(r.energy_error, 0.01) << res;
  }
}

}  // namespace

TEST(DetonationRefinement, GammaLawPlateauExactIsentrope) {
  // The integration against the closed form for gamma = 3: p0 = P_CJ ((gamma+1)/(2 gamma))^(2 gamma/(gamma-1)).
  const auto explosive = gamma_law_explosive();
  const auto& eos = dynamic_cast<const JwlEos&>(explosive->eos());
  EXPECT_NEAR(eos.detonation_velocity(), 8000.0, 1.0);
  const double exact = eos.cj_state().pressure * std::pow(4.0 / 6.0, 3.0);
  EXPECT_NEAR(plateau_pressure(eos), exact, 1e-4 * exact);
}

TEST(DetonationRefinement, GammaLawExplosiveAtThreeResolutions) {
  check_refinement("gamma-law explosive (gamma = 3)", gamma_law_explosive());
}

TEST(DetonationRefinement, TntAtThreeResolutions) {
  check_refinement("TNT (Wang 2005 Table 5)", tnt());
}
