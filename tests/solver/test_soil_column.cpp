// 1-D uniaxial-strain soil column hit by a pressure pulse:
// the shock runs at the Rankine-Hugoniot speed of the model's own loading
// curve p(rho), and once the (much faster) release from the end of the pulse
// overtakes it, the peak stress decays with distance.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "materials/registry.hpp"
#include "materials/sandy_clay_preset.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

// Hydrodynamic sandy clay (three-phase EOS alone), so sigma_xx = -p and the
// jump conditions involve the EOS only.
std::shared_ptr<const Material> soil_eos_only() {
  const MaterialPreset p = sandy_clay_wang2005();
  return make_material("soil", "", {}, p.eos, Parameters{}, Parameters{});
}

// Loading-curve pressure at density rho (predictor call: history untouched).
double loading_pressure(const Material& m, double rho) {
  MaterialPoints pts;
  m.setup(pts, 1);
  pts.density[0] = rho;
  m.eos().evaluate(pts, MaterialContext{}, false);
  return pts.pressure[0];
}

TEST(SoilColumn, ShockSpeedAndAttenuation) {
  test::use_threads(1);
  const auto soil = soil_eos_only();
  const double rho0 = soil->reference_density();
  const double load = 50e6;        // Pa, pulse amplitude
  const double duration = 0.4e-3;  // s, pulse length
  const double length = 1.5, cell = 2.5e-3;
  const int cells = static_cast<int>(std::lround(length / cell));

  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  add_block(model.mesh, {"column", 0, {0, 0, 0}, {length, cell, cell}, {cells, 1, 1}});
  model.materials.push_back({"soil", soil, {}});
  Part part;
  part.name = "column";
  part.material = 0;
  model.parts.push_back(part);
  model.boundaries.push_back(test::pressure(
      "column.xmin", load, TimeHistory{{0.0, duration, duration + 1e-5, 1.0}, {1.0, 1.0, 0.0, 0.0}}));
  model.boundaries.push_back(test::symmetry("column.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("column.ymax", {0, 1, 0}));
  model.run.end_time = 3.5e-3;
  // The released soil is 39 times stiffer than on loading (unloading rule of
  // docs/theory/three-phase-soil.md): behind the viscous shock each element
  // rings on that stiff branch at the 2-cell mode. A linear viscosity of 0.3
  // (default 0.06) damps the ringing without touching the jump conditions.
  model.run.viscosity_linear = 0.3;
  Solver<2> solver(model);

  // Element stations: arrival = first time sigma_xx <= -load/2; peak = max compression.
  const std::vector<double> stations{0.10, 0.30, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
  std::vector<double> history_time, history_stress;  // first station
  std::vector<std::size_t> element(stations.size());
  std::vector<double> arrival(stations.size(), 0.0), peak(stations.size(), 0.0),
      previous(stations.size(), 0.0);
  for (std::size_t s = 0; s < stations.size(); ++s) element[s] = static_cast<std::size_t>(stations[s] / cell);
  double t_prev = 0.0;
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    for (std::size_t s = 0; s < stations.size(); ++s) {
      const double stress = -solver.elements().stress[element[s]].xx;  // compression positive
      if (arrival[s] == 0.0 && stress >= 0.5 * load)
        arrival[s] = t_prev + (0.5 * load - previous[s]) / (stress - previous[s]) * (solver.time() - t_prev);
      peak[s] = std::max(peak[s], stress);
      previous[s] = stress;
    }
    t_prev = solver.time();
    history_time.push_back(solver.time());
    history_stress.push_back(previous[0]);
  }

  // Rankine-Hugoniot from the model's loading curve: state behind a shock of
  // amplitude `load` into soil at rest, U_s = sqrt(p1 / (rho0 (1 - rho0/rho1))).
  double lo = rho0, hi = 2.0 * rho0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (loading_pressure(*soil, mid) < load ? lo : hi) = mid;
  }
  const double rho1 = 0.5 * (lo + hi);
  const double shock_speed = std::sqrt(load / (rho0 * (1.0 - rho0 / rho1)));
  const double measured = (stations[1] - stations[0]) / (arrival[1] - arrival[0]);
  test::verify({"Soil column, 50 MPa pulse: shock speed between 0.10 and 0.30 m",
                "Rankine-Hugoniot speed of the model's loading curve", shock_speed, measured, 0.03, true,
                "m/s"});
  // State behind the shock: mean stress over 0.1 ms after the front passed 0.1 m.
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < history_time.size(); ++k)
    if (history_time[k] > arrival[0] + 2e-5 && history_time[k] < arrival[0] + 1.2e-4) {
      sum += history_stress[k];
      ++count;
    }
  test::verify({"Soil column, 50 MPa pulse: stress behind the shock at 0.1 m (0.1 ms mean)",
                "the applied pressure (Rankine-Hugoniot state)", load, sum / count, 0.05, true, "Pa"});
  // Peak stress decays with distance once the release overtakes the shock.
  // It decays in steps: the release is so stiff that the loaded end comes to
  // rest (and spalls at the cut-off) while the soil ahead still moves, so the
  // shock runs on as a plateau until the next release (theory section, §3).
  // Hence "never increases" (1 % for the ringing) and "halves from 0.4 to 0.9 m".
  bool decays = true;
  std::string peaks;
  for (std::size_t s = 2; s < stations.size(); ++s) {
    if (s > 2) decays = decays && peak[s] <= 1.01 * peak[s - 1];
    peaks += fmt::format("{}{:.1f} MPa at {:.1f} m", s > 2 ? ", " : "", peak[s] / 1e6, stations[s]);
  }
  test::record_check("Soil column, 50 MPa, 0.4 ms pulse: peak stress vs distance",
                     "non-increasing from 0.4 to 0.9 m and below half at 0.9 m", peaks,
                     decays && peak.back() < 0.5 * peak[2]);
  EXPECT_TRUE(decays) << peaks;
  EXPECT_LT(peak.back(), 0.5 * peak[2]) << peaks;
}

}  // namespace
