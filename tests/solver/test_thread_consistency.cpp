// Thread consistency: the same FEM case and the same
// SPH case run on 1 and 2 OpenMP threads give the same gauge histories.
//
// Which equality holds, and why:
// * FEM (hex8): the element forces are scattered colour by colour (blocks of
//   consecutive elements of which no two of a colour share a node,
//   fem/element_colouring.hpp), so each node adds its elements in the same
//   order on any thread count: since 5fe2477 (22 Nov 2026) the histories are bit-identical
//   (measured 0). The check stays within 1e-12 relative to the history's peak,
//   which the per-thread buffer assembly (bench/fem_assemblies.hpp: the same
//   element forces in another grouping) also meets.
// * SPH: the pair sums are pair-symmetric (each pair once, sph_forces.cpp):
//   each thread scatters into its own copy of the particle sums, added in
//   thread order (sph/thread_sums.hpp), so, like the FEM, a fixed thread count
//   is bit-identical (checked exactly) and 1 vs 2 threads equal to round-off
//   (within 1e-12 relative). Before the pair-symmetric sums (gather only) 1 and
//   2 threads were bit-identical.
// * Joined model (SPH zone inside a FEM column, coupling/joined_zone.hpp):
//   FEM forces as above, SPH sums gathered, the join's reactions added in one
//   serial loop: within 1e-12 relative.
// The models are the benchmark's standard problems (bench/bench_problems.hpp)
// at a small size, above the parallel thresholds of fem/parallel.hpp, and a
// joined column of 2560 elements and 1280 particles.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../../bench/bench_problems.hpp"
#include "common/fem_models.hpp"
#include "common/history_difference.hpp"
#include "common/verification.hpp"
#include "coupling/joined_zone.hpp"
#include "fem/parallel.hpp"
#include "solver/solver.hpp"
#include "sph/sph_system.hpp"

using namespace camouflet;
using camouflet::test::relative_difference;

namespace {

// Gauges: vertical velocity of nodes and stress_zz of elements spread through
// the cube, every cycle.
std::vector<double> fem_history(int threads, int cycles) {
  omp_set_num_threads(threads);
  const Model model = bench::hex_impact_model(16 * 16 * 16);  // 4096 elements > parallel_threshold
  Solver<3> solver(model);
  std::vector<double> history;
  const std::size_t nn = solver.node_count(), ne = solver.elements().size();
  for (int c = 0; c < cycles; ++c) {
    solver.step();
    for (std::size_t g = 1; g <= 7; ++g) {
      history.push_back(solver.velocity()[(g * nn / 8) * 3 + 2]);
      history.push_back(solver.elements().stress[g * ne / 8].zz);
    }
    history.push_back(solver.time());
  }
  return history;
}

// Gauges: axial velocity, pressure and position of particles along the bar.
std::vector<double> sph_history(int threads, int cycles) {
  omp_set_num_threads(threads);
  const Model model = bench::taylor_bar_model(2000);
  sph::SphSystem<3> bar(model, bench::taylor_bar_options(),
                        {sph::MirrorPlane{2, 0.0, sph::PlaneKind::symmetry}});
  bar.compute_accelerations();
  std::vector<double> history;
  const std::size_t n = bar.size();
  double t = 0.0;
  for (int c = 0; c < cycles; ++c) {
    const double dt = 0.3 * bar.stable_time_step().dt;
    t += dt;
    bar.step(dt, t);
    for (std::size_t g = 0; g < 8; ++g) {
      const std::size_t i = g * n / 8;
      history.push_back(bar.particles().velocity[i][2]);
      history.push_back(bar.particles().pressure[i]);
      history.push_back(bar.particles().position[i][2]);
    }
    history.push_back(t);
  }
  return history;
}

// A plane-strain column 0.6 m x 0.04 m of 2.5 mm quads whose part [0.1, 0.3]
// m is an SPH zone joined to the FEM (2560 elements > parallel_threshold, 1280
// particles); the zone starts at 1 m/s, loading both joins at once. Gauges:
// node velocities on both sides of each join, particle velocity and pressure,
// every cycle.
std::vector<double> join_history(int threads, int cycles) {
  omp_set_num_threads(threads);
  const test::ElasticConstants c;
  Model model =
      test::block_model(GeometryMode::plane_strain, {{"bar", 0, {0, 0, 0}, {0.6, 0.04, 0}, {240, 16, 1}}}, c);
  Part zone;
  zone.name = "zone";
  zone.kind = PartKind::sph;
  zone.material = 0;
  zone.initial_velocity = {1.0, 0.0, 0.0};
  model.parts.push_back(zone);
  ParticleFillSpec fill;
  fill.part = 1;
  fill.spacing = 2.5e-3;
  fill.region.min = {0.1, 0.0, 0.0};
  fill.region.max = {0.3, 0.04, 0.0};
  make_joined_zone(model, fill);
  model.boundaries.push_back(test::symmetry("bar.ymin", {0, 1, 0}));
  model.boundaries.push_back(test::symmetry("bar.ymax", {0, 1, 0}));
  model.run.end_time = 1.0;
  Solver<2> solver(model);
  EXPECT_GT(solver.elements().size(), static_cast<std::size_t>(parallel_threshold));
  auto nearest_node = [&](double x, double y) {
    std::size_t best = 0;
    double best_d = 1e300;
    for (std::size_t n = 0; n < solver.node_count(); ++n) {
      if (solver.node_mass()[n] <= 0.0) continue;
      const double d = std::hypot(solver.position()[2 * n] - x, solver.position()[2 * n + 1] - y);
      if (d < best_d) best_d = d, best = n;
    }
    return best;
  };
  std::vector<std::size_t> nodes;
  for (double x : {0.09, 0.1, 0.3, 0.31}) nodes.push_back(nearest_node(x, 0.02));
  std::vector<double> history;
  for (int k = 0; k < cycles; ++k) {
    solver.step();
    for (std::size_t n : nodes) {
      history.push_back(solver.velocity()[2 * n]);
      history.push_back(solver.velocity()[2 * n + 1]);
    }
    const auto& pa = solver.particles()->particles();
    for (std::size_t g = 0; g < 8; ++g) {
      const std::size_t i = g * pa.real / 8;
      history.push_back(pa.velocity[i][0]);
      history.push_back(pa.pressure[i]);
    }
    history.push_back(solver.time());
  }
  return history;
}

}  // namespace

