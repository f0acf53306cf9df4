// The same 1-D elastic-plastic impact through FEM and through SPH:
// a von Mises bar (uniaxial strain: symmetry at y = 0 and y = H)
// moving at -v0 stops against a rigid wall at x = 0. The velocity step splits
// into an elastic precursor at the Hugoniot elastic limit and a slower plastic
// wave (Meyers, Dynamic Behavior of Materials, 1994, s. 7.2); in Lagrangian
// (initial) coordinates, exactly for a linear EOS and perfect plasticity,
//   elastic precursor  U = c_p = sqrt((K + 4G/3) / rho0),  v_HEL = sigma_HEL / (rho0 c_p)
//   plastic wave       U = c_b = sqrt(K / rho0)            (the deviator is frozen at yield)
// Each front is located where the velocity change crosses the middle of its
// jump, in initial coordinates X = x - u, at two instants; the smearing of the
// fronts (a few cells / smoothing lengths) cancels in the difference.
// The material object is the same for both (one code path, materials/).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "mesh/particle_fill.hpp"
#include "solver/solver.hpp"
#include "sph/sph_system.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

ElasticConstants aluminium() {
  ElasticConstants c;
  c.density = 2700.0;
  c.bulk_modulus = 70e9;
  c.shear_modulus = 32.3e9;
  c.yield_stress = 300e6;
  return c;
}

constexpr double length = 1.0, v0 = 60.0;

// Initial coordinate where the velocity change |v + v0| first drops below `level`, scanning from the far end.
double front(std::vector<std::pair<double, double>> samples, double level) {
  std::sort(samples.begin(), samples.end());  // by initial coordinate X
  for (std::size_t k = samples.size() - 1; k > 0; --k) {
    const auto [xa, ua] = samples[k - 1];
    const auto [xb, ub] = samples[k];
    if (ua >= level && ub < level) return xa + (ua - level) / (ua - ub) * (xb - xa);
  }
  return 0.0;
}

struct Fronts {
  double elastic = 0.0, plastic = 0.0;  // Lagrangian speeds, m/s
};

template <class Sample>
Fronts speeds(const Sample& at_t1, const Sample& at_t2, double t1, double t2, double v_hel) {
  const double e1 = front(at_t1, 0.5 * v_hel), e2 = front(at_t2, 0.5 * v_hel);
  const double p1 = front(at_t1, 0.5 * (v_hel + v0)), p2 = front(at_t2, 0.5 * (v_hel + v0));
  EXPECT_GT(p1, 0.0);
  EXPECT_GT(e1, p1);
  return {(e2 - e1) / (t2 - t1), (p2 - p1) / (t2 - t1)};
}

