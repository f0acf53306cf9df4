// Transmitting boundaries: Lysmer-Kuhlemeyer
// dashpots absorb a P-wave at normal incidence (reflection < 5 % of the
// incident amplitude), at 45 degrees (< 15 %), and a spherical wave in an
// axisymmetric quarter domain leaves < 5 % of its energy behind; the energy
// balance books the dashpot work.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

BoundaryCondition transmitting(const std::string& face_set) {
  BoundaryCondition bc;
  bc.kind = BoundaryKind::transmitting;
  bc.set = face_set;
  return bc;
}

// sin^2 pulse of duration T as a piecewise-linear history (scale 0..1..0).
TimeHistory sine_squared_pulse(double duration) {
  TimeHistory h;
  const int n = 40;
  for (int k = 0; k <= n; ++k) {
    const double s = static_cast<double>(k) / n;
    h.time.push_back(s * duration);
    h.value.push_back(std::pow(std::sin(std::numbers::pi * s), 2));
  }
  return h;
}

// Peak |v_x| at mid-column of the incident pulse and of what comes back from
// the far end (x = L), which is `far` (transmitting or fixed).
std::pair<double, double> column_reflection(bool absorbing) {
  test::use_threads(1);
  const ElasticConstants c;
  const double length = 1.0, cell = 5e-3, v0 = 1.0;
  const double c_p = c.p_wave_speed();
  const double duration = 0.1 / c_p;  // pulse 0.1 m long: 20 cells
  Model model = test::block_model(GeometryMode::plane_strain,
                                  {{"bar", 0, {0, 0, 0}, {length, cell, 0}, {200, 1, 1}}}, c);
  BoundaryCondition drive = test::velocity("bar.xmin", 0, v0);
  drive.history = sine_squared_pulse(duration);
  model.boundaries.push_back(drive);
  model.boundaries.push_back(test::symmetry("bar.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("bar.ymax", {0, 1, 0}));
  if (absorbing)
    model.boundaries.push_back(transmitting("bar.xmax"));
  else
    model.boundaries.push_back(test::velocity("bar.xmax", 0, 0.0));
  model.run.end_time = 2.4 * length / c_p;
  Solver<2> solver(model);
  std::size_t gauge = 0;
  for (std::size_t n = 0; n < solver.node_count(); ++n)
    if (std::abs(solver.position()[n * 2] - 0.5) < std::abs(solver.position()[gauge * 2] - 0.5)) gauge = n;
  const double split = 0.5 * length / c_p + 1.5 * duration;  // incident pulse has passed the gauge
  double incident = 0.0, reflected = 0.0;
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    const double v = std::abs(solver.velocity()[gauge * 2]);
    (solver.time() < split ? incident : reflected) =
        std::max(v, solver.time() < split ? incident : reflected);
  }
  return {incident, reflected};
}

// A plane P-pulse (initial velocity along n, Gaussian in (x - x0) . n) in a
// square, or a spherical one in an axisymmetric quarter domain; returns the
// energy left (kinetic + internal) over the initial kinetic energy, and the
// energy-balance error with the dashpot work booked.
struct EnergyLeft {
  double fraction = 0.0;
  double balance_error = 0.0;
};

EnergyLeft energy_left(GeometryMode mode, bool absorbing, double cell = 1.25e-2, double width = 0.04,
                       double end = 0.0, double angle = 45.0) {
  test::use_threads(1);
  const ElasticConstants c;
  const double size = 1.0;
  const int cells = static_cast<int>(std::lround(size / cell));
  Model model = test::block_model(mode, {{"box", 0, {0, 0, 0}, {size, size, 0}, {cells, cells, 1}}}, c);
  const bool axi = mode == GeometryMode::axisymmetric;
  if (axi) {
    BoundaryCondition axis;
    axis.kind = BoundaryKind::axis;
    axis.set = "box.xmin";
    model.boundaries.push_back(axis);
    model.boundaries.push_back(test::symmetry("box.ymin", {0, 1, 0}));
  }
  if (absorbing) {
    for (const char* f : {"box.xmax", "box.ymax"}) model.boundaries.push_back(transmitting(f));
    if (!axi)
      for (const char* f : {"box.xmin", "box.ymin"}) model.boundaries.push_back(transmitting(f));
  }
  const double c_p = c.p_wave_speed();  // width: m, Gaussian half width
  model.run.end_time = (end > 0.0 ? end : axi ? 1.8 : 1.0) * size / c_p;
  Solver<2> solver(model);
  auto& v = solver.velocity();
  double e0 = 0.0;
  for (std::size_t n = 0; n < solver.node_count(); ++n) {
    const double x = solver.position()[n * 2], y = solver.position()[n * 2 + 1];
    const double ang = angle * std::numbers::pi / 180.0;
    std::array<double, 2> dir{std::cos(ang), std::sin(ang)};
    double xi = (x - 0.5 * size) * dir[0] + (y - 0.5 * size) * dir[1];
    if (axi) {  // spherical shell of radius 0.2 m about the origin, radial velocity
      const double r = std::hypot(x, y);
      xi = r - 0.2;
      dir = r > 0.0 ? std::array<double, 2>{x / r, y / r} : std::array<double, 2>{0.0, 0.0};
    }
    const double amplitude = std::exp(-(xi * xi) / (width * width));
    for (int i = 0; i < 2; ++i)
      v[n * 2 + static_cast<std::size_t>(i)] = amplitude * dir[static_cast<std::size_t>(i)];
    e0 += 0.5 * solver.node_mass()[n] * amplitude * amplitude;
  }
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
  }
  const EnergyBalance& e = solver.energy();
  EnergyLeft r;
  r.fraction = (e.kinetic + e.internal) / e0;
  r.balance_error = std::abs(e.kinetic + e.internal + e.hourglass - e0 - e.boundary_work) / e0;
  return r;
}

