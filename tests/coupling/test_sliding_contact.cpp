// Sliding interface: a disc (2-D) / cylinder
// (3-D) of SPH particles strikes a free FEM plate through the penalty contact.
// Total momentum of particles and nodes is conserved within 0.5 % and no
// particle centre crosses the plate surface (the documented tolerance: an
// interpenetration below half a particle spacing).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "mesh/particle_fill.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

struct ImpactResult {
  double momentum_error = 0.0;  // |P_end - P_0| / |P_0|
  double smallest_gap = 0.0;    // m, smallest signed distance of a particle centre to the plate face
  double spacing = 0.0;         // m
  double rebound = 0.0;         // m/s, mean particle velocity at the end (normal)
  double plate_velocity = 0.0;  // m/s, mean plate velocity at the end (normal)
};

template <int D>
ImpactResult disc_on_plate(double friction, double tangential_speed) {
  test::use_threads(1);
  const test::ElasticConstants c;
  const GeometryMode mode = D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d;
  const double cell = 4e-3, s = 2e-3, v0 = 50.0;
  // Plate: 0.12 x 0.02 (x 0.12) m, its top face at y = 0.
  Model model =
      test::block_model(mode, {{"plate", 0, {-0.06, -0.02, -0.02}, {0.12, 0.02, 0.04}, {30, 5, 10}}}, c);
  Part disc;
  disc.name = "disc";
  disc.kind = PartKind::sph;
  disc.material = 0;
  disc.initial_velocity = {tangential_speed, -v0, 0.0};
  model.parts.push_back(disc);
  ParticleFillSpec fill;
  fill.part = 1;
  fill.spacing = s;
  const double radius = 0.015;
  if (D == 2) {
    fill.region.shape = ParticleRegion::Shape::sphere;
    fill.region.centre = {0.0, radius + 0.5e-3, 0.0};
    fill.region.radius = radius;
  } else {  // a cylinder lying along z, short enough to keep the run quick
    fill.region.shape = ParticleRegion::Shape::cylinder;
    fill.region.centre = {0.0, radius + 0.5e-3, -0.01};
    fill.region.axis = {0, 0, 1};
    fill.region.radius = radius;
    fill.region.length = 0.02;
  }
  fill_particles(model.particles, fill, mode);
  Contact contact;
  contact.sph_part = 1;
  contact.face_set = "plate.ymax";
  contact.friction = friction;
  model.contacts.push_back(contact);
  model.run.end_time = 2.0 * radius / c.p_wave_speed() + 1e-3 / v0 + 20e-6;
  Solver<D> solver(model);

  auto momentum = [&] {
    Vec<D> pm = solver.particles()->momentum();
    for (std::size_t n = 0; n < solver.node_count(); ++n)
      for (int i = 0; i < D; ++i)
        pm[i] += solver.node_mass()[n] * solver.velocity()[n * D + static_cast<std::size_t>(i)];
    return pm;
  };
  const Vec<D> p0 = momentum();
  ImpactResult r;
  r.spacing = s;
  r.smallest_gap = 1e300;
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    // Height of each particle centre above the local plate surface: the mean
    // height of the top nodes within one cell of it horizontally.
    const auto& top = model.mesh.node_sets.at("plate.ymax");
    const auto& x = solver.particles()->particles().position;
    for (std::size_t i = 0; i < solver.particles()->size(); ++i) {
      if (x[i][1] > 0.01) continue;  // far above the plate
      double surface = 0.0;
      int count = 0;
      for (std::int64_t n : top) {
        const double* xn = &solver.position()[static_cast<std::size_t>(n) * D];
        double horizontal = std::abs(xn[0] - x[i][0]);
        if (D == 3) horizontal = std::max(horizontal, std::abs(xn[D - 1] - x[i][D - 1]));
        if (horizontal < cell) surface += xn[1], ++count;
      }
      if (count > 0) r.smallest_gap = std::min(r.smallest_gap, x[i][1] - surface / count);
    }
  }
  const Vec<D> p1 = momentum();
  Vec<D> dp = p1 - p0;
  r.momentum_error = std::sqrt(dot(dp, dp) / dot(p0, p0));
  double mp = 0.0, vp = 0.0;
  const auto& pa = solver.particles()->particles();
  for (std::size_t i = 0; i < pa.real; ++i) mp += pa.mass[i], vp += pa.mass[i] * pa.velocity[i][1];
  r.rebound = vp / mp;
  double mn = 0.0, vn = 0.0;
  for (std::size_t n = 0; n < solver.node_count(); ++n)
    mn += solver.node_mass()[n], vn += solver.node_mass()[n] * solver.velocity()[n * D + 1];
  r.plate_velocity = vn / mn;
  fmt::print(
      "impact {}-D: momentum error {:.3g}, smallest centre gap {:.4g} m (spacing {:.3g}), particle v_y "
      "{:.4g}, "
      "plate v_y {:.4g}\n",
      D, r.momentum_error, r.smallest_gap, s, r.rebound, r.plate_velocity);
  return r;
}

}  // namespace

TEST(SlidingContact, DiscHitsPlatePlaneStrain) {
  const ImpactResult r = disc_on_plate<2>(0.3, 10.0);
  test::verify({"SPH disc on a FEM plate (sliding interface, mu = 0.3): momentum change / initial",
                "0 (conserved)", 0.0, r.momentum_error, 0.005, false, "-"});
  test::record_check("SPH disc on a FEM plate: interpenetration",
                     "no particle centre below the plate surface",
                     fmt::format("smallest centre height above the plate {:.3g} m (half spacing {:.3g} m)",
                                 r.smallest_gap, 0.5 * r.spacing),
                     r.smallest_gap > 0.0);
  EXPECT_GT(r.smallest_gap, 0.0);
  // The plate was pushed down: the contact transmitted momentum.
  EXPECT_LT(r.plate_velocity, -0.5);
}

TEST(SlidingContact, CylinderHitsPlate3D) {
  const ImpactResult r = disc_on_plate<3>(0.3, 10.0);
  test::verify({"SPH cylinder on a FEM plate, 3-D (sliding interface): momentum change / initial",
                "0 (conserved)", 0.0, r.momentum_error, 0.005, false, "-"});
  EXPECT_GT(r.smallest_gap, 0.0);
  EXPECT_LT(r.plate_velocity, -0.1);
}
