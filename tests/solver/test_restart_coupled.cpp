// Restart determinism for the state added after the first restart tests
// (docs/reliability.md): a model with steel
// rebar layers and embedded bars, one whose elements erode after the restart,
// an SPH zone joined to FEM, and SPH particles sliding on a FEM plate. Each
// run stopped at half its cycles and restarted from its checkpoint must end
// with gauge CSVs and every state array identical bit for bit to the
// uninterrupted run (one thread). A state array a visit_state() forgot makes
// the restarted run drift and the comparison fail.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "coupling/join_models.hpp"
#include "coupling/joined_zone.hpp"
#include "mesh/particle_fill.hpp"
#include "mesh/rebar_layers.hpp"
#include "restart_helpers.hpp"
#include "solver/rc_models.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return test::fresh_test_output(fs::path("restart-coupled") / name);
}

GaugeGroup gauges(const std::string& name, std::initializer_list<std::array<double, 3>> points) {
  GaugeGroup group;
  group.name = name;
  int k = 0;
  for (const auto& p : points) group.points.push_back({"g" + std::to_string(k++), p, {}});
  return group;
}

// Common run settings: a field snapshot half way, a checkpoint at the end.
void run_settings(Model& model, double end_time, std::int64_t max_cycles) {
  model.run.end_time = end_time;
  model.run.max_cycles = max_cycles;
  model.output.field_interval = 0.5 * end_time;
  model.checkpoint.interval_cycles = 1000000;
}

// A plane-strain reinforced-concrete wall strip (RHT concrete, Steel 1006
// layers sharing nodes with it, one embedded bar through its core) struck at
// 20 m/s on its left end: the concrete is crushed and damaged near the
// impact, the steel loads elastically and plastically.
Model rebar_model(std::int64_t max_cycles) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  model.materials.push_back({"concrete", test::rate_free_concrete(1.0), {}});
  model.materials.push_back({"steel", test::steel_1006(), {}});
  model.parts.push_back(Part{"wall", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"rebar", PartKind::fem, 1, {}, {}, {}, {}, {}, {}, {}});
  RebarWallSpec wall;
  wall.name = "wall";
  wall.concrete_part = 0;
  wall.origin = {0.0, 0.0, 0.0};
  wall.size = {0.2, 0.1, 0.0};
  wall.cells = {10, 5, 1};
  wall.layers = {{0.02, 2e-3, RebarFace::ymin, 1}, {0.02, 2e-3, RebarFace::ymax, 1}};
  add_rebar_wall(model.mesh, wall);
  BarSet bar;
  bar.name = "bar";
  bar.from = {0.0, 0.05, 0.0};
  bar.to = {0.2, 0.05, 0.0};
  bar.segments = 10;
  bar.area = 1e-3;
  bar.material = 1;
  model.bars.push_back(bar);
  model.erosion = {{0.0, 0.99}, {}};
  model.boundaries.push_back(test::ramped_velocity("wall.xmin", 0, 20.0, 5e-6));
  model.boundaries.push_back(test::symmetry("wall.xmax", {1, 0, 0}));
  model.gauges.push_back(gauges("wall", {{0.03, 0.05, 0.0}, {0.1, 0.021, 0.0}, {0.15, 0.05, 0.0}}));
  run_settings(model, 6e-5, max_cycles);
  return model;
}

// The erosion test's bar (tests/solver/test_erosion.cpp): steel pulled at
// 10 m/s with a weaker seed in the middle that erodes at a geometric strain
// of 0.15, after the half-way restart: the accumulated strain must survive it.
Model erosion_model(std::int64_t max_cycles) {
  test::ElasticConstants steel{7800.0, 160e9, 80e9, 300e6};
  test::ElasticConstants weak = steel;
  weak.yield_stress = 270e6;
  Model model =
      test::seeded_pulled_bar(test::elastic_material(steel, "steel"), test::elastic_material(weak, "seed"));
  model.erosion = {{0.15, 0.0}, {0.15, 0.0}};
  model.gauges.push_back(gauges("bar", {{0.02, 0.005, 0.0}, {0.05, 0.005, 0.0}, {0.08, 0.005, 0.0}}));
  run_settings(model, 3.4e-4, max_cycles);  // erodes at ~0.29 ms
  return model;
}

