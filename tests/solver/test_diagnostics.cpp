// Numerical-failure diagnostics: each failure
// is provoked by a small model and the message must name the right entity id,
// its material and position, the cycle, the time and the failed quantity; the
// run writes a final snapshot, summary and failure checkpoint.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "../sph/sph_test_models.hpp"
#include "checkpoint/checkpoint_file.hpp"
#include "common/fem_models.hpp"
#include "solver/energy_guard.hpp"
#include "solver/run.hpp"
#include "solver/solver.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

Model block() {
  return test::block_model(GeometryMode::plane_strain, {{"block", 0, {0, 0, 0}, {1, 1, 0}, {3, 3, 1}}},
                           test::ElasticConstants{});
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Diagnostics, NonFiniteVelocityNamesTheNode) {
  test::use_threads(1);
  Model model = block();
  Solver<2> solver(model);
  solver.velocity()[2 * 6 + 1] = std::numeric_limits<double>::quiet_NaN();  // node 7, y
  try {
    solver.step();
    FAIL() << "a NaN velocity must stop the run";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.kind(), EntityKind::node);
    EXPECT_EQ(e.id(), 7);
    EXPECT_EQ(e.quantity(), "velocity");
    EXPECT_EQ(e.cycle(), 0);  // found in the state at t_n, before forces spread it
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, "node 7 (position (")) << m;
    EXPECT_TRUE(contains(m, "velocity at cycle 0, time")) << m;
  }
}

TEST(Diagnostics, NodeLeavingTheDomainIsNamed) {
  test::use_threads(1);
  Model model = block();
  model.run.end_time = 1.0;
  model.run.domain_max = {1.01, 10.0, 10.0};  // m: the block's right face is at x = 1
  model.mesh.node_sets["right"] = {3, 7, 11, 15};
  for (const char* set : {"right"}) model.boundaries.push_back(test::velocity(set, 0, 100.0));
  RunOptions o;
  o.progress = ProgressStyle::none;
  try {
    run_model(model, o);
    FAIL() << "the node must leave the domain";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.kind(), EntityKind::node);
    EXPECT_EQ(e.id(), 4);  // the lowest-numbered node of the pushed face
    EXPECT_EQ(e.quantity(), "position");
    EXPECT_TRUE(contains(e.what(), "left the domain box: coordinate 1 = ")) << e.what();
    EXPECT_TRUE(contains(e.what(), "outside [-inf, 1.01] m")) << e.what();
  }
}

TEST(Diagnostics, ParticleLeavingTheDomainIsNamedAndAFailureCheckpointWritten) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.run.end_time = 1e-3;
  model.run.domain_max = {0.05, 1.0, 1.0};
  const auto solid = test::elastic_solid("steel", 7800.0, 1.6e11, 8.0e10);
  test::add_sph_part(model, "striker", solid, test::box_fill({0.0, 0.0, 0.0}, {0.04, 0.04, 0.0}, 0.004),
                     {500.0, 0.0, 0.0});
  const fs::path out = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "diagnostics" / "particle";
  fs::remove_all(out);
  RunOptions o;
  o.progress = ProgressStyle::none;
  o.threads = 1;
  o.output_dir = out;
  try {
    run_model(model, o);
    FAIL() << "a particle must leave the domain";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.kind(), EntityKind::particle);
    EXPECT_EQ(e.quantity(), "position");
    // 10 x 10 particles; one of the column at the largest x (the lowest id of them) is named.
    EXPECT_GE(e.id(), 1);
    EXPECT_LE(e.id(), 100);
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, "particle " + std::to_string(e.id()) + " (material 'striker', position (0.05"))
        << m;
    EXPECT_TRUE(contains(m, "position at cycle ")) << m;
  }
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_TRUE(fs::exists(out / "fields.pvd"));
  ASSERT_TRUE(fs::exists(out / "failure.h5"));
  EXPECT_NO_THROW(read_checkpoint(out / "failure.h5"));
}

TEST(Diagnostics, EnergyErrorAboveTheLimitStopsTheRun) {
  test::use_threads(1);
  Model model = block();
  model.run.end_time = 0.1;  // s: past the guard's 100 warm-up cycles
  model.run.energy_error_limit = 1e-14;
  model.run.cfl = 0.9;
  model.mesh.node_sets["top"] = {12, 13, 14, 15};
  model.boundaries.push_back(test::velocity("top", 1, -5.0));
  RunOptions o;
  o.progress = ProgressStyle::none;
  try {
    run_model(model, o);
    FAIL() << "the energy error must exceed 1e-14";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.quantity(), "energy balance");
    EXPECT_TRUE(contains(e.what(), "exceeds energy_error_limit 1.000e-14")) << e.what();
    EXPECT_EQ(e.cycle(), EnergyGuard<2>::warm_up_cycles);  // the first cycle judged
  }
}

// A broken balance: after 200 clean cycles every node velocity is raised by
// 1 % per cycle (as a faulty force term would), creating kinetic energy that
// no force did work for. The guard the run loop uses stops it past the
// default 5 % and names the kinetic energy; the same model untouched stays
// far inside. (The exit code of the failure: test_end_to_end.cpp.)
Model pushed_block() {
  Model model = block();
  model.run.end_time = 1.0;
  model.run.cfl = 0.9;
  model.mesh.node_sets["top"] = {12, 13, 14, 15};
  model.boundaries.push_back(test::velocity("top", 1, -5.0));
  return model;
}

TEST(Diagnostics, EnergyCreatedDuringTheRunStopsItNamingTheTerm) {
  test::use_threads(1);
  EXPECT_DOUBLE_EQ(RunControl{}.energy_error_limit, 0.05);
  const Model model = pushed_block();
  {
    Solver<2> clean(model);
    EnergyGuard<2> guard(model.run, clean);
    for (int k = 0; k < 600; ++k) {
      clean.step();
      ASSERT_NO_THROW(guard.after_cycle(clean)) << "cycle " << clean.cycle();
    }
    EXPECT_LT(clean.energy().relative_error, 0.01);
  }
  Solver<2> solver(model);
  EnergyGuard<2> guard(model.run, solver);
  try {
    for (int k = 0; k < 600; ++k) {
      solver.step();
      if (solver.cycle() > 200)
        for (double& v : solver.velocity()) v *= 1.01;
      guard.after_cycle(solver);
    }
    FAIL() << "raising the velocities must break the balance";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.quantity(), "energy balance");
    EXPECT_GT(e.cycle(), 200);
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, "exceeds energy_error_limit 5.000e-02")) << m;
    EXPECT_TRUE(contains(m, "the largest change since cycle")) << m;
    EXPECT_TRUE(contains(m, "is kinetic +")) << m;
    EXPECT_TRUE(contains(m, "at cycle " + std::to_string(e.cycle()))) << m;
  }
}

TEST(Diagnostics, TimeStepBelowMinimumNamesTheElement) {
  test::use_threads(1);
  Model model = block();
  model.run.min_dt = 1.0;
  try {
    Solver<2> solver(model);
    FAIL() << "dt below min_dt must stop the run";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.quantity(), "time step");
    EXPECT_EQ(e.kind(), EntityKind::element);
    EXPECT_EQ(e.id(), 1);  // all equal: the lowest id
    EXPECT_TRUE(contains(e.what(), "is below min_dt 1 s")) << e.what();
  }
}

}  // namespace
}  // namespace camouflet
