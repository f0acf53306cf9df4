// The FEM package stepped across ranks (parallel/rank_part.hpp, Solver(const RankPart&)) against
// the serial run of the same model, on 1-4 ranks: an elastic-plastic steel block falling at
// 100 m/s onto a fixed face (and in 3-D spinning), under gravity, with a pressure load on its
// top and a symmetry plane (3-D) or the axis (r-z, quad4). Every rank runs the whole model
// serially beside its part (the blocks are small) and compares what it holds.
//
// Expected: on one rank the same bits as the serial run (the cut is the whole mesh in the same
// order, nothing is shared). On more, not the same bits: the ranks add a shared node's shares in
// rank order, the serial run its elements in colour order. After 400 cycles the masses agree
// within 1e-14, displacements, plastic strains, the whole run's energies (every rank's shares
// added up) and the clock within 1e-12 of their largest value; the velocities, where the fixed
// face rings, within ten times what one ulp in the initial velocities does to the serial run
// itself (measured here, 4e-12 to 6e-12 of the largest velocity). Measured on 2-4 ranks: 2e-16
// (mass), 5e-14 (displacement), 7e-12 (velocity), 1e-13 (plastic strain), 7e-15 (energy). With the
// shared forces not added up the differences are 0.1 to 20.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "case/case_reader.hpp"
#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "mesh/rebar_layers.hpp"
#include "parallel/communicator.hpp"
#include "parallel/rank_part.hpp"
#include "solver/rc_models.hpp"
#include "solver/solver.hpp"