// A column FEM | SPH | FEM in one elastic material, the SPH zone joined to
// the FEM (coupling/joined_zone.hpp, as tests/coupling/join_models.hpp),
// driven at its near end: the pulse crosses both joins.
Model join_model(std::int64_t max_cycles) {
  const test::ElasticConstants c;
  const double width = 0.04;
  Model model =
      test::block_model(GeometryMode::plane_strain, {{"bar", 0, {0, 0, 0}, {0.6, width, 0}, {60, 4, 1}}}, c);
  make_joined_zone(model, test::zone_box(model, 0.01, {0.2, 0.0, 0.0}, {0.4, width, 0.0}));
  model.boundaries.push_back(test::ramped_velocity("bar.xmin", 0, 1.0, 2e-5));
  model.boundaries.push_back(test::symmetry("bar.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("bar.ymax", {0, 1, 0}));
  model.gauges.push_back(gauges("column", {{0.1, 0.02, 0.0}, {0.3, 0.02, 0.0}, {0.5, 0.02, 0.0}}));
  run_settings(model, 0.5 / c.p_wave_speed(), max_cycles);
  return model;
}

// The joined column with the FEM element just before the first join (beside the axis of symmetry
// y = 0) eroding as the pulse arrives, before the half-way restart: the restored run must rebuild the
// interface the erosion left (coupling/join_erosion.cpp).
Model join_erosion_model(std::int64_t max_cycles) {
  Model model = join_model(max_cycles);
  test::make_element_erode(model, {0.195, 0.005, 0.0}, 1e-4);
  return model;
}

// The sliding-contact test's disc (tests/coupling/test_sliding_contact.cpp):
// SPH particles striking a FEM plate at 50 m/s, obliquely, with friction;
// the contact is active across the restart.
Model contact_model(std::int64_t max_cycles) {
  const test::ElasticConstants c;
  Model model = test::block_model(GeometryMode::plane_strain,
                                  {{"plate", 0, {-0.04, -0.02, 0}, {0.08, 0.02, 0}, {20, 5, 1}}}, c);
  Part disc;
  disc.name = "disc";
  disc.kind = PartKind::sph;
  disc.material = 0;
  disc.initial_velocity = {10.0, -50.0, 0.0};
  model.parts.push_back(disc);
  ParticleFillSpec fill;
  fill.part = 1;
  fill.spacing = 2e-3;
  fill.region.shape = ParticleRegion::Shape::sphere;
  fill.region.centre = {0.0, 0.0105, 0.0};
  fill.region.radius = 0.01;
  fill_particles(model.particles, fill, model.run.mode);
  Contact contact;
  contact.sph_part = 1;
  contact.face_set = "plate.ymax";
  contact.friction = 0.3;
  model.contacts.push_back(contact);
  model.gauges.push_back(gauges("impact", {{0.0, 0.005, 0.0}, {0.0, -0.002, 0.0}, {0.02, -0.01, 0.0}}));
  run_settings(model, 40e-6, max_cycles);
  return model;
}

// An r-z block of gas (1000 kg/m^3, 1e5 Pa, sound speed 11.8 m/s) thrown at the axis from
// r = 20 mm at 40 m/s, with the smoothed hoop terms and their band ([sph] smoothed_hoop,
// smoothed_hoop_width, viscosity_hoop): it reaches the axis within the first half of the run, so
// the axis images are rebuilt and their number grows from none before the half-way restart. A
// restart must place the ghosts and what follows them (the smoothed hoop stresses, the coupling
// points) by the restored ghost count, not by the count at start-up.
Model axis_band_model(std::int64_t max_cycles) {
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  model.run.cfl = 0.5;
  model.sph.smoothed_hoop = true;
  model.sph.smoothed_hoop_width = 0.5;
  model.sph.viscosity_hoop = true;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1000.0, 1.4, 1e5),
                     test::box_fill({0.02, 0.0, 0.0}, {0.06, 0.04, 0.0}, 0.002), {-40.0, 0.0, 0.0});
  model.gauges.push_back(gauges("gas", {{0.021, 0.02, 0.0}, {0.03, 0.02, 0.0}, {0.05, 0.02, 0.0}}));
  run_settings(model, 1.5e-3, max_cycles);
  return model;
}

