// An FEM element of the SPH-FEM interface erodes (coupling/join_erosion.cpp).
//
// The r-z column of test_join_axis.cpp (12 cells of 5 mm, axis at r = 0,
// roller at r = 12 cells; FEM | SPH [0.4, 0.8] m | FEM), a plane elastic
// P-pulse driven down from the top. The axis element just below the zone is
// given its own material, the same elastic solid with erosion at a geometric
// strain of 1e-4 (the pulse's peak strain is 1 m/s / c_p = 9.4e-4), so it
// erodes as the pulse arrives. Its top axis node then belongs to no element:
// nothing acts on it (the axis constraint only holds v_r = 0), and its
// velocity must not change from the cycle it was left alone. Before the join
// followed erosion the eroded face kept taking the pair reactions and drove
// that node on (in the buried case at about 2 km/s). The faces the hole
// exposes carry the pulse on: the node under the hole moves with the plane
// wave.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "common/verification.hpp"
#include "join_models.hpp"

using namespace camouflet;

TEST(SphFemJoin, AnErodedInterfaceElementLeavesTheJoin) {
  test::use_threads(1);
  const test::ElasticConstants c;
  const double cell = 5e-3;
  Model model = test::axis_column(12, c, true);
  // The axis element under the zone erodes as the pulse arrives.
  const std::size_t needle = test::make_element_erode(model, {0.5 * cell, 0.4 - 0.5 * cell, 0.0}, 1e-4);
  ASSERT_LT(needle, model.mesh.element_count());

  const double c_p = c.p_wave_speed(), duration = 0.1 / c_p;
  // The pulse's tail passes z = 0.4 - cell at (0.8 + cell + 0.1) / c_p.
  model.run.end_time = 1.05 / c_p;

  Solver<2> solver(model);
  auto node_at = [&](double r, double z) {
    for (std::size_t n = 0; n < solver.node_count(); ++n)
      if (std::abs(solver.position()[2 * n] - r) < 1e-9 && std::abs(solver.position()[2 * n + 1] - z) < 1e-9)
        return n;
    return solver.node_count();
  };
  const std::size_t orphan = node_at(0.0, 0.4), below = node_at(0.0, 0.4 - cell);
  ASSERT_LT(orphan, solver.node_count());
  ASSERT_LT(below, solver.node_count());
  const double z_below = solver.position()[2 * below + 1];
  double v_left = 0.0, drift = 0.0, t_eroded = -1.0;
  double largest_error = 0.0;
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    const double v = solver.velocity()[2 * orphan + 1];
    // From the cycle after the erosion: that cycle's velocity update still had the element.
    if (t_eroded >= 0.0) drift = std::max(drift, std::abs(v - v_left));
    if (t_eroded < 0.0 && solver.eroded_count() > 0) t_eroded = solver.time(), v_left = v;
    if (solver.time() > duration) largest_error = std::max(largest_error, std::abs(solver.energy().relative_error));
    if (std::getenv("JOIN_DEBUG") && solver.cycle() % 50 == 0)
      fmt::print("t c_p {:.3f} error {:.3e}\n", solver.time() * c_p, solver.energy().relative_error);
  }
  ASSERT_EQ(solver.eroded_count(), 1u);
  ASSERT_GT(t_eroded, 0.0);
  fmt::print("eroded at t c_p = {:.3f} m; orphan node v_z {:.4f} m/s then, largest change after {:.3e} m/s; "
             "node below: u_z {:.4e} m; largest energy error {:.3e}\n",
             t_eroded * c_p, v_left, drift, solver.position()[2 * below + 1] - z_below, largest_error);
  // The drive is 1 m/s: without the erosion's follow-up the orphan gained the pair reactions.
  test::verify({"Eroded join element (r-z): change of its orphaned axis node's velocity after erosion / drive",
                "0 (a node with no element takes no force)", 0.0, drift, 1e-9, false, "-"});
  // The plane wave displaces every point it has passed by its impulse, 0.05 m / c_p (downwards).
  const double u_plane = -0.05 / c_p, u_below = solver.position()[2 * below + 1] - z_below;
  test::verify({"Eroded join element (r-z): axial displacement of the axis node under the hole / plane wave's",
                "1 (the pulse, 20 cells long, passes a 1-cell hole)", 1.0, u_below / u_plane, 0.1, true, "-"});
  test::verify({"Eroded join element (r-z): largest energy balance error over the run",
                "0 (the join's own error: < 1 % over a crossing, test_join.cpp)", 0.0, largest_error, 0.01,
                false, "-"});
}