namespace camouflet {
namespace {

constexpr std::int64_t cycles = 400;

// The block: 3-D 12 x 8 x 6 hexes over 60 x 40 x 30 mm; r-z 12 x 16 quads over 30 x 40 mm.
Model impact_model(GeometryMode mode) {
  test::ElasticConstants steel{7850.0, 160e9, 80e9, 0.5e9};
  const bool three_d = mode == GeometryMode::three_d;
  BlockSpec block{"b", 0, {0, 0, 0}, three_d ? std::array<double, 3>{0.06, 0.04, 0.03} : std::array<double, 3>{0.03, 0.04, 0},
                  three_d ? std::array<int, 3>{12, 8, 6} : std::array<int, 3>{12, 16, 1}};
  Model model = test::block_model(mode, {block}, steel);
  model.run.end_time = 1.0;
  model.run.max_cycles = cycles;
  const int up = three_d ? 2 : 1;  // the axis the block falls along
  model.run.gravity[static_cast<std::size_t>(up)] = -9.81;
  BoundaryCondition fixed;
  fixed.kind = BoundaryKind::fixed;
  fixed.set = three_d ? "b.zmin" : "b.ymin";
  model.boundaries.push_back(fixed);
  if (three_d) {
    model.boundaries.push_back(test::symmetry("b.ymin", {0, 1, 0}));
  } else {
    BoundaryCondition axis;
    axis.kind = BoundaryKind::axis;
    axis.set = "b.xmin";
    model.boundaries.push_back(axis);
  }
  model.boundaries.push_back(test::pressure(three_d ? "b.zmax" : "b.ymax", 2e8, TimeHistory{{0.0, 4e-6}, {0.0, 1.0}}));
  return model;
}

// Falling at 100 m/s onto the fixed face and, in 3-D, spinning about the vertical axis at
// 2000 rad/s (72 m/s at the corners), so that every cut carries forces that do not cancel. A rigid
// motion: no velocity gradient without an acceleration, which the default viscosity form
// (along the acceleration, fem_kinematics.cpp) would orient by round-off.
template <int D>
std::vector<double> initial_velocity(const std::vector<double>& x) {
  std::vector<double> v(x.size());
  for (std::size_t n = 0; n < x.size() / D; ++n) {
    const double* p = &x[n * D];
    if (D == 3) {
      v[n * 3 + 0] = -2000.0 * (p[1] - 0.02);
      v[n * 3 + 1] = 2000.0 * (p[0] - 0.03);
      v[n * 3 + 2] = -100.0;
    } else {
      v[n * 2 + 1] = -100.0;
    }
  }
  return v;
}

double largest(const std::vector<double>& values) {
  double m = 0.0;
  for (double v : values) m = std::max(m, std::abs(v));
  return m;
}

// How far a run (`run`, its nodes and elements numbered by `node`, `element` in the whole mesh)
// lies from the serial run: each field's largest difference over its largest serial value, the
// energies' over the largest of the initial energy and the serial run's terms, the clock's over the
// time.
struct Difference {
  double mass = 0.0, displacement = 0.0, velocity = 0.0, plastic_strain = 0.0, energy = 0.0, time = 0.0;
  double bar_stress = 0.0;  // embedded bars' axial stress, over the largest serial one
  bool same_bits = true;
};

template <int D>
Difference difference(const Solver<D>& run, const Solver<D>& serial, const std::vector<std::int64_t>& node,
                      const std::vector<std::int64_t>& element) {
  Difference d;
  const double x_scale = largest(serial.displacement()), v_scale = largest(serial.velocity());
  for (std::size_t l = 0; l < node.size(); ++l) {
    const auto g = static_cast<std::size_t>(node[l]);
    d.mass = std::max(d.mass, std::abs(run.node_mass()[l] - serial.node_mass()[g]) / serial.node_mass()[g]);
    for (std::size_t i = 0; i < D; ++i) {
      const double a = run.displacement()[l * D + i], b = serial.displacement()[g * D + i];
      const double va = run.velocity()[l * D + i], vb = serial.velocity()[g * D + i];
      d.displacement = std::max(d.displacement, std::abs(a - b) / x_scale);
      d.velocity = std::max(d.velocity, std::abs(va - vb) / v_scale);
      d.same_bits = d.same_bits && a == b && va == vb;
    }
  }
  // Plastic strains of every material, each over its own largest.
  for (std::size_t e = 0; e < element.size(); ++e) {
    const auto ge = static_cast<std::size_t>(element[e]);
    const MaterialPoints& p_run = run.batches()[static_cast<std::size_t>(run.elements().material[e])];
    const MaterialPoints& p_serial = serial.batches()[static_cast<std::size_t>(serial.elements().material[ge])];
    const double eps_scale = largest(p_serial.plastic_strain);
    const double a = p_run.plastic_strain[run.elements().point[e]];
    const double b = p_serial.plastic_strain[serial.elements().point[ge]];
    d.plastic_strain = std::max(d.plastic_strain, eps_scale > 0.0 ? std::abs(a - b) / eps_scale : std::abs(a - b));
    d.same_bits = d.same_bits && a == b;
  }
  // The bar segments this run steps, by their place in the whole model's (the serial run's index).
  double sigma_scale = 0.0;
  for (std::size_t s = 0; s < serial.bars().segment_count(); ++s)
    sigma_scale = std::max(sigma_scale, std::abs(serial.bars().axial_stress(s)));
  for (std::size_t s = 0; s < run.bars().segment_count(); ++s) {
    const double a = run.bars().axial_stress(s), b = serial.bars().axial_stress(run.bars().whole_segment(s));
    d.bar_stress = std::max(d.bar_stress, std::abs(a - b) / sigma_scale);
    d.same_bits = d.same_bits && a == b && run.bars().plastic_strain(s) ==
                                               serial.bars().plastic_strain(run.bars().whole_segment(s));
  }
  const EnergyBalance &er = run.energy(), &es = serial.energy();
  d.energy = std::max({std::abs(er.kinetic - es.kinetic), std::abs(er.internal - es.internal),
                       std::abs(er.hourglass - es.hourglass), std::abs(er.boundary_work - es.boundary_work),
                       std::abs(er.initial_total - es.initial_total)}) /
             std::max({es.initial_total, std::abs(es.kinetic), std::abs(es.internal), std::abs(es.boundary_work)});
  d.time = std::abs(run.time() - serial.time()) / serial.time();
  return d;
}

Difference worst_over_ranks(const Communicator& comm, const Difference& d) {
  return {comm.max(d.mass).value,          comm.max(d.displacement).value, comm.max(d.velocity).value,
          comm.max(d.plastic_strain).value, comm.max(d.energy).value,       comm.max(d.time).value,
          comm.max(d.bar_stress).value,     !comm.any(!d.same_bits)};
}

std::string text(const Difference& d) {
  return fmt::format("mass {:.2g}, displacement {:.2g}, velocity {:.2g}, plastic strain {:.2g}, energy {:.2g}, "
                     "time {:.2g}{}{}",
                     d.mass, d.displacement, d.velocity, d.plastic_strain, d.energy, d.time,
                     d.bar_stress > 0.0 ? fmt::format(", bar stress {:.2g}", d.bar_stress) : std::string(),
                     d.same_bits ? " (bit-identical)" : "");
}

using VelocityField = std::vector<double> (*)(const std::vector<double>&);

// Runs `model` serially, serially twice more with every initial velocity component nudged by one
// ulp of max(|v|, v_ref), up and down in turn and then down and up (the problem's own response to
// round-off, the larger of the two: a pattern that strains the elements as a different order of
// sums does, where a nudge of one sign would move a body at rest rigidly and strain nothing), and
// on the world's ranks; compares.
template <int D>
void compare_with_serial(const Model& model, VelocityField velocity, double v_ref, const std::string& problem,
                         bool plastic, double energy_error = 1e-3) {
  const Communicator& comm = world();
  test::use_threads(1);

  Solver<D> serial(model);
  serial.set_initial_velocity(velocity(serial.position()));
  for (std::int64_t c = 0; c < cycles; ++c) serial.step();

  std::vector<std::int64_t> all_nodes(serial.node_count()), all_elements(serial.elements().size());
  for (std::size_t k = 0; k < all_nodes.size(); ++k) all_nodes[k] = static_cast<std::int64_t>(k);
  for (std::size_t k = 0; k < all_elements.size(); ++k) all_elements[k] = static_cast<std::int64_t>(k);
  Difference round_off;
  for (const int first : {1, -1}) {
    Solver<D> nudged(model);
    std::vector<double> v = velocity(nudged.position());
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double size = std::max(std::abs(v[k]), v_ref);
      v[k] += (k % 2 == 0 ? first : -first) * (std::nextafter(size, HUGE_VAL) - size);
    }
    nudged.set_initial_velocity(v);
    for (std::int64_t c = 0; c < cycles; ++c) nudged.step();
    const Difference d = difference(nudged, serial, all_nodes, all_elements);
    round_off = {std::max(round_off.mass, d.mass),
                 std::max(round_off.displacement, d.displacement),
                 std::max(round_off.velocity, d.velocity),
                 std::max(round_off.plastic_strain, d.plastic_strain),
                 std::max(round_off.energy, d.energy),
                 std::max(round_off.time, d.time),
                 std::max(round_off.bar_stress, d.bar_stress),
                 false};
  }