Fronts fem_fronts(double t1, double t2, double v_hel) {
  const ElasticConstants c = aluminium();
  const double cell = 4e-3;
  const int cells = static_cast<int>(std::lround(length / cell));
  Model model = test::block_model(GeometryMode::plane_strain,
                                  {{"bar", 0, {0, 0, 0}, {length, cell, 0}, {cells, 1, 1}}}, c);
  model.parts[0].initial_velocity = {-v0, 0, 0};
  model.boundaries.push_back(test::velocity("bar.xmin", 0, 0.0));
  model.boundaries.push_back(test::symmetry("bar.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("bar.ymax", {0, 1, 0}));
  Solver<2> solver(model);
  auto sample = [&] {
    std::vector<std::pair<double, double>> s;
    for (std::size_t n = 0; n < solver.position().size() / 2; ++n)
      if (solver.position()[2 * n + 1] < 0.5 * cell)
        s.emplace_back(solver.position()[2 * n] - solver.displacement()[2 * n],
                       solver.velocity()[2 * n] + v0);
    return s;
  };
  std::vector<std::pair<double, double>> s1;
  while (solver.time() < t2) {
    solver.limit_next_step((solver.time() < t1 ? t1 : t2) - solver.time());
    solver.step();
    if (std::abs(solver.time() - t1) < 1e-15) s1 = sample();
  }
  return speeds(s1, sample(), t1, t2, v_hel);
}

Fronts sph_fronts(double t1, double t2, double v_hel) {
  const ElasticConstants c = aluminium();
  const double dx = 4e-3;
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.materials.push_back({"solid", test::elastic_material(c), {}});
  Part part;
  part.name = "bar";
  part.kind = PartKind::sph;
  part.material = 0;
  part.initial_velocity = {-v0, 0, 0};
  model.parts.push_back(part);
  ParticleFillSpec spec;
  spec.region.min = {0, 0, 0};
  spec.region.max = {length, 4 * dx, 0};
  spec.spacing = dx;
  fill_particles(model.particles, spec, model.run.mode);
  const std::vector<sph::MirrorPlane> planes{{0, 0.0, sph::PlaneKind::symmetry},
                                             {1, 0.0, sph::PlaneKind::symmetry},
                                             {1, 4 * dx, sph::PlaneKind::symmetry}};
  sph::SphSystem<2> sph(model, sph::SphOptions{}, planes);
  auto sample = [&] {
    const auto& p = sph.particles();
    std::vector<std::pair<double, double>> s;
    for (std::size_t i = 0; i < sph.size(); ++i)
      if (p.position[i][1] - p.displacement[i][1] < dx)
        s.emplace_back(p.position[i][0] - p.displacement[i][0], p.velocity[i][0] + v0);
    return s;
  };
  sph.compute_accelerations();
  double t = 0.0;
  std::vector<std::pair<double, double>> s1;
  for (const double t_stop : {t1, t2}) {
    while (t < t_stop * (1 - 1e-12)) {
      double dt = 0.3 * sph.stable_time_step().dt;
      if (t + dt > t_stop) dt = t_stop - t;
      t += dt;
      sph.step(dt, t);
    }
    if (t_stop == t1) s1 = sample();
  }
  // The velocity is staggered (v at t - dt/2): the last step ended exactly at t2, as the first at t1.
  return speeds(s1, sample(), t1, t2, v_hel);
}

}  // namespace

TEST(FemSphImpact, SameElasticPlasticWavesInBoth) {
  test::use_threads(1);
  const ElasticConstants c = aluminium();
  const double cp = c.p_wave_speed(), cb = c.bulk_wave_speed();
  const double hel =
      (c.bulk_modulus + 4.0 * c.shear_modulus / 3.0) * c.yield_stress / (2.0 * c.shear_modulus);
  const double v_hel = hel / (c.density * cp);
  ASSERT_GT(v0, 1.5 * v_hel) << "the impact must exceed the elastic limit";
  const double t1 = 0.3 * length / cp, t2 = 0.85 * length / cp;
  const Fronts fem = fem_fronts(t1, t2, v_hel);
  const Fronts sph = sph_fronts(t1, t2, v_hel);
  std::printf("elastic: FEM %.1f SPH %.1f (c_p %.1f); plastic: FEM %.1f SPH %.1f (c_b %.1f)\n", fem.elastic,
              sph.elastic, cp, fem.plastic, sph.plastic, cb);
  test::verify({"Elastic-plastic impact, FEM (dx = 4 mm): elastic precursor speed (Lagrangian)",
                "c_p = sqrt((K + 4G/3)/rho0)", cp, fem.elastic, 0.03, true, "m/s"});
  test::verify({"Elastic-plastic impact, SPH (dx = 4 mm): elastic precursor speed (Lagrangian)",
                "c_p = sqrt((K + 4G/3)/rho0)", cp, sph.elastic, 0.03, true, "m/s"});
  test::verify({"Elastic-plastic impact, FEM: plastic wave speed (Lagrangian)", "c_b = sqrt(K/rho0)", cb,
                fem.plastic, 0.03, true, "m/s"});
  test::verify({"Elastic-plastic impact, SPH: plastic wave speed (Lagrangian)", "c_b = sqrt(K/rho0)", cb,
                sph.plastic, 0.03, true, "m/s"});
  test::verify({"Elastic-plastic impact, SPH vs FEM: elastic precursor speed", "the FEM result", fem.elastic,
                sph.elastic, 0.03, true, "m/s"});
  test::verify({"Elastic-plastic impact, SPH vs FEM: plastic wave speed", "the FEM result", fem.plastic,
                sph.plastic, 0.03, true, "m/s"});
}
