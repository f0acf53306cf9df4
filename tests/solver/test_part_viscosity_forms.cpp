// Subzonal pressures and the FEM viscosity form chosen per part (`hourglass.subzonal` and
// `viscosity = { form = ... }` of a [[parts]] entry): a buried structure's soil takes them, its
// concrete keeps the point q. Two closed r-z boxes of gas, stirred by the same smooth velocity
// field, far apart in one model: each must move exactly as it does alone in a model whose run-wide
// settings are its part's, bit for bit, whichever part carries the run's settings and whichever
// its own. A part whose own settings were ignored, or applied to the other part's elements,
// would move as the other settings make it move.
#include <gtest/gtest.h>

#include <cmath>

#include "../sph/sph_test_models.hpp"
#include "case/case_reader.hpp"
#include "common/fem_models.hpp"
#include "core/error.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

struct Settings {
  double subzonal = 0.0;
  ViscosityForm form = ViscosityForm::acceleration;
};

const Settings point_q{0.0, ViscosityForm::acceleration};
const Settings edge_and_subzones{1.0, ViscosityForm::edge};

constexpr int cycles = 150;

// A closed gas box of 8 x 8 quads, r in [r0, r0 + 1] m, z in [0, 1] m, as part `index`.
void add_box(Model& model, const std::string& name, double r0, int index) {
  add_block(model.mesh, {name, index, {r0, 0, 0}, {1.0, 1.0, 0.0}, {8, 8, 1}});
  Part part;
  part.name = name;
  part.material = 0;
  model.parts.push_back(part);
  for (const char* side : {"xmin", "xmax"}) model.boundaries.push_back(test::symmetry(name + "." + side, {1, 0, 0}));
  for (const char* side : {"ymin", "ymax"}) model.boundaries.push_back(test::symmetry(name + "." + side, {0, 1, 0}));
}

// The boxes at r0 = 0.5 m (first) and 3 m (second), each stirred by the same field relative to
// its own corner; run at a fixed step (max_dt below both CFL limits) for `cycles` cycles. `run` is
// the run-wide setting, `own` that of the parts marked in `own_parts`. Returns the velocities.
std::vector<double> stirred(const std::vector<double>& corners, const Settings& run, const Settings& own,
                            const std::vector<bool>& own_parts) {
  test::use_threads(1);
  Model model = test::fixed_step_model(GeometryMode::axisymmetric, 5e-3, cycles);  // s; the CFL step is ~0.04 s
  model.run.area_weighted_momentum = true;
  model.run.subzonal_pressure = run.subzonal;
  model.run.viscosity_form = run.form;
  model.materials.push_back({"gas", test::ideal_gas("gas", 1.0, 1.4, 2.5), {}});  // p = 1 Pa, c = 1.18 m/s
  for (std::size_t k = 0; k < corners.size(); ++k) {
    add_box(model, "box" + std::to_string(k), corners[k], static_cast<int>(k));
    if (own_parts[k]) {
      model.parts[k].subzonal = own.subzonal;
      model.parts[k].viscosity_form = own.form;
    }
  }
  Solver<2> solver(model);
  const auto& x = solver.position();
  std::vector<double> v(solver.velocity().size());
  for (std::size_t n = 0; n < v.size() / 2; ++n) {
    const double r0 = x[2 * n] < 2.0 ? corners.front() : corners.back();
    const double s = x[2 * n] - r0, z = x[2 * n + 1];
    v[2 * n] = 0.2 * std::sin(7.0 * s + 3.0 * z) * s * (1.0 - s);  // zero on the walls
    v[2 * n + 1] = 0.2 * std::cos(5.0 * s - 4.0 * z) * z * (1.0 - z);
  }
  solver.set_initial_velocity(v);
  while (solver.cycle() < cycles) solver.step();
  EXPECT_EQ(solver.cycle(), cycles);
  return solver.velocity();
}

std::size_t differing(const std::vector<double>& a, std::size_t from_a, const std::vector<double>& b, std::size_t n) {
  std::size_t count = 0;
  for (std::size_t k = 0; k < n; ++k) count += a[from_a + k] != b[k] ? 1 : 0;
  return count;
}

}  // namespace

TEST(PartViscosityForms, EachPartMovesAsWithItsSettingsRunWide) {
  const std::vector<double> both = {0.5, 3.0};
  const std::size_t box = 2 * 9 * 9;  // velocity values of one box
  const auto alone_point = stirred({0.5}, point_q, point_q, {false});
  const auto alone_edge = stirred({3.0}, edge_and_subzones, edge_and_subzones, {false});
  // The settings change the motion: otherwise the comparisons below prove nothing.
  const auto second_point = stirred({3.0}, point_q, point_q, {false});
  EXPECT_GT(differing(alone_edge, 0, second_point, box), box / 2);

  // The second box carries its own edge viscosity and subzonal pressures; the run has the point q.
  const auto own_edge = stirred(both, point_q, edge_and_subzones, {false, true});
  EXPECT_EQ(differing(own_edge, 0, alone_point, box), 0u) << "the first box (run's point q)";
  EXPECT_EQ(differing(own_edge, box, alone_edge, box), 0u) << "the second box (its own edge form)";
  // The other way round, as the buried-structure generator writes it: the run has the edge
  // viscosity and subzonal pressures, the first box its own point q without them.
  const auto own_point = stirred(both, edge_and_subzones, point_q, {true, false});
  EXPECT_EQ(differing(own_point, 0, alone_point, box), 0u) << "the first box (its own point q)";
  EXPECT_EQ(differing(own_point, box, alone_edge, box), 0u) << "the second box (run's edge form)";
}

TEST(PartViscosityForms, CaseKeysAreReadAndBadOnesNamed) {
  const std::string head = R"([run]
geometry = "axisymmetric"
end_time = 1e-3

[run.hourglass]
subzonal = 1.0

[run.viscosity]
form = "edge"

[materials.gas]
eos = { type = "ideal_gas", density = 1.0, gamma = 1.4, specific_energy = 2.5 }

[[parts]]
name = "soil"
material = "gas"
block = { origin = [0.0, 0.0], size = [1.0, 1.0], cells = [2, 2] }

[[parts]]
name = "box"
material = "gas"
block = { origin = [1.0, 0.0], size = [1.0, 1.0], cells = [2, 2] }
)";
  const Model model = read_case_text(
      head + "hourglass = { form = \"stiffness\", coefficient = 0.3, subzonal = 0.0 }\n"
             "viscosity = { form = \"acceleration\" }\n",
      "parts.toml");
  EXPECT_EQ(model.subzonal_of(0), 1.0);
  EXPECT_EQ(model.viscosity_form_of(0), ViscosityForm::edge);
  EXPECT_EQ(model.subzonal_of(1), 0.0);
  EXPECT_EQ(model.viscosity_form_of(1), ViscosityForm::acceleration);
  try {
    read_case_text(head + "viscosity = { form = \"tensor\" }\n", "bad.toml");
    FAIL() << "an unknown viscosity form was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("form"), std::string::npos) << what;
  }
  try {
    read_case_text(head + "hourglass = { form = \"stiffness\", subzonal = -1.0 }\n", "bad.toml");
    FAIL() << "a negative subzonal coefficient was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("subzonal"), std::string::npos) << e.what();
  }
}
