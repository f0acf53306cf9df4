// Cost of one constitutive update per point (ns/point) for the three-phase
// soil (EOS root solve + Drucker-Prager + bond damage) beside an elastic
// reference (linear polynomial EOS p = K mu + a Hookean deviator defined here,
// since the project's `elastic` strength lives on another branch).
//
//   bench_soil_update --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "materials/material.hpp"
#include "materials/registry.hpp"
#include "materials/sandy_clay_preset.hpp"

namespace {

using namespace camouflet;

// Hooke's law for the deviator: the cheapest strength model, as the baseline.
class HookeStrength final : public StrengthModel {
 public:
  explicit HookeStrength(double g) : g_(g) {}
  std::string type() const override { return "hooke (benchmark baseline)"; }
  void initialise(MaterialPoints& pts) const override {
    for (auto& g : pts.shear_modulus) g = g_;
  }
  void update(MaterialPoints& pts, const MaterialContext& ctx) const override {
    const std::size_t n = pts.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) pts.deviator[i] += deviator(pts.strain_rate[i]) * (2.0 * g_ * ctx.dt);
  }

 private:
  double g_;
};

std::shared_ptr<const Material> soil() {
  const MaterialPreset p = sandy_clay_wang2005();
  return make_material("soil", "", {}, p.eos, p.strength, p.damage);
}

std::shared_ptr<const Material> elastic() {
  Parameters eos;
  eos.set_string("type", "polynomial");
  eos.set_number("density", 1917.0);
  eos.set_number("a1", 5.5e9);  // the soil's unloading bulk modulus
  return std::make_shared<const Material>("elastic", make_eos(eos), std::make_shared<HookeStrength>(55e6));
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