TEST(ThreadConsistency, FemHexImpactOneVersusTwoThreads) {
  const std::vector<double> one = fem_history(1, 25);
  const std::vector<double> two = fem_history(2, 25);
  const std::vector<double> two_again = fem_history(2, 25);
  EXPECT_EQ(two, two_again) << "a fixed thread count must give bit-identical histories";
  const double diff = relative_difference(one, two);
  RecordProperty("fem_relative_difference", std::to_string(diff));
  std::printf("hex8: 1 vs 2 threads, max relative difference %.3e\n", diff);
  test::verify({"Thread consistency, hex8 impact 4096 elements, 25 cycles: gauge histories 1 vs 2 threads",
                "identical to round-off", 0.0, diff, 1e-12, false, ""});
}

TEST(ThreadConsistency, SphTaylorBarOneVersusTwoThreads) {
  const std::vector<double> one = sph_history(1, 20);
  const std::vector<double> two = sph_history(2, 20);
  const std::vector<double> two_again = sph_history(2, 20);
  EXPECT_EQ(two, two_again) << "a fixed thread count must give bit-identical histories";
  const double diff = relative_difference(one, two);
  std::printf("SPH: 1 vs 2 threads, max relative difference %.3e\n", diff);
  test::verify(
      {"Thread consistency, SPH Taylor bar ~2000 particles, 20 steps: gauge histories 1 vs 2 threads",
       "identical to round-off (pair-symmetric sums, per-thread buffers)", 0.0, diff, 1e-12, false, ""});
}

TEST(ThreadConsistency, JoinedSphZoneOneVersusTwoThreads) {
  const std::vector<double> one = join_history(1, 20);
  const std::vector<double> two = join_history(2, 20);
  const double diff = relative_difference(one, two);
  std::printf("joined SPH zone: 1 vs 2 threads, max relative difference %.3e\n", diff);
  test::verify(
      {"Thread consistency, joined SPH zone in a FEM column (2560 quads, 1280 particles), 20 cycles: "
       "gauge histories 1 vs 2 threads",
       "identical to round-off", 0.0, diff, 1e-12, false, ""});
}
