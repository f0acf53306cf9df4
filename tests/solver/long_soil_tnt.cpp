// Spherical TNT charge fully contained in the sandy clay:
// peak radial stress against scaled distance Z = R / W^(1/3) compared with
// the TM 5-855-1 band of the seed paper's Fig. 8b (Functions 1 and 2 with its
// coupling factor f = 0.6). FEM only: a spherical wedge (1-D spherical flow) in
// axisymmetric quad4 elements, mapped from a (R, phi) block onto
// r = R cos(phi), z = R sin(phi), with symmetry planes on its two radial sides.
// Why the band is missed: docs/theory/three-phase-soil.md, section 12.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "materials/registry.hpp"
#include "mesh/block_generator.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

std::shared_ptr<const Material> preset(const std::string& name) {
  return make_material(name, name, {}, Parameters{}, Parameters{}, Parameters{});
}

struct GroundShock {
  std::vector<double> scaled;    // m/kg^(1/3)
  std::vector<double> peak;      // Pa, peak radial compression
  std::vector<double> velocity;  // m/s, peak outward radial particle velocity
  std::vector<double> last;      // Pa, radial compression at the end of the run
};

// Mesh and duration of one run. Table 2: 3 mm soil cells at the charge, 3 m
// outer radius, 9 ms (its slow wave, c_p = 336 m/s, passes Z = 2.5 by 7 ms).
// The seismic preset's wave (c_p = 1400 m/s) passes Z = 2.5 by about 2 ms;
// its stiff skeleton makes the soil cell at the cavity wall, which thins as
// the cavity grows, set a step of a few ns, so that run uses 6 mm cells at the
// charge (the 1-D runs of theory section 12.1: 3 mm raised the peaks by
// <= 8 %), a 4 m outer radius (the free outer edge's tensile reflection comes
// back to Z = 2.5 after 3.9 ms) and ends at 3.2 ms.
struct WedgeRun {
  double first_cell = 3.0e-3;  // m, soil cell at the charge
  double outer = 3.0;          // m, outer radius (free)
  double end_time = 9e-3;      // s
};

