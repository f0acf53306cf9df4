// Whole-run benchmark command: builds one of the standard problems
// of bench/bench_problems.hpp, runs it on the requested thread count and
// prints ONE JSON line with the grind time.
//
//   camouflet_bench PROBLEM --threads N [--size S] [--steps K] [--assembly buffers|colours|colour_blocks]
//   PROBLEM: taylor_bar | hex_impact | soil_axisymmetric | buried_coarse
// --assembly: how the FEM element forces are assembled on threads
// (fem_elements.hpp, ForceAssembly); the line then carries an "assembly" key.
//
// Grind time = time / (size x cycles): wall_ns is the wall time, cpu_ns the
// CPU time of all threads (getrusage), i.e. the per-core cost; on a shared,
// loaded machine cpu_ns is the steadier number (OpenMP barriers may spin,
// which counts as CPU time, so compare threads by wall time on an idle machine).
// The set-up (mesh, particle fill, first neighbour search) is not timed; the
// first 3 cycles are warm-up and not counted.
#include <omp.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>

#include "bench_problems.hpp"
#include "case/case_reader.hpp"
#include "solver/run.hpp"
#include "solver/solver.hpp"
#include "sph/sph_system.hpp"

using namespace camouflet;

namespace {

struct Timing {
  std::chrono::steady_clock::time_point wall;
  double cpu = 0.0;  // s, user + system of the whole process
  static Timing now() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return {std::chrono::steady_clock::now(),
            static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
                1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec)};
  }
};

struct Result {
  std::string problem;
  long size = 0;
  long cycles = 0;
  double wall_s = 0.0, cpu_s = 0.0;
  double neighbours = -1.0;  // mean neighbours per particle (SPH only)
  std::string note;
};

double load_at_start = -1.0;
const char* assembly_name = nullptr;  // --assembly, if given

void print(const Result& r, int threads) {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const double work = static_cast<double>(r.size) * static_cast<double>(r.cycles);
  std::printf(
      "{\"problem\":\"%s\",\"threads\":%d,\"size\":%ld,\"cycles\":%ld,\"wall_s\":%.4f,\"cpu_s\":%.4f,",
      r.problem.c_str(), threads, r.size, r.cycles, r.wall_s, r.cpu_s);
  std::printf("\"grind_wall_ns\":%.2f,\"grind_cpu_ns\":%.2f,", 1e9 * r.wall_s / work, 1e9 * r.cpu_s / work);
  if (r.neighbours >= 0.0)
    std::printf("\"mean_neighbours\":%.2f,\"ns_per_pair_cpu\":%.3f,", r.neighbours,
                1e9 * r.cpu_s / (work * r.neighbours));
  if (!r.note.empty()) std::printf("\"note\":\"%s\",", r.note.c_str());
  if (assembly_name) std::printf("\"assembly\":\"%s\",", assembly_name);
  std::printf("\"peak_rss_mib\":%.1f,\"load_average\":%.2f}\n", static_cast<double>(u.ru_maxrss) / 1024.0,
              load_at_start);
  std::fflush(stdout);
}

Result taylor_bar(long size, long steps) {
  const Model model = bench::taylor_bar_model(size);
  // The rigid, frictionless wall z = 0 is a symmetry mirror plane.
  sph::SphSystem<3> bar(model, bench::taylor_bar_options(),
                        {sph::MirrorPlane{2, 0.0, sph::PlaneKind::symmetry}});
  bar.compute_accelerations();
  double t = 0.0;
  auto cycle = [&] {
    const double dt = 0.3 * bar.stable_time_step().dt;
    t += dt;
    bar.step(dt, t);
  };
  for (int k = 0; k < 3; ++k) cycle();
  const Timing start = Timing::now();
  for (long k = 0; k < steps; ++k) cycle();
  const Timing end = Timing::now();
  Result r;
  r.problem = "taylor_bar";
  r.size = static_cast<long>(bar.size());
  r.cycles = steps;
  r.wall_s = std::chrono::duration<double>(end.wall - start.wall).count();
  r.cpu_s = end.cpu - start.cpu;
  double neighbours = 0.0;
  for (int c : bar.particles().neighbour_count) neighbours += c;
  r.neighbours = neighbours / static_cast<double>(bar.size());
  r.note = "t_end " + std::to_string(t * 1e6) + " us";
  return r;
}