std::uint64_t ghost_count(const fs::path& checkpoint) {
  return test::checkpoint_array(checkpoint, "solver.sph.ghost_source").count;
}

std::uint64_t eroded_count(const fs::path& checkpoint) {
  const StateArray a = test::checkpoint_array(checkpoint, "solver.eroded_count");
  std::uint64_t n = 0;
  if (a.bytes.size() == sizeof n) std::memcpy(&n, a.bytes.data(), sizeof n);
  return n;
}

TEST(RestartCoupled, RebarLayersAndEmbeddedBarsBitIdentical) {
  const auto cycles = test::expect_split_run_bit_identical(scratch("rebar"), rebar_model, "wall.csv");
  EXPECT_GT(cycles, 40);
}

TEST(RestartCoupled, ErosionAfterTheRestartBitIdentical) {
  const fs::path root = scratch("erosion");
  const auto cycles = test::expect_split_run_bit_identical(root, erosion_model, "bar.csv");
  EXPECT_GT(cycles, 40);
  // keep = 2: the final checkpoint and the half-way one the restart began from.
  const auto list = list_checkpoints(root / "split" / "checkpoints");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(eroded_count(list[1]), 0u) << "the seed must erode after the restart";
  EXPECT_GE(eroded_count(list[0]), 1u) << "the seed erodes before the end";
}

TEST(RestartCoupled, JoinedSphZoneBitIdentical) {
  const auto cycles = test::expect_split_run_bit_identical(scratch("join"), join_model, "column.csv");
  EXPECT_GT(cycles, 40);
}

TEST(RestartCoupled, JoinElementErodedBeforeTheRestartBitIdentical) {
  const fs::path root = scratch("join-erosion");
  const auto cycles = test::expect_split_run_bit_identical(root, join_erosion_model, "column.csv");
  EXPECT_GT(cycles, 40);
  const auto list = list_checkpoints(root / "split" / "checkpoints");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(eroded_count(list[1]), 1u) << "the element must erode before the restart";
}

TEST(RestartCoupled, SlidingContactBitIdentical) {
  const auto cycles = test::expect_split_run_bit_identical(scratch("contact"), contact_model, "impact.csv");
  EXPECT_GT(cycles, 40);
}

TEST(RestartCoupled, AxisImagesRebuiltBeforeTheRestartBitIdentical) {
  const fs::path root = scratch("axis-band");
  const auto cycles = test::expect_split_run_bit_identical(root, axis_band_model, "gas.csv");
  EXPECT_GT(cycles, 100);
  // The ghost count at the restart differs from that of the first cycle (the start-up's).
  const RunSummary one = run_model(axis_band_model(1), test::quiet_run_options(root / "one"));
  ASSERT_EQ(one.cycles, 1);
  const auto at_start = list_checkpoints(root / "one" / "checkpoints");
  const auto split = list_checkpoints(root / "split" / "checkpoints");
  ASSERT_EQ(at_start.size(), 1u);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_GT(ghost_count(split[1]), ghost_count(at_start[0]) + 10) << "the axis images must grow before the restart";
}

}  // namespace
}  // namespace camouflet
