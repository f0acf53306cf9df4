// Particle gauges by kernel interpolation at a fixed point:
// on a particle lattice carrying analytic fields, the Shepard-normalised
// interpolation must return a constant field to round-off and a linear field
// to the lattice's small first-moment error; in r-z the weights must be the
// meridian areas (with ring volumes a field linear in r comes out biased
// towards large r by ~ b h^2 / r, which the tolerance below excludes).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/verification.hpp"
#include "output/gauges.hpp"

namespace camouflet {
namespace {

struct Lattice {
  std::vector<double> position, mass, density, h, velocity, displacement, acceleration, pressure, plastic,
      damage;
  std::vector<SymTensor> stress;
  FieldSnapshot view(GeometryMode mode) const {
    FieldSnapshot s;
    s.dimension = mode == GeometryMode::three_d ? 3 : 2;
    s.mode = mode;
    s.particle_position = position;
    s.particle_mass = mass;
    s.particle_density = density;
    s.particle_smoothing_length = h;
    s.particle_velocity = velocity;
    s.particle_displacement = displacement;
    s.particle_acceleration = acceleration;
    s.particle_pressure = pressure;
    s.particle_plastic_strain = plastic;
    s.particle_damage = damage;
    s.particle_stress = stress;
    return s;
  }
};

// Particles at the centres of an n x n grid of cells dx on [0, n dx]^2 with
// velocity_x = a + b x + c y, pressure = constant p0, density varying (so
// volume weights matter), mass = rho x cell volume (ring volume in r-z).
constexpr double a = 2.0, b = 30.0, c = -12.0, p0 = 7.5e6;
Lattice lattice_2d(int n, double dx, GeometryMode mode) {
  Lattice l;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
      const double rho = 1000.0 * (1.0 + 0.5 * x);
      const double volume = mode == GeometryMode::axisymmetric ? 2 * std::numbers::pi * x * dx * dx : dx * dx;
      l.position.insert(l.position.end(), {x, y});
      l.mass.push_back(rho * volume);
      l.density.push_back(rho);
      l.h.push_back(1.2 * dx);
      l.velocity.insert(l.velocity.end(), {a + b * x + c * y, 0.0});
      l.displacement.insert(l.displacement.end(), {0.0, 0.0});
      l.acceleration.insert(l.acceleration.end(), {0.0, 0.0});
      l.pressure.push_back(p0);
      l.plastic.push_back(0.0);
      l.damage.push_back(0.0);
      l.stress.push_back(SymTensor::isotropic(-p0));
    }
  return l;
}

// Worst errors (constant pressure, linear velocity) over interior points that are not lattice sites.
std::pair<double, double> worst_errors(GeometryMode mode, double dx) {
  const Lattice l = lattice_2d(40, dx, mode);
  const FieldSnapshot s = l.view(mode);
  const int dim = 2;
  double worst_p = 0.0, worst_v = 0.0;
  for (int k = 0; k < 9; ++k) {
    GaugePoint g;
    g.name = "g";
    g.interpolate = true;
    g.position = {(8.3 + 2.71 * k) * dx, (31.2 - 2.37 * k) * dx, 0.0};
    const LocatedGauge located = locate_gauge(g, s);
    EXPECT_TRUE(located.interpolate);
    std::vector<double> out;
    sample_gauge(located, s, out);
    EXPECT_EQ(out.size(), gauge_quantities(dim).size());
    EXPECT_EQ(out[0], g.position[0]);  // the gauge stays where it was put
    const double v_exact = a + b * g.position[0] + c * g.position[1];
    worst_v = std::max(worst_v, std::abs(out[static_cast<std::size_t>(2 * dim)] - v_exact));
    worst_p = std::max(worst_p, std::abs(out[static_cast<std::size_t>(4 * dim + 6)] - p0) / p0);
  }
  return {worst_p, worst_v};
}

TEST(ParticleGauges, InterpolationOfAnalyticFieldsPlane) {
  const double dx = 0.01;
  const auto [p_err, v_err] = worst_errors(GeometryMode::plane_strain, dx);
  test::verify({"Particle gauge, kernel interpolation at a fixed point (plane): constant pressure",
                "exact (Shepard normalisation)", 0.0, p_err, 1e-12, false, "-"});
  // Error of a linear field = gradient x the first moment of the weights, a
  // small fraction of dx on a lattice; 2 % of |grad v| dx bounds it.
  test::verify({"Particle gauge, kernel interpolation at a fixed point (plane): linear velocity",
                "v = a + b x + c y, error < 0.02 |grad v| dx", 0.0, v_err, 0.02 * std::hypot(b, c) * dx,
                false, "m/s"});
}

TEST(ParticleGauges, InterpolationOfAnalyticFieldsAxisymmetric) {
  const double dx = 0.01;
  const auto [p_err, v_err] = worst_errors(GeometryMode::axisymmetric, dx);
  test::verify({"Particle gauge, kernel interpolation at a fixed point (r-z): constant pressure",
                "exact (Shepard normalisation)", 0.0, p_err, 1e-12, false, "-"});
  test::verify(
      {"Particle gauge, kernel interpolation at a fixed point (r-z, meridian-area weights): linear "
       "velocity",
       "v = a + b r + c z, error < 0.02 |grad v| dx", 0.0, v_err, 0.02 * std::hypot(b, c) * dx, false,
       "m/s"});
}

TEST(ParticleGauges, InterpolatingGaugeOutsideParticlesNamesKey) {
  const Lattice l = lattice_2d(10, 0.01, GeometryMode::plane_strain);
  const FieldSnapshot s = l.view(GeometryMode::plane_strain);
  GaugePoint g;
  g.name = "far";
  g.interpolate = true;
  g.position = {0.5, 0.05, 0.0};
  g.where = SourceLocation{"case.toml", 12, 0, "gauges[1].points[0].position"};
  try {
    locate_gauge(g, s);
    FAIL() << "interpolating gauge outside the particles accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 12);
    EXPECT_NE(std::string(e.what()).find("gauges[1].points[0].position"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace camouflet
