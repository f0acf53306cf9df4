// 1-D planar detonation along a TNT column in FEM:
// the seed paper's TNT (Table 5, JWL + programmed burn with
// the default burn width) in a plane-strain column one element across,
// rollers on the long sides and a rigid wall at the lit end, lit at x = 0 at
// t = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "common/fem_models.hpp"
#include "detonation_column.hpp"
#include "common/verification.hpp"
#include "materials/jwl_eos.hpp"
#include "materials/registry.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

constexpr double kLength = 0.1;  // m

struct ColumnResult {
  double front_speed = 0.0;  // m/s
  double peak_mid = 0.0;     // Pa, largest pressure of the mid-column element
  double p_cj = 0.0;         // Pa
  double detonation_velocity = 0.0;
  EnergyBalance energy;
  double time = 0.0;                // s, end of the run
  std::vector<double> x, pressure;  // element centres (m, current) and pressures (Pa) at the end
};

ColumnResult run_column(int cells) {
  const double dx = kLength / cells;
  Model model = test::detonation_column_model(
      "tnt", make_material("tnt", "tnt_wang2005", {}, Parameters{}, Parameters{}, Parameters{}), kLength, cells);

  const auto& jwl = dynamic_cast<const JwlEos&>(model.materials[0].material->eos());
  ColumnResult r;
  r.detonation_velocity = jwl.detonation_velocity();
  r.p_cj = jwl.cj_state().pressure;
  model.run.end_time = 0.9 * kLength / r.detonation_velocity;
  Solver<2> solver(model);

  // Arrival of the front at each element (elements run along x, one per
  // cell): the first time its pressure exceeds P_CJ / 2.
  std::vector<double> arrival(static_cast<std::size_t>(cells), -1.0);
  const std::size_t mid = static_cast<std::size_t>(cells / 2);
  while (solver.time() < model.run.end_time) {
    if (solver.cycle() > 100 * cells) throw std::runtime_error("detonation column: too many cycles");
    solver.step();
    const MaterialPoints& pts = solver.batches()[0];
    for (std::size_t e = 0; e < arrival.size(); ++e)
      if (arrival[e] < 0.0 && pts.pressure[e] > 0.5 * r.p_cj) arrival[e] = solver.time();
    r.peak_mid = std::max(r.peak_mid, pts.pressure[mid]);
  }
  // Front speed: least-squares slope of x against arrival time between 30 %
  // and 80 % of the column (past the start-up, before the end of the run).
  double st = 0, sx = 0, stt = 0, stx = 0;
  int n = 0;
  for (int e = static_cast<int>(0.3 * cells); e < static_cast<int>(0.8 * cells); ++e) {
    const double t = arrival[static_cast<std::size_t>(e)], x = (e + 0.5) * dx;
    if (t < 0.0)
      throw std::runtime_error("detonation column: the front did not reach element " + std::to_string(e));
    st += t;
    sx += x;
    stt += t * t;
    stx += t * x;
    ++n;
  }
  r.front_speed = (n * stx - st * sx) / (n * stt - st * st);
  r.energy = solver.energy();
  r.time = solver.time();
  const auto& conn = solver.elements().connectivity;
  for (std::size_t e = 0; e < arrival.size(); ++e) {
    double xc = 0.0;
    for (std::size_t a = 0; a < 4; ++a)
      xc += 0.25 * solver.position()[static_cast<std::size_t>(conn[4 * e + a]) * 2];
    r.x.push_back(xc);
    r.pressure.push_back(solver.batches()[0].pressure[e]);
  }
  return r;
}

}  // namespace

