// run_model(): the driver around Solver<D> (solver/run.hpp) that advances to
// the end time, feeds RunOutput every cycle and reports progress.
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>

#include "output/progress.hpp"
#include "output/vtu_writer.hpp"
#include "parallel/communicator.hpp"
#include "parallel/rank_part.hpp"
#include "parallel/whole_snapshot.hpp"
#include "output/run_output.hpp"
#include "solver/bar_output.hpp"
#include "solver/energy_guard.hpp"
#include "solver/energy_output.hpp"
#include "solver/interrupt.hpp"
#include "solver/run_checkpoints.hpp"
#include "solver/solver.hpp"

namespace camouflet {

namespace fs = std::filesystem;

namespace {

// On MPI ranks (docs/parallel.md): what each rank steps, and the whole model's snapshot that rank 0
// writes. Every rank walks through run_dimension alike, so that their exchanges pair up; only
// rank 0 writes files and progress lines.
struct Ranks {
  Ranks(const Communicator& comm, const Model& whole) : part(comm, whole), whole_snapshot(whole) {
    for (const std::int64_t n : part.local().global_node) node_ids.push_back(n + 1);
    for (const std::int64_t e : part.local().global_element) element_ids.push_back(e + 1);
  }
  RankPart part;
  WholeSnapshot whole_snapshot;
  std::vector<std::int64_t> node_ids, element_ids;  // 1-based, in the whole mesh (the pieces' ids)
  bool writes() const { return part.comm().rank() == 0; }
};

template <int D>
RunSummary run_dimension(const Model& model, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const auto wall = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const Communicator& comm = world();
  std::unique_ptr<Ranks> ranks;
  if (comm.size() > 1) ranks = std::make_unique<Ranks>(comm, model);
  const bool writes = !ranks || ranks->writes();
  std::unique_ptr<Solver<D>> solver_owner =
      ranks ? std::make_unique<Solver<D>>(ranks->part) : std::make_unique<Solver<D>>(model);
  Solver<D>& solver = *solver_owner;
  // The snapshot the output reads: the solver's own, or on ranks the whole model's on rank 0
  // (every rank takes part in assembling it; elsewhere it is empty and nothing reads it).
  FieldSnapshot mine;
  const auto snapshot = [&]() -> const FieldSnapshot& {
    mine = solver.snapshot();
    return ranks ? ranks->whole_snapshot.gather(ranks->part, mine) : mine;
  };
  // Gauges are located in the mesh as given, on a fresh start as on a restart; a dynamic
  // relaxation then brings the model to rest, and t = 0 records that state.
  const bool relaxing = options.restart.empty() && model.run.relaxation.has_value();
  std::optional<RunOutput> output_owner;
  {
    const FieldSnapshot& initial = snapshot();
    // On ranks the first snapshot waits for the pieces (below).
    if (writes) output_owner.emplace(model, options, initial, !relaxing && !ranks);
  }
  RunOutput* output = output_owner ? &*output_owner : nullptr;
  if (ranks) {
    // The gauges are located: from here on the snapshot gathers only what they read, however
    // large the mesh. Rank 0's lists (its output's), passed to every rank: the node count, the
    // nodes, the elements.
    std::vector<std::int64_t> ids;
    if (output) {
      ids.push_back(static_cast<std::int64_t>(output->sampled_nodes().size()));
      ids.insert(ids.end(), output->sampled_nodes().begin(), output->sampled_nodes().end());
      ids.insert(ids.end(), output->sampled_elements().begin(), output->sampled_elements().end());
    }
    std::vector<char> bytes(ids.size() * sizeof(std::int64_t));
    std::memcpy(bytes.data(), ids.data(), bytes.size());
    comm.broadcast(bytes, 0);
    ids.resize(bytes.size() / sizeof(std::int64_t));
    std::memcpy(ids.data(), bytes.data(), bytes.size());
    const std::span<const std::int64_t> all(ids);
    const auto nodes = static_cast<std::size_t>(all[0]);
    ranks->whole_snapshot.restrict_to(ranks->part, all.subspan(1, nodes), all.subspan(1 + nodes));
  }
  // On ranks: every rank writes its piece of snapshot `index` (rank 0's decision, passed on here
  // or in the cycle's exchange; -1: none), then all wait, so that the .pvtu rank 0 writes next
  // names complete pieces.
  const auto write_pieces = [&](int index) {
    if (index < 0 || options.output_dir.empty()) return;
    mine = solver.snapshot();
    const fs::path path = RunOutput::piece_path(options.output_dir, index, comm.rank());
    fs::create_directories(path.parent_path());
    write_mesh_vtu(path, mine, ranks->node_ids, ranks->element_ids);
    comm.barrier();
  };
  const auto shared_index = [&](int index_on_rank0) {
    std::vector<char> bytes(sizeof(int));
    std::memcpy(bytes.data(), &index_on_rank0, sizeof(int));
    comm.broadcast(bytes, 0);
    int index = -1;
    std::memcpy(&index, bytes.data(), sizeof(int));
    return index;
  };
  if (ranks) {
    if (output) output->write_fields_in_pieces(comm.size());
    if (!relaxing) {
      write_pieces(shared_index(output ? output->initial_snapshot() : -1));
      const FieldSnapshot& initial = snapshot();
      if (output) output->write_initial(initial);
    }
  }
  const ProgressStyle style = writes ? options.progress : ProgressStyle::none;
  if (relaxing) {
    // A line every log interval (wall clock): a relaxation runs tens of thousands of cycles.
    const bool report = style != ProgressStyle::none;
    double next_line = model.output.log_interval_s;
    const auto relaxed = solver.relax(*model.run.relaxation, [&](const typename Solver<D>::Relaxation& r) {
      // A signal stops a relaxation too, without a checkpoint: a restart goes on from a relaxed
      // state, and a state half relaxed is none. On ranks every 100th cycle, alike on all (the
      // ranks step in lockstep; mpirun passes the signal to each at its own moment).
      int signal = stop_requested();
      if (ranks) {
        if (r.cycles % 100 != 0) {
          signal = 0;
        } else {
          const double mine = signal;
          for (const double other : comm.all_gather(std::span<const double>(&mine, 1)))
            signal = std::max(signal, static_cast<int>(other));
        }
      }
      if (signal)
        throw RunInterrupted(signal, fmt::format("interrupted by signal {} during the dynamic relaxation, after {:.4g} s "
                                                 "of relaxation ({} cycles): no checkpoint (a relaxation is not "
                                                 "resumed); run the case again",
                                                 signal, r.time, r.cycles));
      if (!report || wall() < next_line) return;
      next_line = wall() + model.output.log_interval_s;
      fmt::print(stderr,
                 "dynamic relaxation: {:.4g} s of relaxation ({} cycles, {:.0f} s wall); kinetic energy "
                 "{:.3g} of its peak\n",
                 r.time, r.cycles, wall(), r.kinetic_ratio);
    });
    if (style != ProgressStyle::none)
      fmt::print(stderr,
                 "dynamic relaxation: at rest after {:.6g} s ({} cycles); kinetic energy {:.3g} of its peak "
                 "{:.6g} J\n",
                 relaxed.time, relaxed.cycles, relaxed.kinetic_ratio, relaxed.peak_kinetic);
    if (ranks) write_pieces(shared_index(output ? output->initial_snapshot() : -1));
    const FieldSnapshot& rest = snapshot();
    if (output) output->write_initial(rest);
  }
  // Rebar strain histories (on ranks every rank's part: each row is gathered to rank 0) and the
  // energy history with its split (rank 0's: on ranks the solver's balance is the whole run's).
  BarCsv<D> bar_csv(model, options, solver.bars(), &comm);
  std::optional<EnergyCsv<D>> energy_csv;
  if (writes) energy_csv.emplace(model, options, solver);
  // Checkpoints and restarts: the solver's state, then the output's (on ranks each rank its own
  // part of the solver's, rank 0 the output's).
  RunCheckpoints checkpoints(
      model, options,
      [&solver, &output](StateVisitor& v) {
        solver.visit_state(v);
        if (output) output->visit_state(v);
      },
      ranks ? &comm : nullptr);
  if (!options.restart.empty()) {
    checkpoints.restart();
    bar_csv.resume(solver.time(), solver.bars());
    if (energy_csv) energy_csv->resume(solver);
  }
  EnergyGuard<D> energy_guard(model.run, solver);
  ProgressReporter progress(style, model.run.end_time);
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
  const auto finish = [&] {
    if (ranks) write_pieces(shared_index(output ? output->final_snapshot_due(solver.cycle()) : -1));
    const FieldSnapshot& last = snapshot();
    if (output) output->finish(last, summary);
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
      int signal = stop_requested();
      bool checkpoint_due = checkpoints.due(solver.cycle());
      if (ranks) {
        // One exchange a cycle carries what every rank must do alike: whether rank 0's output
        // wants the fields now, and a signal any rank caught (mpirun passes SIGTERM to each, not
        // necessarily within the same cycle).
        const double flags[4] = {output && output->due(solver.time()) ? 1.0 : 0.0, static_cast<double>(signal),
                                 checkpoint_due ? 1.0 : 0.0,
                                 output ? static_cast<double>(output->snapshot_due(solver.time())) : -1.0};
        const std::vector<double> all = comm.all_gather(std::span<const double>(flags, 4));
        bool due = false;
        checkpoint_due = false;  // a wall-clock interval elapses on each rank at its own moment
        for (std::size_t r = 0; r < all.size(); r += 4) {
          due = due || all[r] != 0.0;
          signal = std::max(signal, static_cast<int>(all[r + 1]));
          checkpoint_due = checkpoint_due || all[r + 2] != 0.0;
        }
        write_pieces(static_cast<int>(all[3]));  // rank 0's
        if (due) {
          const FieldSnapshot& whole = snapshot();  // every rank takes part
          if (output) output->after_cycle(whole);
        }
      } else {
        output->after_cycle(snapshot());
      }
      bar_csv.after_cycle(solver.time(), solver.bars());
      if (energy_csv) energy_csv->after_cycle(solver);
      if (signal) {
        checkpoints.write(solver.cycle(), solver.time());
        summarise(fmt::format("interrupted by signal {}", signal), true);
        finish();
        throw RunInterrupted(signal, fmt::format("interrupted by signal {} at cycle {}, time {:.6g} s; checkpoint in {}",
                                                 signal, solver.cycle(), solver.time(),
                                                 (ranks ? checkpoints.dir().parent_path() : checkpoints.dir()).string()));
      }
      if (checkpoint_due) checkpoints.write(solver.cycle(), solver.time());
      const EnergyBalance& energy = solver.energy();
      progress.update(solver.time(), solver.cycle(), solver.time_step_limit().dt,
                      solver.time_step_limit().reason, energy.relative_error, wall());
      energy_guard.after_cycle(solver);
    }
  } catch (const NumericalError& error) {
    // On ranks every rank throws the same error at the same point of the cycle (the solver agrees
    // on failures), so all of them take part in the last snapshot.
    progress.done();
    checkpoints.write_failure(solver.cycle(), solver.time());
    summarise(error.what(), true);
    finish();
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
      particles && particles->volume_limited_count() > 0 && style != ProgressStyle::none)
    fmt::print(stderr,
               "note: {} SPH particles end expanded past h_max_factor; their volume in the particle sums "
               "is limited (docs/theory/sph.md, \"Ejecta\")\n",
               particles->volume_limited_count());
  // The final state, so that a later run can go on with a later end time or
  // more cycles; written before finish() adds its closing row and snapshot,
  // which the continued run would not have.
  if (model.checkpoint.enabled()) checkpoints.write(solver.cycle(), solver.time());
  summarise(reason, false);
  finish();
  return summary;
}

}  // namespace

RunSummary run_model(const Model& model, const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  if (model.dimension() == 3) return run_dimension<3>(model, options);
  return run_dimension<2>(model, options);
}

}  // namespace camouflet
