// Artificial conductivity (SphOptions::conductivity; Price 2008, JCP 227,
// 10040, eqs. 28 and 30): one kick on a gas lattice at rest with one hot
// particle. The heat the hot particle loses is what its neighbours gain (the
// pair exchange is antisymmetric), heat flows from hot to cold only, its rate
// matches the pair sum written out here, it stays within a family of
// equations of state, and it is zero when the option is off.
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

struct HotLattice {
  Model model;
  std::size_t hot = 0;
};

// 7 x 7 x 7 gas particles (dx = 0.1 m, rho = 1, u = 1 J/kg), the centre one at
// u = 10 J/kg; `neighbour_material` replaces the gas of the centre's +x neighbour.
HotLattice hot_lattice(std::shared_ptr<const Material> neighbour_material = nullptr) {
  HotLattice l;
  l.model.run.mode = GeometryMode::three_d;
  test::add_sph_part(l.model, "cold", test::ideal_gas("cold", 1.0, 1.4, 1.0),
                     test::box_fill({0, 0, 0}, {0.7, 0.7, 0.7}, 0.1));
  test::add_sph_part(l.model, "hot", test::ideal_gas("hot", 1.0, 1.4, 10.0),
                     test::box_fill({0.3, 0.3, 0.3}, {0.4, 0.4, 0.4}, 0.1));
  // The "hot" fill put one more particle on the centre: drop the cold one there.
  auto& ps = l.model.particles;
  const std::size_t centre = 3 + 7 * 3 + 49 * 3;
  ps.particle_part[centre] = 1;
  ps.coordinates.resize(3 * (ps.count() - 1));
  ps.volume.pop_back();
  ps.spacing.pop_back();
  ps.particle_part.pop_back();
  l.hot = centre;
  if (neighbour_material) {
    test::add_sph_part(l.model, "other", neighbour_material,
                       test::box_fill({0.4, 0.3, 0.3}, {0.5, 0.4, 0.4}, 0.1));
    ps.particle_part[centre + 1] = 2;
    ps.coordinates.resize(3 * (ps.count() - 1));
    ps.volume.pop_back();
    ps.spacing.pop_back();
    ps.particle_part.pop_back();
  }
  return l;
}

}  // namespace

TEST(SphConductivity, HeatFlowsFromHotToColdAndIsConserved) {
  HotLattice l = hot_lattice();
  SphOptions options;
  options.conductivity = 1.0;
  options.artificial_stress = false;
  SphSystem<3> sph(l.model, options);
  const double dt = 1e-4;
  sph.compute_accelerations();
  sph.kick(dt);
  const auto& p = sph.particles();
  const std::size_t hot = l.hot;
  ASSERT_NEAR(p.position[hot][0], 0.35, 1e-12);

  double gained = 0.0, expected_loss = 0.0;
  bool only_neighbours_warm = true;
  const Kernel<3> kernel{};
  const double p_hot = 0.4 * 10.0, p_cold = 0.4 * 1.0, v_sig = std::sqrt((p_hot - p_cold) / 1.0);
  for (std::size_t j = 0; j < sph.size(); ++j) {
    if (j == hot) continue;
    gained += p.mass[j] * p.heating[j];
    const double r = norm(p.position[hot] - p.position[j]);
    const double h = p.smoothing_length[j];
    // Price (2008) eq. 28 written out for the pair: m_j alpha v_sig (u_i - u_j) / rho dW/dr.
    expected_loss += -p.mass[j] * v_sig * (10.0 - 1.0) / 1.0 * kernel.derivative(r, h) * dt;
    if (r >= 2.0 * h && p.heating[j] != 0.0) only_neighbours_warm = false;
    if (r < 2.0 * h && !(p.heating[j] > 0.0)) only_neighbours_warm = false;
  }
  const double lost = -p.mass[hot] * p.heating[hot];
  test::verify({"SPH artificial conductivity: heat lost by the hot particle in one kick",
                "Price (2008) eq. 28 summed over its neighbours", p.mass[hot] * expected_loss, lost, 1e-12,
                true, "J"});
  test::verify({"SPH artificial conductivity: heat gained by the neighbours / heat lost by the hot particle",
                "1 (pairwise antisymmetric exchange)", 1.0, gained / lost, 1e-12, true, ""});
  EXPECT_GT(lost, 0.0);
  EXPECT_TRUE(only_neighbours_warm) << "heat must reach exactly the hot particle's kernel neighbours";
}

TEST(SphConductivity, OffByDefaultAndOnlyWithinOneEosFamily) {
  {
    HotLattice l = hot_lattice();
    SphSystem<3> sph(l.model, SphOptions{});
    sph.compute_accelerations();
    sph.kick(1e-4);
    EXPECT_EQ(sph.particles().heating[l.hot], 0.0) << "no conductivity unless asked for";
  }
  // The +x neighbour is a solid (polynomial EOS, u = 0): its energy has another
  // reference, so no heat may cross to it, while the gas neighbours take theirs.
  HotLattice l = hot_lattice(test::elastic_solid("solid", 1.0, 1e3, 1e3));
  SphOptions options;
  options.conductivity = 1.0;
  options.artificial_stress = false;
  SphSystem<3> sph(l.model, options);
  sph.compute_accelerations();
  sph.kick(1e-4);
  const auto& p = sph.particles();
  EXPECT_NEAR(p.position[l.hot + 1][0], 0.45, 1e-12);
  EXPECT_EQ(p.heating[l.hot + 1], 0.0);
  EXPECT_GT(p.heating[l.hot - 1], 0.0);
  EXPECT_LT(p.heating[l.hot], 0.0);
}
