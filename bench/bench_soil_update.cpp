// Cost of one constitutive update per point (ns/point) for the three-phase
// soil (EOS root solve + Drucker-Prager + bond damage) beside the elastic
// reference (`linear` EOS + `elastic` strength), through Material::update.
//
//   OMP_NUM_THREADS=1 bench_soil_update --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "materials/material.hpp"
#include "materials/registry.hpp"
#include "materials/sandy_clay_preset.hpp"

namespace {

using namespace camouflet;

std::shared_ptr<const Material> soil() {
  const MaterialPreset p = sandy_clay_wang2005();
  return make_material("soil", "", {}, p.eos, p.strength, p.damage);
}

std::shared_ptr<const Material> elastic() {
  Parameters eos, strength;
  eos.set_string("type", "linear");
  eos.set_number("density", 1917.0);
  eos.set_number("bulk_modulus", 5.5e9);  // the soil's unloading bulk modulus
  strength.set_string("type", "elastic");
  strength.set_number("shear_modulus", 55e6);
  return make_material("elastic", "", {}, eos, strength, Parameters{});
}

// Every point alternates compression and release with its own amplitude, so
// the soil visits its loading, unloading and reloading branches.
void run(benchmark::State& state, const Material& m) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  MaterialPoints pts;
  m.setup(pts, n);
  const double dt = 1e-6;  // s
  long step = 0;
  for (auto _ : state) {
    const double sign = (step % 2 == 0) ? 1.0 : -0.9;
    for (std::size_t i = 0; i < n; ++i) {
      const double rate = 200.0 * sign * (1.0 + 0.5 * std::sin(0.1 * static_cast<double>(i)));  // 1/s
      pts.density_previous[i] = pts.density[i];
      pts.density[i] *= std::exp(rate * dt);
      pts.strain_rate[i] = SymTensor{-rate, 0.1 * rate, 0.2 * rate, 0.3 * rate, 0.0, 0.0};
    }
    m.update(pts, MaterialContext{dt, dt * static_cast<double>(++step)});
    benchmark::DoNotOptimize(pts.pressure.data());
  }
  state.counters["ns_per_point"] =
      benchmark::Counter(static_cast<double>(n) * 1e-9,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_SoilUpdate(benchmark::State& state) {
  run(state, *soil());
}
void BM_ElasticUpdate(benchmark::State& state) {
  run(state, *elastic());
}

}  // namespace

BENCHMARK(BM_SoilUpdate)->Arg(1 << 14)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ElasticUpdate)->Arg(1 << 14)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
