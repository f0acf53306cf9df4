// run_model(): the driver around Solver<D> (solver/run.hpp) that advances to
// the end time, feeds RunOutput every cycle and reports progress.
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include "output/progress.hpp"
#include "output/run_output.hpp"
#include "solver/bar_output.hpp"
#include "solver/energy_guard.hpp"
#include "solver/energy_output.hpp"
#include "solver/interrupt.hpp"
#include "solver/run_checkpoints.hpp"
#include "solver/solver.hpp"

namespace camouflet {

namespace {

template <int D>
RunSummary run_dimension(const Model& model, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const auto wall = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  Solver<D> solver(model);
  // Gauges are located in the mesh as given, on a fresh start as on a restart; a dynamic
  // relaxation then brings the model to rest, and t = 0 records that state.
  const bool relaxing = options.restart.empty() && model.run.relaxation.has_value();
  RunOutput output(model, options, solver.snapshot(), !relaxing);
  if (relaxing) {
    // A line every log interval (wall clock): a relaxation runs tens of thousands of cycles.
    const bool report = options.progress != ProgressStyle::none;
    double next_line = model.output.log_interval_s;
    const auto relaxed = solver.relax(*model.run.relaxation, [&](const Solver<D>::Relaxation& r) {
      if (!report || wall() < next_line) return;
      next_line = wall() + model.output.log_interval_s;
      fmt::print(stderr,
                 "dynamic relaxation: {:.4g} s of relaxation ({} cycles, {:.0f} s wall); kinetic energy "
                 "{:.3g} of its peak\n",
                 r.time, r.cycles, wall(), r.kinetic_ratio);
    });
    if (options.progress != ProgressStyle::none)
      fmt::print(stderr,
                 "dynamic relaxation: at rest after {:.6g} s ({} cycles); kinetic energy {:.3g} of its peak "
                 "{:.6g} J\n",
                 relaxed.time, relaxed.cycles, relaxed.kinetic_ratio, relaxed.peak_kinetic);
    output.write_initial(solver.snapshot());
  }
  BarCsv<D> bar_csv(model, options, solver.bars());  // rebar strain histories
  EnergyCsv<D> energy_csv(model, options, solver);   // energy history and its split
  // Checkpoints and restarts: the solver's state, then the output's.
  RunCheckpoints checkpoints(model, options, [&solver, &output](StateVisitor& v) {
    solver.visit_state(v);
    output.visit_state(v);
  });
  if (!options.restart.empty()) {
    checkpoints.restart();
    bar_csv.resume(solver.time(), solver.bars());
    energy_csv.resume(solver);
  }
  EnergyGuard<D> energy_guard(model.run, solver);
  ProgressReporter progress(options.progress, model.run.end_time);
  progress.set_log_interval(model.output.log_interval_s);
  progress.set_origin(solver.time(), wall());  // after a relaxation or at a restart's time
  RunSummary summary;
  const auto summarise = [&](std::string reason, bool failed) {
    summary.time = solver.time();
    summary.cycles = solver.cycle();
    summary.wall_seconds = wall();
    summary.energy = solver.energy();
    summary.last_limit = solver.time_step_limit();
    summary.stop_reason = std::move(reason);
    summary.failed = failed;
  };
  const RunControl& run = model.run;
  // A step shorter than this fraction of the last one would only land on the
  // end time by rounding: stop instead.
  const double end_tolerance = 1e-12 * std::max(run.end_time, 1e-300);
  std::string reason = "end time reached";
  try {
    while (solver.time() < run.end_time - end_tolerance) {
      if (solver.cycle() >= run.max_cycles) {
        reason = "max cycles reached";
        break;
      }
      solver.limit_next_step(run.end_time - solver.time());
      solver.step();
      output.after_cycle(solver.snapshot());
      bar_csv.after_cycle(solver.time(), solver.bars());
      energy_csv.after_cycle(solver);
      if (const int signal = stop_requested()) {
        checkpoints.write(solver.cycle(), solver.time());
        summarise(fmt::format("interrupted by signal {}", signal), true);
        output.finish(solver.snapshot(), summary);
        throw RunInterrupted(
            signal, fmt::format("interrupted by signal {} at cycle {}, time {:.6g} s; checkpoint in {}",
                                signal, solver.cycle(), solver.time(), checkpoints.dir().string()));
      }
      if (checkpoints.due(solver.cycle())) checkpoints.write(solver.cycle(), solver.time());
      const EnergyBalance& energy = solver.energy();
      progress.update(solver.time(), solver.cycle(), solver.time_step_limit().dt,
                      solver.time_step_limit().reason, energy.relative_error, wall());
      energy_guard.after_cycle(solver);
    }
  } catch (const NumericalError& error) {
    progress.done();
    checkpoints.write_failure(solver.cycle(), solver.time());
    summarise(error.what(), true);
    output.finish(solver.snapshot(), summary);
    throw;
  } catch (const std::filesystem::filesystem_error&) {
    // Output failed (disk full, folder gone): one last checkpoint attempt, then exit code 3.
    progress.done();
    checkpoints.try_write(solver.cycle(), solver.time());
    throw;
  }
  progress.done();
  // SPH particles expanded past their smoothing-length cap weigh in their
  // neighbours' sums with a limited volume (sph_system.hpp, quadrature_density).
  if (const auto* particles = solver.particles();
      particles && particles->volume_limited_count() > 0 && options.progress != ProgressStyle::none)
    fmt::print(stderr,
               "note: {} SPH particles end expanded past h_max_factor; their volume in the particle sums "
               "is limited (docs/theory/sph.md, \"Ejecta\")\n",
               particles->volume_limited_count());
  // The final state, so that a later run can go on with a later end time or
  // more cycles; written before finish() adds its closing row and snapshot,
  // which the continued run would not have.
  if (model.checkpoint.enabled()) checkpoints.write(solver.cycle(), solver.time());
  summarise(reason, false);
  output.finish(solver.snapshot(), summary);
  return summary;
}

}  // namespace

RunSummary run_model(const Model& model, const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  if (model.dimension() == 3) return run_dimension<3>(model, options);
  return run_dimension<2>(model, options);
}

}  // namespace camouflet