// A plane P-pulse travelling along d = (1, -1)/sqrt(2) (initial velocity only:
// half of it goes along d) meets the bottom face of a 3 m x 1.5 m box at 45
// degrees; all faces transmit. At the gauge (1.6, 0.4) m the incident pulse
// peaks at 0.85 m / c_p, the reflected P pulse at 1.41 m / c_p, the
// mode-converted SV at 1.72 m / c_p and the diffraction from the ends of the
// truncated pulse at <= 1.1 or >= 1.65 m / c_p (image-point geometry).
std::pair<double, double> oblique_reflection() {
  test::use_threads(1);
  const ElasticConstants c;
  const double cell = 1e-2, width = 0.08;
  Model model =
      test::block_model(GeometryMode::plane_strain, {{"box", 0, {0, 0, 0}, {3.0, 1.5, 0}, {300, 150, 1}}}, c);
  for (const char* f : {"box.xmin", "box.xmax", "box.ymin", "box.ymax"})
    model.boundaries.push_back(transmitting(f));
  const double c_p = c.p_wave_speed();
  model.run.end_time = 1.55 / c_p;
  Solver<2> solver(model);
  const double d[2] = {1.0 / std::numbers::sqrt2, -1.0 / std::numbers::sqrt2};
  std::size_t gauge = 0;
  for (std::size_t n = 0; n < solver.node_count(); ++n) {
    const double x = solver.position()[n * 2], y = solver.position()[n * 2 + 1];
    const double xi = (x - 0.9) * d[0] + (y - 0.9) * d[1];
    const double g = std::exp(-(xi * xi) / (width * width));
    solver.velocity()[n * 2] = g * d[0];
    solver.velocity()[n * 2 + 1] = g * d[1];
    if (std::hypot(x - 1.6, y - 0.4) <
        std::hypot(solver.position()[gauge * 2] - 1.6, solver.position()[gauge * 2 + 1] - 0.4))
      gauge = n;
  }
  double incident = 0.0, reflected = 0.0;
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    const double t = solver.time() * c_p;  // m travelled
    const double v = std::hypot(solver.velocity()[gauge * 2], solver.velocity()[gauge * 2 + 1]);
    if (t > 0.6 && t < 1.05) incident = std::max(incident, v);
    if (t > 1.3 && t < 1.53) reflected = std::max(reflected, v);
  }
  std::printf("45 degrees: incident %.4f reflected P %.4f (cell %g m)\n", incident, reflected, cell);
  return {incident, reflected};
}

}  // namespace