// One run per soil preset, shared by the tests below: Table 2 about 12 minutes on a
// shared core; the seismic preset a few minutes (theory section 12.4).
GroundShock run_ground_shock(const std::string& soil_preset, const WedgeRun& setup) {
  test::use_threads(1);            // a few hundred elements: a thread team costs more than it gains
  const double charge_mass = 1.0;  // kg TNT
  const double tnt_density = 1630.0;
  const double charge_radius = std::cbrt(3.0 * charge_mass / (4.0 * std::numbers::pi * tnt_density));
  const double outer = setup.outer;  // m: the reflection from the outer edge reaches Z = 2.5 after its peak
  // A 10-degree wedge: the chord/arc error (0.13 %) is uniform, and the
  // elements at the centre are not so thin that they set a tiny time step.
  const double phi1 = 40.0 * std::numbers::pi / 180.0, phi2 = 50.0 * std::numbers::pi / 180.0;
  const double inner = 0.1 * charge_radius;  // small cavity at the centre (the map is singular at R = 0)

  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  model.mesh.dimension = 2;
  add_block(model.mesh, {"charge", 0, {inner, phi1, 0}, {charge_radius - inner, phi2 - phi1, 0}, {15, 1, 1}});
  const double first = setup.first_cell, last = 30e-3;  // m, soil cell sizes at the charge and far out
  const double grading = last / first;
  const int soil_cells =
      static_cast<int>(std::lround((outer - charge_radius) * std::log(grading) / (last - first)));
  add_block(model.mesh, {"soil",
                         1,
                         {charge_radius, phi1, 0},
                         {outer - charge_radius, phi2 - phi1, 0},
                         {soil_cells, 1, 1},
                         {grading, 1, 1}});
  for (std::size_t n = 0; n < model.mesh.node_count(); ++n) {
    const double radius = model.mesh.coordinates[2 * n], phi = model.mesh.coordinates[2 * n + 1];
    model.mesh.coordinates[2 * n] = radius * std::cos(phi);
    model.mesh.coordinates[2 * n + 1] = radius * std::sin(phi);
  }
  model.materials.push_back({"tnt", preset("tnt_wang2005"), {}});
  model.materials.push_back({"soil", preset(soil_preset), {}});
  for (int m = 0; m < 2; ++m) {
    Part part;
    part.name = m == 0 ? "charge" : "soil";
    part.material = m;
    model.parts.push_back(part);
  }
  for (const char* block : {"charge", "soil"}) {
    model.boundaries.push_back(
        test::symmetry(std::string(block) + ".ymin", {-std::sin(phi1), std::cos(phi1), 0}));
    model.boundaries.push_back(
        test::symmetry(std::string(block) + ".ymax", {-std::sin(phi2), std::cos(phi2), 0}));
  }
  model.detonations.push_back(DetonationPoint{{0.0, 0.0, 0.0}, 0.0});
  model.detonation_where.push_back({});
  model.run.end_time = setup.end_time;
  model.run.viscosity_linear = 0.3;  // see test_soil_column.cpp
  Solver<2> solver(model);

  // Soil elements nearest each scaled distance; peak radial (compressive) stress.
  const std::vector<double> scaled{0.3, 0.4, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5};
  std::vector<std::size_t> element(scaled.size());
  std::vector<double> peak(scaled.size(), 0.0), velocity(scaled.size(), 0.0);
  const auto& el = solver.elements();
  auto centre_radius = [&](std::size_t e) {
    double r = 0.0, z = 0.0;
    for (int k = 0; k < 4; ++k) {
      const auto node = static_cast<std::size_t>(el.connectivity[e * 4 + static_cast<std::size_t>(k)]);
      r += 0.25 * solver.position()[2 * node];
      z += 0.25 * solver.position()[2 * node + 1];
    }
    return std::hypot(r, z);
  };
  for (std::size_t s = 0; s < scaled.size(); ++s) {
    const double target = scaled[s] * std::cbrt(charge_mass);
    std::size_t best = 0;
    for (std::size_t e = 0; e < el.size(); ++e)
      if (std::abs(centre_radius(e) - target) < std::abs(centre_radius(best) - target)) best = e;
    element[s] = best;
  }
  const double c = std::cos(0.5 * (phi1 + phi2)), sn = std::sin(0.5 * (phi1 + phi2));
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    if (solver.cycle() % 100000 == 0)
      fmt::print(stderr, "cycle {} t = {:.3e} s, dt = {:.2e} s ({})\n", solver.cycle(), solver.time(),
                 solver.time_step_limit().dt, solver.time_step_limit().reason);
    for (std::size_t s = 0; s < scaled.size(); ++s) {
      const SymTensor& sigma = el.stress[element[s]];
      const double radial = c * c * sigma.xx + 2.0 * c * sn * sigma.xy + sn * sn * sigma.yy;
      peak[s] = std::max(peak[s], -radial);
      double u = 0.0;
      for (int k = 0; k < 4; ++k) {
        const auto node =
            static_cast<std::size_t>(el.connectivity[element[s] * 4 + static_cast<std::size_t>(k)]);
        u += 0.25 * (c * solver.velocity()[2 * node] + sn * solver.velocity()[2 * node + 1]);
      }
      velocity[s] = std::max(velocity[s], u);
    }
  }

  std::vector<double> final_stress(scaled.size());
  for (std::size_t s = 0; s < scaled.size(); ++s) {
    const SymTensor& sigma = el.stress[element[s]];
    final_stress[s] = -(c * c * sigma.xx + 2.0 * c * sn * sigma.xy + sn * sn * sigma.yy);
  }
  fmt::print(stderr, "{}: {} cycles to {:.3e} s\n", soil_preset, solver.cycle(), solver.time());
  return GroundShock{scaled, peak, velocity, final_stress};
}

// Table 2 as printed.
const GroundShock& ground_shock() {
  static const GroundShock result = run_ground_shock("sandy_clay_wang2005", WedgeRun{});
  return result;
}
// K_p calibrated to Table 1's seismic velocity (theory section 12).
const GroundShock& seismic_ground_shock() {
  static const GroundShock result =
      run_ground_shock("sandy_clay_wang2005_seismic", WedgeRun{6.0e-3, 4.0, 3.2e-3});
  return result;
}

// TM 5-855-1 Functions 1 and 2 (15 Z^-2.5 and 22 Z^-2 MPa) times a coupling
// factor f, widened by a factor 1.5 either way: f = 0.6 as Wang et al. 2005
// use it (eqs. 38-39, Fig. 8b), f = 1 for a fully
// contained charge.
constexpr double paper_coupling = 0.6, contained_coupling = 1.0;
double band_low(double z, double coupling = paper_coupling) {
  return coupling * std::min(15e6 * std::pow(z, -2.5), 22e6 * std::pow(z, -2.0)) / 1.5;
}
double band_high(double z, double coupling = paper_coupling) {
  return coupling * std::max(15e6 * std::pow(z, -2.5), 22e6 * std::pow(z, -2.0)) * 1.5;
}

