// 1-D planar detonation along a TNT column in SPH:
// the seed paper's TNT (Table 5, JWL + programmed burn with
// the default burn width over the smoothing length) in a plane-strain
// particle column four particles across, mirror planes on the long sides and
// a rigid wall (mirror) at the lit end x = 0, lit there at t = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "materials/jwl_eos.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

TEST(SphDetonationColumn, FrontSpeedPeakPressureAndEnergy) {
  constexpr double length = 0.1;  // m
  constexpr double dx = length / 200;
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  test::add_sph_part(model, "tnt",
                     make_material("tnt", "tnt_wang2005", {}, Parameters{}, Parameters{}, Parameters{}),
                     test::box_fill({0, 0, 0}, {length, 4 * dx, 0}, dx));
  model.detonations.push_back(DetonationPoint{{0.0, 2.0 * dx, 0.0}, 0.0});
  const auto& jwl = dynamic_cast<const JwlEos&>(model.materials[0].material->eos());
  const double d = jwl.detonation_velocity(), p_cj = jwl.cj_state().pressure;
  const std::vector<MirrorPlane> planes{
      {0, 0.0, PlaneKind::symmetry}, {1, 0.0, PlaneKind::symmetry}, {1, 4 * dx, PlaneKind::symmetry}};
  SphSystem<2> sph(model, SphOptions{}, planes);
  omp_set_num_threads(1);

  const std::size_t n = sph.size();
  std::vector<double> x0(n), arrival(n, -1.0);
  for (std::size_t i = 0; i < n; ++i) x0[i] = sph.particles().position[i][0];
  const double initial_energy = sph.internal_energy() + sph.kinetic_energy();
  const double t_end = 0.9 * length / d;
  double t = 0.0, peak_mid = 0.0;
  long cycles = 0;
  sph.compute_accelerations();
  while (t < t_end && cycles < 20000) {
    const double dt = std::min(0.3 * sph.stable_time_step().dt, t_end - t);
    t += dt;
    sph.step(dt, t);
    ++cycles;
    const auto& p = sph.particles();
    for (std::size_t i = 0; i < n; ++i) {
      if (arrival[i] < 0.0 && p.pressure[i] > 0.5 * p_cj) arrival[i] = t;
      if (std::abs(x0[i] - 0.5 * length) < dx) peak_mid = std::max(peak_mid, p.pressure[i]);
    }
  }
  ASSERT_GE(t, t_end * (1.0 - 1e-12)) << "stopped after " << cycles << " cycles";
  // Front speed: least-squares slope of x against arrival time, 30 % .. 80 % of the column.
  double st = 0, sx = 0, stt = 0, stx = 0;
  int count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (x0[i] < 0.3 * length || x0[i] > 0.8 * length) continue;
    ASSERT_GT(arrival[i], 0.0) << "the front never reached x = " << x0[i];
    st += arrival[i];
    sx += x0[i];
    stt += arrival[i] * arrival[i];
    stx += arrival[i] * x0[i];
    ++count;
  }
  const double speed = (count * stx - st * sx) / (count * stt - st * st);
  test::verify({"1-D TNT detonation column (SPH, dx = 0.5 mm): front speed",
                "D = 6930 m/s (Wang 2005 Table 5)", 6930.0, speed, 0.02, true, "m/s"});
  test::verify({"1-D TNT detonation column (SPH, dx = 0.5 mm): peak mid-column pressure / P_CJ",
                "0.8 .. 1.1", 0.95, peak_mid / p_cj, 0.15 / 0.95, true, ""});
  // The chemical energy is internal energy from the start: the total must hold.
  const double total = sph.internal_energy() + sph.kinetic_energy();
  test::verify({"1-D TNT detonation column (SPH): energy balance",
                "total energy conserved within 1 % of the chemical energy", initial_energy, total, 0.01, true,
                "J"});
  EXPECT_GT(sph.kinetic_energy(), 0.05 * initial_energy);
}