TEST(TransmittingBoundary, NormalIncidencePlaneStrain) {
  const auto [incident, reflected] = column_reflection(true);
  const auto [incident_fixed, reflected_fixed] = column_reflection(false);
  test::verify({"Transmitting boundary, normal-incidence P-pulse: reflected / incident amplitude",
                "0 (Lysmer & Kuhlemeyer 1969: exact at normal incidence)", 0.0, reflected / incident, 0.05,
                false, "-"});
  // The same column with a fixed far end reflects the whole pulse: the measure sees reflections.
  test::verify({"Fixed far end (control): reflected / incident amplitude", "1 (total reflection)", 1.0,
                reflected_fixed / incident_fixed, 0.2, true, "-"});
}

TEST(TransmittingBoundary, ObliqueIncidence45Degrees) {
  const auto [incident, reflected] = oblique_reflection();
  test::verify({"Transmitting boundary, plane P-pulse at 45 degrees: reflected P / incident amplitude",
                "0 (< 0.15 required)", 0.0, reflected / incident, 0.15, false, "-"});
}

TEST(TransmittingBoundary, SphericalWaveAxisymmetricQuarter) {
  // Gaussian half width 0.12 m (12 cells), energy measured at t = 2 m / c_p.
  const EnergyLeft r = energy_left(GeometryMode::axisymmetric, true, 1e-2, 0.12, 2.0);
  test::verify({"Transmitting boundary, spherical pulse in an r-z quarter domain: energy left / initial",
                "0 (< 0.05 required)", 0.0, r.fraction, 0.05, false, "-"});
  test::verify({"Transmitting boundary, spherical pulse: energy balance with dashpot work", "0", 0.0,
                r.balance_error, 0.01, false, "-"});
  const EnergyLeft closed = energy_left(GeometryMode::axisymmetric, false, 1e-2, 0.12, 2.0);
  test::verify({"Closed quarter domain (control): energy left / initial", "1 (nothing leaves)", 1.0,
                closed.fraction, 0.05, true, "-"});
}

TEST(TransmittingBoundary, OnAnSphPartIsRefused) {
  Model model =
      test::block_model(GeometryMode::plane_strain, {{"soil", 0, {0, 0, 0}, {1, 1, 0}, {4, 4, 1}}}, {});
  Part zone;
  zone.name = "charge";
  zone.kind = PartKind::sph;
  zone.material = 0;
  model.parts.push_back(zone);
  model.boundaries.push_back(transmitting("charge.xmax"));
  try {
    Solver<2> solver(model);
    FAIL() << "a transmitting boundary on an SPH part was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not supported on SPH particle parts"), std::string::npos)
        << e.what();
  }
}

// Dashpot nodes that a constraint holds too: a 3-D soil column (1 x 1 x 10 m, 4 x 4 x 40 hexes)
// pushed up at its base at 1 m/s for 2 ms (a prescribed velocity), its sides xmin, ymin and
// ymax on symmetry planes, its top and its xmax side transmitting. The nodes where the side's
// dashpots meet the symmetry planes and the pushed base have both; the dashpot's work is booked
// against the velocity the node moves with once the constraint has acted. Booked against the
// dashpot's own solution instead, the balance missed 16 % at 10 ms (15.7 % at 42 ms).
TEST(TransmittingBoundary, DashpotNodesUnderAConstraintKeepTheBalance) {
  test::use_threads(1);
  Model model = test::block_model(GeometryMode::three_d, {BlockSpec{"c", 0, {0, 0, 0}, {1.0, 1.0, 10.0}, {4, 4, 40}}},
                                  ElasticConstants{});
  model.run.end_time = 0.01;
  model.run.viscosity_form = ViscosityForm::volumetric;
  BoundaryCondition push = test::velocity("c.zmin", 2, 1.0);
  push.history = TimeHistory{{0.0, 0.002, 0.0021}, {1.0, 1.0, 0.0}};
  model.boundaries.push_back(push);
  model.boundaries.push_back(test::symmetry("c.xmin", {1, 0, 0}));
  model.boundaries.push_back(test::symmetry("c.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("c.ymax", {0, 1, 0}));
  model.boundaries.push_back(transmitting("c.zmax"));
  model.boundaries.push_back(transmitting("c.xmax"));
  Solver<3> solver(model);
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
  }
  test::verify({"Transmitting boundary, 3-D soil column pushed at its base, dashpots on nodes held by symmetry "
                "planes and the prescribed velocity: relative energy error at 10 ms",
                "0 (energy conserved; the dashpot work booked against the velocity the node moves with)", 0.0,
                solver.energy().relative_error, 0.005, false, "-"});
}
