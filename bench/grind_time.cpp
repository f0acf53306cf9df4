// Grind-time driver (docs/performance.md, "Targets"): an elastic 3-D block
// of about 100k hex8 elements (or quad4 with --2d) hit by a velocity field,
// stepped for a number of cycles; prints the wall time per element-cycle of
// the whole explicit cycle and the peak memory per element. Threads follow
// OMP_NUM_THREADS; under mpirun the block is cut among the ranks
// (docs/parallel.md) and rank 0 prints the whole run's figures.
//   grind_time [--elements N] [--cycles K] [--2d] [--preset MATERIAL]   (default: elastic rock)
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>

#include "materials/elastic_strength.hpp"
#include "materials/linear_eos.hpp"
#include "materials/registry.hpp"
#include "mesh/block_generator.hpp"
#include "parallel/communicator.hpp"
#include "parallel/rank_part.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

Model elastic_block(int dimension, long elements, const std::string& preset) {
  Model model;
  model.run.mode = dimension == 3 ? GeometryMode::three_d : GeometryMode::plane_strain;
  model.run.end_time = 1.0;
  model.mesh.dimension = dimension;
  BlockSpec block{"block", 0, {0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  if (dimension == 3) {
    const int n = static_cast<int>(std::lround(std::cbrt(static_cast<double>(elements) / 2.0)));
    block.cells = {2 * n, n, n};
    block.size = {2.0, 1.0, 1.0};
  } else {
    const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(elements) / 2.0)));
    block.cells = {2 * n, n, 1};
    block.size = {2.0, 1.0, 0.0};
  }
  add_block(model.mesh, block);
  if (preset.empty()) {
    auto eos = std::make_shared<const LinearEos>(2000.0, 2.0e9);
    auto strength = std::make_shared<const ElasticStrength>(1.5e9);
    model.materials.push_back({"rock", std::make_shared<const Material>("rock", eos, strength), {}});
  } else {  // a registered material preset (soil, concrete, steel): what an element of it costs
    model.materials.push_back(
        {preset, make_material(preset, preset, SourceLocation{"", 0, 0, "--preset"}, {}, {}, {}), {}});
  }
  Part part;
  part.name = "block";
  part.material = 0;
  part.initial_velocity = {0.0, 0.0, 0.0};
  part.initial_velocity[static_cast<std::size_t>(dimension - 1)] = -10.0;
  model.parts.push_back(part);
  BoundaryCondition fixed;
  fixed.kind = BoundaryKind::fixed;
  fixed.set = dimension == 3 ? "block.zmin" : "block.ymin";
  model.boundaries.push_back(fixed);
  return model;
}

// This process's peak resident memory (bytes; Linux's VmHWM), 0 when unknown.
double peak_memory() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0.0;
  char line[256];
  double kb = 0.0;
  while (std::fgets(line, sizeof line, f))
    if (!std::strncmp(line, "VmHWM:", 6)) kb = std::atof(line + 6);
  std::fclose(f);
  return kb * 1024.0;
}

template <int D>
void run(long elements, int cycles, const std::string& preset) {
  const Communicator& comm = world();
  const Model model = elastic_block(D, elements, preset);
  std::unique_ptr<RankPart> part;
  if (comm.size() > 1) part = std::make_unique<RankPart>(comm, model);
  std::unique_ptr<Solver<D>> owner = part ? std::make_unique<Solver<D>>(*part) : std::make_unique<Solver<D>>(model);
  Solver<D>& solver = *owner;
  for (int k = 0; k < 3; ++k) solver.step();  // warm-up: first touch, caches
  comm.barrier();
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  for (int k = 0; k < cycles; ++k) solver.step();
  comm.barrier();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = comm.sum(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
  const double n = static_cast<double>(model.mesh.element_count());
  const double memory = comm.sum(peak_memory());  // every rank holds the whole model while it starts
  // Wall time is the grind time; CPU time (all threads of all ranks) tells a loaded machine apart.
  if (comm.rank() == 0)
    std::printf(
        "%s%s%s: %.0f elements, %d cycles, %d rank(s) x %d thread(s): %.1f ns per element-cycle wall, %.1f ns CPU, "
        "peak memory %.0f bytes per element (energy error %.2e)\n",
        D == 3 ? "hex8" : "quad4", preset.empty() ? "" : " ", preset.c_str(), n, cycles, comm.size(), omp_get_max_threads(), 1e9 * seconds / (n * cycles),
        1e9 * cpu_seconds / (n * cycles), memory / n, solver.energy().relative_error);
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(argc, argv);
  long elements = 100000;
  int cycles = 50;
  bool two_d = false;
  std::string preset;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--elements") && i + 1 < argc)
      elements = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--cycles") && i + 1 < argc)
      cycles = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--2d"))
      two_d = true;
    else if (!std::strcmp(argv[i], "--preset") && i + 1 < argc)
      preset = argv[++i];
    else {
      std::fprintf(stderr, "usage: grind_time [--elements N] [--cycles K] [--2d] [--preset MATERIAL]\n");
      return 2;
    }
  }
  if (two_d)
    run<2>(elements, cycles, preset);
  else
    run<3>(elements, cycles, preset);
  return 0;
}
