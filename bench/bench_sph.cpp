// SPH micro-benchmarks: the cell-list neighbour search
// and the force loop, on gas blocks in 2-D and 3-D. Counters report the mean
// neighbour count and the time per particle.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "materials/registry.hpp"
#include "mesh/particle_fill.hpp"
#include "sph/sph_system.hpp"

using namespace camouflet;

namespace {

Model gas_block(int dimension, long particles) {
  Model model;
  model.run.mode = dimension == 3 ? GeometryMode::three_d : GeometryMode::plane_strain;
  Parameters eos;
  eos.set_string("type", "ideal_gas");
  eos.set_number("density", 1.0);
  eos.set_number("gamma", 1.4);
  eos.set_number("specific_energy", 2.5);
  model.materials.push_back({"gas", make_material("gas", "", {}, eos, Parameters{}, Parameters{}), {}});
  Part part;
  part.name = "gas";
  part.kind = PartKind::sph;
  part.material = 0;
  model.parts.push_back(part);
  ParticleFillSpec spec;
  spec.region.min = {0, 0, 0};
  spec.region.max = {1, 1, 1};
  spec.spacing = std::pow(1.0 / static_cast<double>(particles), 1.0 / dimension);
  fill_particles(model.particles, spec, model.run.mode);
  return model;
}

template <int D>
void neighbour_search(benchmark::State& state) {
  const Model model = gas_block(D, state.range(0));
  sph::SphSystem<D> sph(model, sph::SphOptions{});
  const auto& p = sph.particles();
  sph::NeighbourSearch<D> search;
  for (auto _ : state) {
    search.build(p.position, p.smoothing_length, sph.size(), 0.3 * p.smoothing_length[0]);
    benchmark::DoNotOptimize(search.pair_count());
  }
  state.counters["particles"] = static_cast<double>(sph.size());
  state.counters["mean_listed"] = static_cast<double>(search.pair_count()) / static_cast<double>(sph.size());
  state.counters["ns_per_particle"] =
      benchmark::Counter(static_cast<double>(sph.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <int D>
void force_loop(benchmark::State& state) {
  const Model model = gas_block(D, state.range(0));
  sph::SphSystem<D> sph(model, sph::SphOptions{});
  sph.compute_accelerations();
  for (auto _ : state) {
    sph.compute_accelerations();
    benchmark::DoNotOptimize(sph.particles().acceleration.data());
  }
  double neighbours = 0.0;
  for (int c : sph.particles().neighbour_count) neighbours += c;
  state.counters["particles"] = static_cast<double>(sph.size());
  state.counters["mean_neighbours"] = neighbours / static_cast<double>(sph.size());
  state.counters["ns_per_particle"] =
      benchmark::Counter(static_cast<double>(sph.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <int D>
void full_cycle(benchmark::State& state) {
  const Model model = gas_block(D, state.range(0));
  sph::SphSystem<D> sph(model, sph::SphOptions{});
  sph.compute_accelerations();
  const double dt = 0.1 * sph.stable_time_step().dt;
  double t = 0.0;
  for (auto _ : state) {
    t += dt;
    sph.step(dt, t);
  }
  state.counters["particles"] = static_cast<double>(sph.size());
  state.counters["ns_per_particle_cycle"] =
      benchmark::Counter(static_cast<double>(sph.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// The whole cycle on a block whose particles are stored in random order (as
// after long mixing, or a fill that is not in cell order), with re-sorting by
// cell off (range(1) = 0) or after every list rebuild (range(1) = 1): the
// sort happens in the first iterations, the timing shows the memory-order effect.
template <int D>
void full_cycle_scattered(benchmark::State& state) {
  Model model = gas_block(D, state.range(0));
  auto& p = model.particles;
  std::vector<std::size_t> order(p.count());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  ParticleSet shuffled;
  for (const std::size_t i : order) {
    for (int d = 0; d < D; ++d) shuffled.coordinates.push_back(p.coordinates[i * D + d]);
    shuffled.volume.push_back(p.volume[i]);
    shuffled.spacing.push_back(p.spacing[i]);
    shuffled.particle_part.push_back(p.particle_part[i]);
  }
  model.particles = shuffled;
  sph::SphOptions options;
  options.sort_interval = static_cast<int>(state.range(1));
  sph::SphSystem<D> sph(model, options);
  sph.compute_accelerations();
  const double dt = 0.1 * sph.stable_time_step().dt;
  double t = 0.0;
  for (int warm = 0; warm < 2; ++warm) sph.step(dt, t += dt);
  for (auto _ : state) {
    t += dt;
    sph.step(dt, t);
  }
  state.counters["particles"] = static_cast<double>(sph.size());
  state.counters["sorts"] = static_cast<double>(sph.sorts());
  state.counters["ns_per_particle_cycle"] =
      benchmark::Counter(static_cast<double>(sph.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(full_cycle_scattered<2>)->Args({100000, 0})->Args({100000, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(full_cycle_scattered<3>)->Args({100000, 0})->Args({100000, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(neighbour_search<2>)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(neighbour_search<3>)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(force_loop<2>)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(force_loop<3>)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(full_cycle<2>)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(full_cycle<3>)->Arg(100000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