  const RankPart part(comm, model);
  Solver<D> ranks(part);
  ranks.set_initial_velocity(velocity(ranks.position()));
  for (std::int64_t c = 0; c < cycles; ++c) ranks.step();
  ASSERT_EQ(ranks.cycle(), serial.cycle());
  const Difference d =
      worst_over_ranks(comm, difference(ranks, serial, part.local().global_node, part.local().global_element));

  if (comm.rank() == 0)
    std::printf("%d ranks, %s, %lld cycles: %s\n  serial nudged by one ulp: %s\n  energy error %.3g (serial %.3g)\n",
                comm.size(), problem.c_str(), static_cast<long long>(cycles), text(d).c_str(),
                text(round_off).c_str(), ranks.energy().relative_error, serial.energy().relative_error);
  // Each field within 1e-12 of its largest value, or ten times what one ulp of the initial state
  // does to the serial run itself where the problem grows round-off faster.
  const auto bound = [](double nudge) { return std::max(1e-12, 10.0 * nudge); };
  const bool within = d.mass < 1e-14 && d.displacement < bound(round_off.displacement) &&
                      d.plastic_strain < bound(round_off.plastic_strain) && d.energy < bound(round_off.energy) &&
                      d.time < bound(round_off.time) && d.velocity < bound(round_off.velocity) &&
                      d.bar_stress < bound(round_off.bar_stress);
  if (comm.rank() == 0)
    test::record_check(fmt::format("FEM on {} MPI ranks, {}, {} cycles: fields against the serial run", comm.size(),
                                   problem, cycles),
                       "serial run; masses 1e-14; displacement, velocity, plastic strain, energies, time: 1e-12 "
                       "of their largest, or 10x the serial run's own response to one ulp",
                       text(d) + "; one ulp: " + text(round_off), within);
  if (plastic) {
    EXPECT_GT(largest(serial.batches()[0].plastic_strain), 0.1) << "the impact must yield the block";
  }
  if (comm.size() == 1) {
    EXPECT_TRUE(d.same_bits) << "one rank steps the serial run's mesh in its order";
  }
  EXPECT_LT(d.mass, 1e-14);  // one addition of shares
  EXPECT_LT(d.displacement, bound(round_off.displacement));
  EXPECT_LT(d.plastic_strain, bound(round_off.plastic_strain));
  EXPECT_LT(d.energy, bound(round_off.energy));
  EXPECT_LT(d.time, bound(round_off.time));
  EXPECT_LT(d.velocity, bound(round_off.velocity));
  EXPECT_LT(d.bar_stress, bound(round_off.bar_stress));
  EXPECT_LT(ranks.energy().relative_error, energy_error);
  // Every segment stepped by exactly one rank.
  EXPECT_EQ(comm.sum(static_cast<std::int64_t>(ranks.bars().segment_count())),
            static_cast<std::int64_t>(serial.bars().segment_count()));
}

// A soil column (1 x 1 x 10 m, 4 x 4 x 40 hexes, elastic), free, under gravity, its base loaded
// by a 1 MPa pressure pulse (ramped over 0.5 ms, held 1.5 ms, released over 0.5 ms): the pulse runs
// up and leaves through the transmitting top and one transmitting side, whose faces the partition
// cuts; the side's dashpots and static hold act on nodes of every rank.
//
// A load switched on at t = 0 in one step would cost the balance 7 % with the dashpots
// (docs/theory-fem.md); ramped, this column's balance closes within 0.4 %.
Model transmitting_column() {
  Model model = test::block_model(GeometryMode::three_d, {BlockSpec{"c", 0, {0, 0, 0}, {1.0, 1.0, 10.0}, {4, 4, 40}}},
                                  test::ElasticConstants{});
  model.run.end_time = 1.0;
  model.run.max_cycles = cycles;
  model.run.gravity = {0.0, 0.0, -9.81};
  // q on tr D: along the acceleration (the default) the column behind the pulse, straining where
  // its acceleration passes through nought, takes q's direction from round-off, and the serial
  // run moves by 5e-4 of its largest velocity when its initial velocities move by one ulp
  // (docs/theory-fem.md, "Which compression d"); with tr D, by 6e-10.
  model.run.viscosity_form = ViscosityForm::volumetric;
  model.boundaries.push_back(test::pressure("c.zmin", 1e6, TimeHistory{{0.0, 5e-4, 2e-3, 2.5e-3}, {0.0, 1.0, 1.0, 0.0}}));
  for (const char* open : {"c.zmax", "c.xmax"}) {
    BoundaryCondition bc;
    bc.kind = BoundaryKind::transmitting;
    bc.set = open;
    model.boundaries.push_back(bc);
  }
  return model;
}

// The Lame thick cylinder of tests/solver/test_lame_cylinder.cpp (r-z, a = 0.1 m < r < b = 0.2 m,
// axial motion held by symmetry planes), two rows of 20 quads so that the partition cuts across
// and along the wall, the internal pressure of 1 MPa ramped as (1 - cos) over 8 breathing periods
// (400 cycles reach about a third of the ramp).
Model lame_cylinder() {
  const test::ElasticConstants c;
  const double a = 0.1, b = 0.2;
  Model model = test::block_model(GeometryMode::axisymmetric, {BlockSpec{"tube", 0, {a, 0, 0}, {b - a, 0.01, 0}, {20, 2, 1}}}, c);
  model.run.end_time = 1.0;
  model.run.max_cycles = cycles;
  model.boundaries.push_back(test::symmetry("tube.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("tube.ymax", {0, 1, 0}));
  const double ramp = 8.0 * 2.0 * std::numbers::pi * 0.5 * (a + b) / c.p_wave_speed();
  TimeHistory history;
  for (int k = 0; k <= 40; ++k) {
    history.time.push_back(ramp * k / 40.0);
    history.value.push_back(0.5 * (1.0 - std::cos(std::numbers::pi * k / 40.0)));
  }
  model.boundaries.push_back(test::pressure("tube.xmin", 1e6, history));
  return model;
}

std::vector<double> at_rest(const std::vector<double>& x) { return std::vector<double>(x.size(), 0.0); }

// A simply supported reinforced-concrete beam under a pressure pulse (the slab of
// tests/solver/long_rc_slab.cpp, shortened to 400 cycles): half the span by symmetry at mid-span,
// 0.5 m long and 0.1 m deep, the 35 MPa RHT concrete without rate enhancement, Steel 1006 bars
// 20 mm inside each face, its top loaded by 5 MPa for 0.2 ms, the bottom held vertically over the
// last 30 mm at the support. 3-D: 0.05 m of the width (symmetric at y = 0), 24 x 2 x 6 hexes, a
// 12 mm bar (113 mm^2) top and bottom as embedded bars of 20 segments. Plane strain: 24 x 6 quads
// with 5 cm^2/m each face, as embedded bars or as steel layers sharing nodes with the concrete.
// The partition cuts the beam across its span, so that segments reach host nodes of other ranks.
enum class Rebar { bars, layers };
Model rc_beam(GeometryMode mode, Rebar rebar) {
  const bool three_d = mode == GeometryMode::three_d;
  const double half_span = 0.5, depth = 0.1, width = 0.05, cover = 0.02, p0 = 5e6, t_d = 2e-4;
  Model model;
  model.run.mode = mode;
  model.mesh.dimension = three_d ? 3 : 2;
  model.run.end_time = 1.0;
  model.run.max_cycles = cycles;
  model.materials.push_back({"concrete", test::rate_free_concrete(1.0), {}});
  model.materials.push_back({"steel", test::steel_1006(), {}});
  model.parts.push_back(Part{"beam", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"rebar", PartKind::fem, 1, {}, {}, {}, {}, {}, {}, {}});
  // The beam's depth along z in 3-D, along y in plane strain.
  const int up = three_d ? 2 : 1;
  if (rebar == Rebar::layers) {
    RebarWallSpec wall;
    wall.name = "beam";
    wall.concrete_part = 0;
    wall.size = {half_span, depth, 0.0};
    wall.cells = {24, 6, 1};
    wall.layers = {{cover, 5e-4, RebarFace::ymin, 1}, {cover, 5e-4, RebarFace::ymax, 1}};
    add_rebar_wall(model.mesh, wall);
  } else {
    add_block(model.mesh, {"beam", 0, {0, 0, 0}, three_d ? std::array<double, 3>{half_span, width, depth}
                                                         : std::array<double, 3>{half_span, depth, 0},
                           three_d ? std::array<int, 3>{24, 2, 6} : std::array<int, 3>{24, 6, 1}});
    for (const double level : {cover, depth - cover}) {
      BarSet bar;
      bar.name = level < 0.5 * depth ? "bottom" : "top";
      bar.from = {0.0, 0.0, 0.0};
      bar.from[static_cast<std::size_t>(up)] = level;
      if (three_d) bar.from[1] = 0.02;  // m, off the mid-width element face
      bar.to = bar.from;
      bar.to[0] = half_span;
      bar.segments = 20;
      bar.area = three_d ? 1.13e-4 : 5e-4;
      bar.material = 1;
      model.bars.push_back(bar);
    }
  }
  auto& held = model.mesh.node_sets["support"];
  const std::size_t dim = three_d ? 3 : 2;
  for (std::size_t n = 0; n < model.mesh.node_count(); ++n)
    if (model.mesh.coordinates[dim * n] <= 0.03 + 1e-9 && model.mesh.coordinates[dim * n + static_cast<std::size_t>(up)] <= 1e-9)
      held.push_back(static_cast<std::int64_t>(n));
  model.boundaries.push_back(test::velocity("support", up, 0.0));
  model.boundaries.push_back(test::symmetry("beam.xmax", {1, 0, 0}));
  if (three_d) model.boundaries.push_back(test::symmetry("beam.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::pressure(three_d ? "beam.zmax" : "beam.ymax", p0,
                                            TimeHistory{{0.0, t_d, t_d * 1.0001}, {1.0, 1.0, 0.0}}));
  return model;
}

TEST(MpiFemRun, LameCylinderMatchesTheSerialRun) {
  compare_with_serial<2>(lame_cylinder(), at_rest, 1.0, "r-z Lame thick cylinder", false);
}

TEST(MpiFemRun, TransmittingColumnMatchesTheSerialRun) {
  compare_with_serial<3>(transmitting_column(), at_rest, 1.0, "3-D soil column, transmitting top and side", false,
                         1e-2);
}

TEST(MpiFemRun, HexImpactMatchesTheSerialRun) {
  compare_with_serial<3>(impact_model(GeometryMode::three_d), initial_velocity<3>, 100.0, "3-D steel block impact", true);
}
// The 3-D impact with erosion at a geometric strain of 0.15: the elements at the foot leave the
// sums while the run goes on (their mass stays on the nodes), on whichever rank holds them.
TEST(MpiFemRun, HexImpactWithErosionMatchesTheSerialRun) {
  Model model = impact_model(GeometryMode::three_d);
  model.erosion.push_back(ErosionCriteria{0.15, 0.0});
  Solver<3> probe(model);
  probe.set_initial_velocity(initial_velocity<3>(probe.position()));
  for (std::int64_t c = 0; c < cycles; ++c) probe.step();
  EXPECT_GT(probe.eroded_count(), 10u) << "the impact must erode elements for the test to cover erosion";
  if (world().rank() == 0) std::printf("serial run: %zu elements eroded\n", probe.eroded_count());
  compare_with_serial<3>(model, initial_velocity<3>, 100.0, "3-D steel block impact with erosion", true);
}

TEST(MpiFemRun, RcBeamWithEmbeddedBarsMatchesTheSerialRun3d) {
  compare_with_serial<3>(rc_beam(GeometryMode::three_d, Rebar::bars), at_rest, 1.0,
                         "3-D RC beam under a pressure pulse, embedded bars", false);
}

TEST(MpiFemRun, RcSlabWithEmbeddedBarsMatchesTheSerialRunPlaneStrain) {
  compare_with_serial<2>(rc_beam(GeometryMode::plane_strain, Rebar::bars), at_rest, 1.0,
                         "plane-strain RC slab under a pressure pulse, embedded bars", false);
}

TEST(MpiFemRun, RcSlabWithSteelLayersMatchesTheSerialRunPlaneStrain) {
  compare_with_serial<2>(rc_beam(GeometryMode::plane_strain, Rebar::layers), at_rest, 1.0,
                         "plane-strain RC slab under a pressure pulse, steel layers sharing nodes", false);
}

// The example case (cases/examples/rc_beam.toml: the presets' concrete with its rate enhancement
// and P-alpha compaction), read as `camouflet run` reads it.
TEST(MpiFemRun, RcBeamExampleMatchesTheSerialRun) {
  compare_with_serial<3>(read_case(CAMOUFLET_SOURCE_DIR "/cases/examples/rc_beam.toml"), at_rest, 1.0,
                         "the RC beam example (cases/examples/rc_beam.toml)", false);
}

TEST(MpiFemRun, AxisymmetricImpactMatchesTheSerialRun) {
  compare_with_serial<2>(impact_model(GeometryMode::axisymmetric), initial_velocity<2>, 100.0, "r-z steel block impact",
                         true);
}

}  // namespace
}  // namespace camouflet

namespace camouflet {
namespace {

// A failure on one rank stops every rank alike: one node of the block driven into its neighbours
// at 200 km/s with a first step of 1 us inverts the elements around it at once, on the ranks that
// share the node. Every rank throws the same error, the serial run's: the same element by its id
// in the whole mesh (the lowest of those that inverted), the same cycle, and the rank that held it.
TEST(MpiFemRun, AFailureOnOneRankStopsEveryRankNamingTheElement) {
  const Communicator& comm = world();
  test::use_threads(1);
  Model model = impact_model(GeometryMode::three_d);
  model.run.initial_dt = 1e-6;  // s: the node crosses its 5 mm element in the first step
  // The node at the middle of the block's top face, driven down.
  const auto crushed = [](const std::vector<double>& x) {
    std::vector<double> v(x.size(), 0.0);
    for (std::size_t n = 0; n < x.size() / 3; ++n)
      if (std::abs(x[n * 3] - 0.03) < 1e-9 && std::abs(x[n * 3 + 1] - 0.02) < 1e-9 && std::abs(x[n * 3 + 2] - 0.03) < 1e-9)
        v[n * 3 + 2] = -2.0e5;
    return v;
  };
  const auto run = [&](Solver<3>& solver) -> std::optional<NumericalError> {
    solver.set_initial_velocity(crushed(solver.position()));
    try {
      for (int c = 0; c < 200; ++c) solver.step();
    } catch (const NumericalError& e) {
      return e;
    }
    return std::nullopt;
  };
  Solver<3> serial(model);
  const std::optional<NumericalError> expected = run(serial);
  ASSERT_TRUE(expected.has_value()) << "the crushed element must invert";

  const RankPart part(comm, model);
  Solver<3> ranks(part);
  const std::optional<NumericalError> got = run(ranks);
  ASSERT_TRUE(got.has_value());
  if (comm.rank() == 0) std::printf("serial: %s\n%d ranks: %s\n", expected->what(), comm.size(), got->what());
  if (comm.rank() == 0)
    test::record_check(fmt::format("FEM on {} MPI ranks: an element inverted on a cut", comm.size()),
                       "the serial run's error: kind, id, quantity, cycle; the same message on every rank",
                       got->what(),
                       got->kind() == expected->kind() && got->id() == expected->id() &&
                           got->quantity() == expected->quantity() && got->cycle() == expected->cycle());
  EXPECT_EQ(got->kind(), expected->kind());
  EXPECT_EQ(got->id(), expected->id());
  EXPECT_EQ(got->quantity(), expected->quantity());
  EXPECT_EQ(got->cycle(), expected->cycle());
  // The same message on every rank.
  std::vector<char> mine(got->what(), got->what() + std::strlen(got->what()));
  std::vector<char> root = mine;
  comm.broadcast(root, 0);
  EXPECT_EQ(mine, root);
  if (comm.size() > 1) {
    EXPECT_NE(std::string(got->what()).find(" of " + std::to_string(comm.size())), std::string::npos);
  }
}

}  // namespace
}  // namespace camouflet
