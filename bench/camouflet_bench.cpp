// Whole-run benchmark command: builds one of the standard problems
// of bench/bench_problems.hpp, runs it on the requested thread count and
// prints ONE JSON line with the grind time.
//
//   camouflet_bench PROBLEM --threads N [--size S] [--steps K]
//   PROBLEM: taylor_bar | hex_impact | sedov_hex | soil_axisymmetric | buried_coarse | buried_coarse3d |
//            buried_default | buried_paper (the cases of cases/wang2005/ to 70 ms)
// Each line also says what was measured and where: commit, build type and flags, compiler,
// host and CPU model, thread count, the load average at the start, and the problem's
// parameters (bench/bench_problems.hpp), so that a line read months later can be compared.
//
// Grind time = time / (size x cycles): wall_ns is the wall time, cpu_ns the
// CPU time of all threads (getrusage), i.e. the per-core cost; on a shared,
// loaded machine cpu_ns is the steadier number (OpenMP barriers may spin,
// which counts as CPU time, so compare threads by wall time on an idle machine).
// The set-up (mesh, particle fill, first neighbour search) is not timed; the
// first 3 cycles are warm-up and not counted.
#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
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
  std::string parameters;    // the problem as built: resolution, material, steps, CFL
  std::string note;
};

// JSON string contents: quotes and backslashes escaped, control characters dropped.
std::string json_text(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out;
}

std::string host_name() {
  char name[256] = {};
  return gethostname(name, sizeof name - 1) == 0 ? std::string(name) : "unknown";
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

#ifndef CAMOUFLET_BENCH_COMMIT
#define CAMOUFLET_BENCH_COMMIT "unknown"
#endif
#ifndef CAMOUFLET_BENCH_FLAGS
#define CAMOUFLET_BENCH_FLAGS "unknown"
#endif
#ifndef CAMOUFLET_BENCH_BUILD_TYPE
#define CAMOUFLET_BENCH_BUILD_TYPE "unknown"
#endif

double load_at_start = -1.0;

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
  if (!r.parameters.empty()) std::printf("\"parameters\":\"%s\",", json_text(r.parameters).c_str());
  if (!r.note.empty()) std::printf("\"note\":\"%s\",", json_text(r.note).c_str());
  std::printf("\"commit\":\"%s\",\"build_type\":\"%s\",\"flags\":\"%s\",\"compiler\":\"%s\",",
              json_text(CAMOUFLET_BENCH_COMMIT).c_str(), json_text(CAMOUFLET_BENCH_BUILD_TYPE).c_str(),
              json_text(CAMOUFLET_BENCH_FLAGS).c_str(), json_text(__VERSION__).c_str());
  std::printf("\"host\":\"%s\",\"cpu\":\"%s\",\"omp_max_threads\":%d,", json_text(host_name()).c_str(),
              json_text(cpu_model()).c_str(), omp_get_max_threads());
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
  const bench::TaylorBar geometry;
  char parameters[200];
  std::snprintf(
      parameters, sizeof parameters,
      "copper bar R %.2f mm L %.1f mm at %.0f m/s, linear EOS + von Mises, spacing %.4g mm, smoothing "
      "factor %.2f, CFL 0.3, %ld steps",
      geometry.radius * 1e3, geometry.length * 1e3, geometry.speed,
      geometry.spacing_for(size > 0 ? size : bench::taylor_bar_full_size) * 1e3,
      bench::taylor_bar_options().smoothing_factor, steps);
  r.parameters = parameters;
  r.note = "t_end " + std::to_string(t * 1e6) + " us";
  return r;
}

template <int D>
Result fem_run(const std::string& name, const std::string& parameters, const Model& model, long steps) {
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
  r.parameters = parameters + ", CFL " + std::to_string(model.run.cfl).substr(0, 4) + ", " +
                 std::to_string(steps) + " steps";
  return r;
}

// Problem 4: a buried-structure case of cases/wang2005/ (coarse, coarse3d, default, paper), run to
// 70 ms (or --steps cycles), set-up included: the whole-run wall time a user waits for.
bool buried_case(const std::string& name, int threads, long steps, Result& r) {
  const std::filesystem::path file = "cases/wang2005/" + name + ".toml";
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
  r.problem = "buried_" + name;
  r.size = static_cast<long>(model.mesh.element_count() + model.particles.count());
  r.cycles = summary.cycles;
  r.wall_s = std::chrono::duration<double>(end.wall - start.wall).count();
  r.cpu_s = end.cpu - start.cpu;
  r.parameters = file.string() + " to 70 ms";
  r.note = "simulated " + std::to_string(summary.time * 1e3) + " ms, includes set-up";
  return true;
}

int usage() {
  std::fprintf(stderr,
               "usage: camouflet_bench PROBLEM --threads N [--size S] [--steps K]\n"
               "  PROBLEM: taylor_bar | hex_impact | sedov_hex | soil_axisymmetric | buried_coarse | "
               "buried_coarse3d | buried_default | buried_paper\n");
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
    else
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
      const long n = size > 0 ? size : bench::hex_impact_full_size;
      r = fem_run<3>(problem,
                     "steel cube 45 mm at 100 m/s onto a fixed face, hex8, " + std::to_string(n) + " asked",
                     bench::hex_impact_model(n), steps > 0 ? steps : 200);
    } else if (problem == "sedov_hex") {
      const long n = size > 0 ? size : bench::sedov_full_size;
      r = fem_run<3>(
          problem,
          "Sedov octant in ideal gas (LULESH's problem), edge 1.125, hex8, " + std::to_string(n) + " asked",
          bench::sedov_hex_model(n), steps > 0 ? steps : 200);
    } else if (problem == "soil_axisymmetric") {
      const long n = size > 0 ? size : bench::soil_full_size;
      r = fem_run<2>(problem, "r-z sandy clay 1 m x 2 m under 20 MPa, quad4, " + std::to_string(n) + " asked",
                     bench::soil_axisymmetric_model(n), steps > 0 ? steps : 500);
    } else if (problem.rfind("buried_", 0) == 0) {
      const std::string name = problem.substr(7);
      if (!buried_case(name, threads, steps, r)) {
        std::printf(
            "{\"problem\":\"%s\",\"threads\":%d,\"skipped\":\"cases/wang2005/%s.toml "
            "not found (run from the repository root)\"}\n",
            problem.c_str(), threads, name.c_str());
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
