// The 100 kg TNT sphere of the seed paper (tnt_wang2005, R = 0.2447 m) as r-z
// SPH particles (R/20 spacing), lit at its centre on the axis and expanding
// into vacuum for 60 us: the set-up that was reported to blow up on the axis
// within a few cycles (density -> 1e160; docs/theory/explosive-and-steel.md).
// The detonation must cross the whole charge, the energy must hold within 1 %
// and the density must stay bounded: nowhere above 1.5 x the
// Chapman-Jouguet density at any cycle (the products expand; only the burn
// front compresses, to rho_CJ = 2228 kg/m^3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/verification.hpp"
#include "materials/jwl_eos.hpp"
#include "materials/registry.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

TEST(SphChargeRz, PointLitTntSphereOnTheAxisStaysBoundedAndConservesEnergy) {
  const Model model = test::tnt_sphere_rz(20);
  const auto& jwl = dynamic_cast<const JwlEos&>(model.materials[0].material->eos());
  const double rho_cj = jwl.cj_state().density, p_cj = jwl.cj_state().pressure;

  SphSystem<2> sph(model, SphOptions{});
  const double e0 = sph.kinetic_energy() + sph.internal_energy();
  const std::size_t n = sph.size();
  const double t_end = 60e-6;  // s: the front reaches the surface after R / D = 35 us
  double dt_last = 0.0, rho_max = 0.0, r_min = 1.0;
  const auto& p = sph.particles();
  const long cycles = test::run_leapfrog_until(sph, t_end, 0.3, &dt_last, [&] {
    for (std::size_t i = 0; i < n; ++i) {
      rho_max = std::max(rho_max, p.density[i]);
      r_min = std::min(r_min, p.position[i][0]);
    }
  });
  const double kinetic = test::synchronised_kinetic_energy(sph, dt_last);
  const double e_end = kinetic + sph.internal_energy();

  std::size_t moved_out = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Every particle has burnt and been pushed outwards (its displacement
    // points away from the centre).
    if (dot(p.displacement[i], p.position[i] - p.displacement[i]) > 0.0) ++moved_out;
  }
  std::printf(
      "TNT sphere r-z SPH: %zu particles, %ld cycles, E %.5e -> %.5e J, kinetic %.3f, largest rho %.0f "
      "(CJ %.0f), p_CJ %.3g, smallest r %.4g m (both over all cycles), moved out %zu\n",
      n, cycles, e0, e_end, kinetic / e_end, rho_max, rho_cj, p_cj, r_min, moved_out);
  test::verify({"TNT sphere in r-z SPH (R/20), lit at the centre on the axis: total energy after 60 us",
                "chemical energy E0 V conserved (within 1 %)", e0, e_end, 0.01, true, "J"});
  test::record_check("TNT sphere in r-z SPH, lit on the axis: density bounded",
                     "largest density < 1.5 rho_CJ (the reported blow-up reached 1e160)",
                     "largest density " + std::to_string(rho_max) + " kg/m^3", rho_max < 1.5 * rho_cj);
  EXPECT_LT(rho_max, 1.5 * rho_cj);
  EXPECT_EQ(moved_out, n) << "every particle must have been pushed away from the centre";
  EXPECT_GT(kinetic, 0.2 * e0) << "the detonation must have turned chemical energy into motion";
}