std::string table(const GroundShock& g, double coupling = paper_coupling) {
  std::string t;
  for (std::size_t s = 0; s < g.scaled.size(); ++s)
    t += fmt::format("Z={:.2f}: {:.2f} MPa, {:.2f} m/s (band {:.2f}-{:.2f} MPa); ", g.scaled[s],
                     g.peak[s] / 1e6, g.velocity[s], band_low(g.scaled[s], coupling) / 1e6,
                     band_high(g.scaled[s], coupling) / 1e6);
  return t;
}

// Every gauge inside the band of coupling factor f; the gauges outside it listed.
bool within_band(const GroundShock& g, double coupling, std::string& outside) {
  bool in_band = true;
  for (std::size_t s = 0; s < g.scaled.size(); ++s) {
    const double low = band_low(g.scaled[s], coupling), high = band_high(g.scaled[s], coupling);
    if (g.peak[s] >= low && g.peak[s] <= high) continue;
    in_band = false;
    outside += fmt::format(" Z={:.2f}: {:.3g} x {} edge;", g.scaled[s],
                           g.peak[s] < low ? g.peak[s] / low : g.peak[s] / high,
                           g.peak[s] < low ? "lower" : "upper");
  }
  return in_band;
}

// Attenuation: least-squares slope of ln(peak) against ln(Z) over Z = 0.5-2.5.
double attenuation_exponent(const GroundShock& g) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (std::size_t s = 0; s < g.scaled.size(); ++s) {
    if (g.scaled[s] < 0.5) continue;  // the TM-5 fit's range here, Z = 0.5-2.5
    n += 1.0;
    const double lx = std::log(g.scaled[s]), ly = std::log(g.peak[s]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST(SoilTnt, AttenuationExponentAsTm5) {
  const GroundShock& g = ground_shock();
  const double exponent = attenuation_exponent(g);
  fmt::print("{}\nfitted attenuation exponent {:.3f}\n", table(g), exponent);
  test::record_check(
      "TNT (1 kg) contained in sandy clay, FEM wedge: attenuation exponent of the peak radial stress, "
      "Z = 0.5-2.5 m/kg^(1/3)",
      "between 2 and 2.8 (TM 5-855-1; Table 1: 2-2.5)", fmt::format("n = {:.3f}", exponent),
      exponent >= 2.0 && exponent <= 2.8);
}

// The far field carries the model's own loading impedance: peak stress over
// peak particle velocity is rho0 c_p with c_p the small-strain P-wave speed of
// the loading branch (plane-wave relation sigma = rho c u, which TM 5-855-1
// writes with the soil's seismic velocity). This is why the model misses the
// band: rho0 c_p = 0.64 MPa s/m against rho c = 2.69 MPa s/m of Table 1.
TEST(SoilTnt, FarFieldStressOverVelocityIsTheLoadingImpedance) {
  const GroundShock& g = ground_shock();
  const double rho0 = 1917.05;  // kg/m^3, sandy_clay_wang2005
  const double k0 = 143.26e6;   // Pa, initial tangent bulk modulus (theory section 5)
  const double shear = 55e6;    // Pa, Table 2
  const double impedance = std::sqrt(rho0 * (k0 + 4.0 / 3.0 * shear));  // rho0 c_p, Pa s/m
  double sum = 0.0;
  int count = 0;
  for (std::size_t s = 0; s < g.scaled.size(); ++s)
    if (g.scaled[s] >= 0.75 && g.scaled[s] <= 2.0) {
      sum += g.peak[s] / g.velocity[s];
      ++count;
    }
  test::verify({"TNT (1 kg) contained in sandy clay, FEM wedge: peak stress / peak velocity, Z = 0.75-2",
                "rho0 c_p of the loading branch (0.644 MPa s/m; Table 1's rho c is 2.69)", impedance,
                sum / count, 0.2, true, "Pa s/m"});
}

// With the paper's Table 2 the peaks lie a factor 1.9-3.3 below the band for Z = 0.4-2.5
// (docs/theory/three-phase-soil.md, section 12): the comparison is recorded, not asserted.
TEST(SoilTnt, PeakStressAgainstTm5BandRecorded) {
  const GroundShock& g = ground_shock();
  bool in_band = true;
  for (std::size_t s = 0; s < g.scaled.size(); ++s)
    in_band = in_band && g.peak[s] >= band_low(g.scaled[s]) && g.peak[s] <= band_high(g.scaled[s]);
  test::record_observation(
      "TNT (1 kg) contained in sandy clay (Table 2 as printed), FEM wedge: peak radial stress vs Z = 0.3-2.5 "
      "m/kg^(1/3)",
      "TM 5-855-1 band f (15 Z^-2.5 ... 22 Z^-2) MPa, f = 0.6, within a factor 1.5", table(g), in_band);
}

// The seismic preset's 6 mm cells against 3 mm (the Table 2 runs' size): the
// peaks the band tests use must not depend on the coarser cells. Measured
// 1 Dec 2026: within 2.5 % for Z >= 0.4 (Z = 1: 9.77 / 9.84 MPa, Z = 2:
// 2.48 / 2.44 MPa). Z = 0.3 is left out: the shock 0.25 m from the charge is
// not resolved at 6 mm, and its band verdict rests on the 6 mm value (theory
// section 12.4). With the time ramp alone over n_burn = 3 cells the burn of
// the coarser charge was spread over 18 mm and this test missed by 5.7 % at
// Z = 1 and 8.5 % at Z = 2; the volumetric burn with n_burn = 1.5
// (materials/programmed_burn.hpp) restored it.
const GroundShock& seismic_ground_shock_fine() {
  static const GroundShock result =
      run_ground_shock("sandy_clay_wang2005_seismic", WedgeRun{3.0e-3, 4.0, 3.2e-3});
  return result;
}

TEST(SoilTnt, SeismicPresetPeaksConvergedAtSixMillimetreCells) {
  const GroundShock& coarse = seismic_ground_shock();
  const GroundShock& fine = seismic_ground_shock_fine();
  fmt::print("3 mm cells: {}\n", table(fine));
  for (std::size_t s = 1; s < fine.scaled.size(); ++s)  // Z >= 0.4 (see above)
    test::verify(
        {fmt::format("TNT (1 kg) in the seismic sandy clay, FEM wedge: peak radial stress at Z = {:.2f} "
                     "with 6 mm cells at the charge",
                     fine.scaled[s]),
         "the same with 3 mm cells", fine.peak[s], coarse.peak[s], 0.05, true, "Pa"});
}

// The same soil with K_p calibrated to the seismic velocity (theory section
// 12.3), against the paper's band (f = 0.6).
TEST(SoilTnt, SeismicPresetPeakStressWithinTm5Band) {
  const GroundShock& g = seismic_ground_shock();
  std::string outside;
  const bool in_band = within_band(g, paper_coupling, outside);
  fmt::print("{}\nfitted attenuation exponent {:.3f}\n", table(g), attenuation_exponent(g));
  // The short run must have let the peak pass the farthest gauge.
  EXPECT_LT(g.last.back(), 0.5 * g.peak.back()) << "the wave has not passed Z = 2.5 by the end of the run";
  test::record_check(
      "TNT (1 kg) contained in sandy clay with K_p calibrated to c = 1400 m/s, FEM wedge: peak radial "
      "stress vs Z = 0.3-2.5 m/kg^(1/3)",
      "TM 5-855-1 band f (15 Z^-2.5 ... 22 Z^-2) MPa, f = 0.6 (W2005 Fig. 8b), within a factor 1.5",
      table(g) + (in_band ? "all inside" : "outside:" + outside), in_band);
}

// The TM 5-855-1 band with coupling factor 1 for a fully contained charge: the seismic preset
// lies below it at Z = 0.4-1 (0.70-0.97 of its lower edge; theory section 12.4). The cases keep
// f = 0.6 as the paper does; this comparison is recorded, not asserted.
TEST(SoilTnt, SeismicPresetPeakStressAgainstContainedBandRecorded) {
  const GroundShock& g = seismic_ground_shock();
  std::string outside;
  const bool in_band = within_band(g, contained_coupling, outside);
  fmt::print("{}\n", table(g, contained_coupling));
  test::record_observation(
      "TNT (1 kg) contained in sandy clay with K_p calibrated to c = 1400 m/s, FEM wedge: peak radial "
      "stress vs Z = 0.3-2.5 m/kg^(1/3)",
      "TM 5-855-1 band f (15 Z^-2.5 ... 22 Z^-2) MPa, f = 1 (fully contained), within a factor 1.5",
      table(g, contained_coupling) + (in_band ? "all inside" : "outside:" + outside), in_band);
}

// The 1-D runs of theory section 12.1 gave n = 1.88 (below 2-2.8); the FEM
// wedge gives n = 2.03 (section 12.4): just inside.
TEST(SoilTnt, SeismicPresetAttenuationExponentAsTm5) {
  const GroundShock& g = seismic_ground_shock();
  const double exponent = attenuation_exponent(g);
  test::record_check(
      "TNT (1 kg) contained in sandy clay with K_p calibrated to c = 1400 m/s, FEM wedge: attenuation "
      "exponent "
      "of the peak radial stress, Z = 0.5-2.5 m/kg^(1/3)",
      "between 2 and 2.8 (TM 5-855-1; Table 1: 2-2.5)", fmt::format("n = {:.3f}", exponent),
      exponent >= 2.0 && exponent <= 2.8);
}

}  // namespace
