// Google Benchmark of the element force loop: stress
// divergence plus hourglass resistance of one-point hexes and quads, the
// dominant kernel of the FEM cycle. Reports time per element.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fem/fem_elements.hpp"
#include "fem_assemblies.hpp"
#include "mesh/block_generator.hpp"

namespace {

using namespace camouflet;

template <int D>
struct ForceProblem {
  FemMesh mesh;
  FemElements<D> elements;
  std::vector<double> velocity, force, hourglass_force;

  explicit ForceProblem(int n) {
    mesh.dimension = D;
    BlockSpec block{"b", 0, {0, 0, 0}, {1, 1, 1}, {n, n, D == 3 ? n : 1}, {1, 1, 1}};
    add_block(mesh, block);
    elements =
        FemElements<D>(mesh, D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d, mesh.coordinates);
    const std::size_t ne = elements.size(), nn = mesh.node_count();
    for (std::size_t e = 0; e < ne; ++e) {
      elements.density[e] = 2000.0;
      elements.wave_speed[e] = 1500.0;
      elements.stress[e] = SymTensor{-1e6, -2e6, -1.5e6, 3e5, -1e5, 2e5};
    }
    velocity.resize(nn * D);
    for (std::size_t k = 0; k < velocity.size(); ++k) velocity[k] = std::sin(0.37 * static_cast<double>(k));
    force.assign(nn * D, 0.0);
    hourglass_force.assign(nn * D, 0.0);
  }
};

template <int D>
void element_forces(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const auto assembly = static_cast<bench::Assembly>(state.range(2));
  ForceProblem<D> p(static_cast<int>(state.range(0)));
  bench::AssemblyScratch scratch;
  const HourglassControl hg{HourglassForm::viscous, 0.1};
  for (auto _ : state) {
    bench::add_internal_forces(assembly, p.elements, p.mesh.coordinates.data(), p.velocity.data(),
                               p.force.data(), p.hourglass_force.data(), hg, 1e-6, scratch);
    benchmark::DoNotOptimize(p.force.data());
    benchmark::ClobberMemory();
  }
  // items_per_second = elements per second; its inverse is the time per element.
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.elements.size()));
}

}  // namespace

// Arguments: cells per direction, threads, assembly (bench::Assembly: 0 buffers, 1 colours, 2 colour_blocks,
// 3 element_order).
void arguments(benchmark::internal::Benchmark* b, int cells) {
  for (int threads : {1, 2})
    for (int assembly : {0, 1, 2, 3}) b->Args({cells, threads, assembly});
}
BENCHMARK(element_forces<3>)
    ->Apply([](benchmark::internal::Benchmark* b) { arguments(b, 32); })
    ->Apply([](benchmark::internal::Benchmark* b) { arguments(b, 48); })
    ->ComputeStatistics("min",
                        [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
    ->Unit(benchmark::kMillisecond);
BENCHMARK(element_forces<2>)
    ->Apply([](benchmark::internal::Benchmark* b) { arguments(b, 256); })
    ->ComputeStatistics("min",
                        [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
