// The joined SPH zone of the buried-structure case, cut down to its near field:
// 100 kg TNT 0.5 m deep on the axis of an r-z soil block 2.5 m x
// 3.5 m (0.05 m cells, the `default` resolution), the soil in r <= 1.5 m down
// to 2 m as SPH particles joined to the FEM soil, transmitting far edges, 8 ms.
//
// In the continuum the soil on both sides of the join moves as one, so the
// join-face nodes must follow the particles beside them. Before the join-face
// fixes named below they did not, in two places:
// * next to the axis, the face nodes at r = 0.05 and 0.1 m were driven down
//   through the elements below them and across the axis (the run stopped at
//   6 ms: "crossed the axis"): the faces took the particles' stress with the
//   particles' ring radii, up to twice the face's own next to the axis;
// * at the zone's bottom outer corner (r = 1.5 m, z = -2 m), the bottom face's
//   last nodes ran outwards and the side face's lowest node down (elements
//   tangled at 5.4 ms): the corner points' reactions held the other face's
//   traction (sph_fem_join.cpp, join_faces.cpp, docs/theory/coupling.md).
// Required: the run reaches 8 ms without a tangled element, and each of the
// watched face nodes is displaced within 30 % of the mean displacement of the
// particles within 0.1 m of it (measured 5-21 %).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "case/case_reader.hpp"
#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "near_field_case.hpp"
#include "solver/solver.hpp"

namespace camouflet {
namespace {

struct Follow {
  double node_shift = 0.0;      // m, |u_node - u_particles|
  double particle_shift = 0.0;  // m, |u_particles|
};

Follow follow(const Solver<2>& solver, const std::vector<double>& x0, double r, double z) {
  std::size_t node = 0;
  double best = 1e300;
  for (std::size_t n = 0; n < solver.node_count(); ++n) {
    const double d = std::hypot(x0[2 * n] - r, x0[2 * n + 1] - z);
    if (d < best) best = d, node = n;
  }
  const auto& p = solver.particles()->particles();
  double ur = 0.0, uz = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < p.real; ++i) {
    const Vec<2> start = p.position[i] - p.displacement[i];
    if (std::hypot(start[0] - r, start[1] - z) < 0.1)
      ur += p.displacement[i][0], uz += p.displacement[i][1], ++count;
  }
  ur /= count;
  uz /= count;
  const double* u = &solver.displacement()[2 * node];
  return {std::hypot(u[0] - ur, u[1] - uz), std::hypot(ur, uz)};
}

TEST(JoinedNearField, FaceNodesFollowTheParticlesAtTheAxisAndTheCorner) {
  test::use_threads(1);
  const Model model = read_case_text(test::near_field_case("joined near field", 0.008), "near_field.toml");
  Solver<2> solver(model);
  const std::vector<double> x0 = solver.position();
  ASSERT_NO_THROW(while (solver.time() < 8e-3) solver.step());
  EXPECT_LT(solver.first_tangled_cycle(), 0) << "element " << solver.first_tangled_element() << " tangled";
  EXPECT_LT(solver.first_axis_crossing_cycle(), 0) << "node " << solver.first_axis_crossing_node();
  const struct {
    const char* name;
    double r, z;
  } watched[] = {{"bottom face r = 0.05 m", 0.05, -2.0}, {"bottom face r = 0.10 m", 0.10, -2.0},
                 {"bottom face r = 0.15 m", 0.15, -2.0}, {"bottom face r = 1.40 m", 1.40, -2.0},
                 {"bottom face r = 1.45 m", 1.45, -2.0}, {"corner (1.5, -2.0) m", 1.50, -2.0},
                 {"side face z = -1.95 m", 1.50, -1.95}, {"side face z = -1.90 m", 1.50, -1.90}};
  for (const auto& w : watched) {
    const Follow f = follow(solver, x0, w.r, w.z);
    test::verify({fmt::format("Joined near field (r-z, 100 kg TNT, 8 ms): join-face node at {}, displacement "
                              "off the particles' beside it / theirs",
                              w.name),
                  "0 (one continuum; bound 30 %)", 0.0, f.node_shift / f.particle_shift, 0.30, false, "-"});
  }
}

}  // namespace
}  // namespace camouflet