TEST(DetonationColumn, FrontSpeedPeakPressureAndEnergy) {
  test::use_threads(1);
  for (int cells : {100, 200}) {
    const ColumnResult r = run_column(cells);
    const std::string res = std::to_string(1000.0 * kLength / cells).substr(0, 4) + " mm";
    test::verify({"1-D TNT detonation column (FEM, " + res + "): front speed",
                  "D = 6930 m/s (Wang 2005 Table 5)", 6930.0, r.front_speed, 0.02, true, "m/s"});
    // The peak must lie within 80 % .. 110 % of P_CJ: centre 0.95, half-width 0.15.
    test::verify({"1-D TNT detonation column (FEM, " + res + "): peak mid-column pressure / P_CJ",
                  "0.8 .. 1.1", 0.95, r.peak_mid / r.p_cj, 0.15 / 0.95, true, ""});
    // The chemical energy is internal energy from the start (e0 / rho0); the
    // detonation turns part of it into kinetic energy and the total must hold.
    test::verify({"1-D TNT detonation column (FEM, " + res + "): energy balance",
                  "total energy conserved within 1 % of the chemical energy", 0.0, r.energy.relative_error,
                  0.01, false, "relative"});
    EXPECT_GT(r.energy.kinetic, 0.05 * r.energy.initial_total);
  }
}

TEST(DetonationColumn, TaylorWaveAgainstGammaLawSolution) {
  // Self-similar Taylor wave behind a CJ detonation running from a rigid wall
  // (Fickett & Davis 1979, sec. 2A; Zel'dovich & Kompaneets 1960) for a
  // gamma-law explosive with the same D and P_CJ: gamma = rho0 D^2 / P_CJ - 1,
  // products at rest for x/t < D/2, and in the fan
  //   c(x/t) = ((gamma - 1) x/t + D) / (gamma + 1),  p = P_CJ (c / c_CJ)^(2 gamma / (gamma - 1)),
  // c_CJ = gamma D / (gamma + 1). The JWL isentrope is not a gamma law, so the
  // profile agrees only approximately: 10 % of P_CJ over the rest region and
  // the fan (x/t from 0.2 D to 0.9 D, clear of the smeared front).
  test::use_threads(1);
  const ColumnResult r = run_column(200);
  const double d = r.detonation_velocity, rho0 = 1630.0;
  const double gamma = rho0 * d * d / r.p_cj - 1.0;
  const double c_cj = gamma * d / (gamma + 1.0);
  auto taylor = [&](double xi) {
    const double c = ((gamma - 1.0) * std::max(xi, 0.5 * d) + d) / (gamma + 1.0);
    return r.p_cj * std::pow(c / c_cj, 2.0 * gamma / (gamma - 1.0));
  };
  double worst = 0.0, worst_xi = 0.0;
  for (std::size_t e = 0; e < r.x.size(); ++e) {
    const double xi = r.x[e] / r.time;
    if (xi < 0.2 * d || xi > 0.9 * d) continue;
    const double err = std::abs(r.pressure[e] - taylor(xi)) / r.p_cj;
    if (err > worst) {
      worst = err;
      worst_xi = xi / d;
    }
  }
  test::verify(
      {"1-D TNT detonation column (FEM, 0.5 mm): Taylor wave, largest pressure error / P_CJ for x/t in "
       "[0.2, 0.9] D (worst at x/t = " +
           std::to_string(worst_xi).substr(0, 4) + " D)",
       "gamma-law self-similar solution with the same D and P_CJ", 0.0, worst, 0.10, false, "P_CJ"});
  // The rest region next to the wall: p0 = P_CJ ((gamma + 1) / (2 gamma))^(2 gamma / (gamma - 1)).
  double wall_p = 0.0;
  int count = 0;
  for (std::size_t e = 0; e < r.x.size(); ++e)
    if (r.x[e] / r.time > 0.1 * d && r.x[e] / r.time < 0.4 * d) {
      wall_p += r.pressure[e];
      ++count;
    }
  test::verify({"1-D TNT detonation column (FEM, 0.5 mm): Taylor wave, plateau pressure behind the wave",
                "gamma-law: P_CJ ((gamma+1)/(2 gamma))^(2 gamma/(gamma-1))", taylor(0.0), wall_p / count,
                0.15, true, "Pa"});
}