template <int D>
Result fem_run(const std::string& name, const Model& model, long steps) {
  Solver<D> solver(model);
  for (int k = 0; k < 3; ++k) solver.step();
  const Timing start = Timing::now();
  for (long k = 0; k < steps; ++k) solver.step();
  const Timing end = Timing::now();
  Result r;
  r.problem = name;
  r.size = static_cast<long>(solver.elements().size());
  r.cycles = steps;
  r.wall_s = std::chrono::duration<double>(end.wall - start.wall).count();
  r.cpu_s = end.cpu - start.cpu;
  char note[96];
  std::snprintf(note, sizeof note, "energy error %.2e", solver.energy().relative_error);
  r.note = note;
  return r;
}

// Problem 4: the coarse buried-structure case, run to 70 ms (or --steps cycles).
bool buried_coarse(int threads, long steps, Result& r) {
  const std::filesystem::path file = "cases/wang2005/coarse.toml";
  if (!std::filesystem::exists(file)) return false;
  Model model = read_case(file);
  model.run.end_time = std::min(model.run.end_time, 0.070);
  if (steps > 0) model.run.max_cycles = steps;
  RunOptions options;
  options.progress = ProgressStyle::none;
  options.threads = threads;
  const Timing start = Timing::now();
  const RunSummary summary = run_model(model, options);
  const Timing end = Timing::now();
  r.problem = "buried_coarse";
  r.size = static_cast<long>(model.mesh.element_count() + model.particles.count());
  r.cycles = summary.cycles;
  r.wall_s = std::chrono::duration<double>(end.wall - start.wall).count();
  r.cpu_s = end.cpu - start.cpu;
  r.note = "simulated " + std::to_string(summary.time * 1e3) + " ms, includes set-up";
  return true;
}

int usage() {
  std::fprintf(stderr,
               "usage: camouflet_bench PROBLEM --threads N [--size S] [--steps K] [--assembly "
               "buffers|colours|colour_blocks]\n"
               "  PROBLEM: taylor_bar | hex_impact | soil_axisymmetric | buried_coarse\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string problem = argv[1];
  int threads = 1;
  long size = 0, steps = 0;
  for (int i = 2; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--threads") && has_value)
      threads = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--size") && has_value)
      size = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--steps") && has_value)
      steps = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--assembly") && has_value) {
      assembly_name = argv[++i];
      if (!std::strcmp(assembly_name, "buffers"))
        set_default_force_assembly(ForceAssembly::buffers);
      else if (!std::strcmp(assembly_name, "colours"))
        set_default_force_assembly(ForceAssembly::colours);
      else if (!std::strcmp(assembly_name, "colour_blocks"))
        set_default_force_assembly(ForceAssembly::colour_blocks);
      else
        return usage();
    } else
      return usage();
  }
  if (threads < 1 || size < 0 || steps < 0) return usage();
  omp_set_num_threads(threads);
  double load[1] = {-1.0};
  if (getloadavg(load, 1) == 1) load_at_start = load[0];

  try {
    Result r;
    if (problem == "taylor_bar") {
      r = taylor_bar(size > 0 ? size : bench::taylor_bar_full_size, steps > 0 ? steps : 500);
    } else if (problem == "hex_impact") {
      r = fem_run<3>(problem, bench::hex_impact_model(size > 0 ? size : bench::hex_impact_full_size),
                     steps > 0 ? steps : 200);
    } else if (problem == "soil_axisymmetric") {
      r = fem_run<2>(problem, bench::soil_axisymmetric_model(size > 0 ? size : bench::soil_full_size),
                     steps > 0 ? steps : 500);
    } else if (problem == "buried_coarse") {
      if (!buried_coarse(threads, steps, r)) {
        std::printf(
            "{\"problem\":\"buried_coarse\",\"threads\":%d,\"skipped\":\"cases/wang2005/coarse.toml "
            "not found (branch buried has not landed it)\"}\n",
            threads);
        return 0;
      }
    } else {
      return usage();
    }
    print(r, threads);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "camouflet_bench %s: %s\n", problem.c_str(), e.what());
    return 1;
  }
  return 0;
}
