#pragma once
// Everything a run writes into its output folder (architecture.md,
// "Contracts"): the case as read, gauge CSVs (one per group, `time_s` first),
// VTK XML field snapshots with a .pvd index, and summary.json. The solver
// calls it; it never reaches into solver types.
#include <memory>

#include "core/state_visitor.hpp"
#include "model/run_options.hpp"
#include "model/run_summary.hpp"
#include "model/snapshot.hpp"

namespace camouflet {

class RunOutput {
 public:
  // Locates every gauge in the initial configuration (InputError naming the
  // gauge's key when it lies outside the mesh and every particle support),
  // creates the folder, copies the case file, writes the first snapshot and
  // gauge row. With an empty options.output_dir gauges are still sampled
  // (tests read them through gauge_peaks()) but nothing is written.
  // With write_initial false the first snapshot and gauge row wait for
  // write_initial(): a dynamic relaxation moves the model between the
  // configuration the gauges are located in (the mesh as given, as on a
  // restart) and the state at rest that t = 0 records.
  RunOutput(const Model& model, const RunOptions& options, const FieldSnapshot& initial,
            bool write_initial = true);
  void write_initial(const FieldSnapshot& initial);
  ~RunOutput();
  RunOutput(const RunOutput&) = delete;
  RunOutput& operator=(const RunOutput&) = delete;

  // Called after every cycle; samples gauges and writes snapshots when their
  // intervals have elapsed.
  void after_cycle(const FieldSnapshot& state);
  // Whether after_cycle at `time` would sample the gauges or write a snapshot (a run across MPI
  // ranks assembles the whole model's fields only then).
  bool due(double time) const;

  // A run across `ranks` MPI ranks (docs/parallel.md; before the first snapshot): each snapshot
  // is a .pvtu joining fields_<k>/piece_<r>.vtu, which every rank writes before this one writes
  // the .pvtu (piece_path). The snapshot passed in then serves the gauges alone.
  void write_fields_in_pieces(int ranks);
  // The nodes and elements (0-based, ascending) whose fields the gauges read: all a run across
  // ranks must gather for them once they are located (parallel/whole_snapshot.hpp).
  const std::vector<std::int64_t>& sampled_nodes() const;
  const std::vector<std::int64_t>& sampled_elements() const;
  // The index the next snapshot takes when after_cycle at `time` (or finish at `cycle`, or the
  // initial snapshot) writes one, else -1: what the ranks must write their pieces for.
  int snapshot_due(double time) const;
  int final_snapshot_due(std::int64_t cycle) const;
  int initial_snapshot() const;
  // The piece of snapshot `index` that rank `rank` writes, in the output folder.
  static std::filesystem::path piece_path(const std::filesystem::path& dir, int index, int rank);

  // Final snapshot, last gauge row and summary.json (also after a failure).
  void finish(const FieldSnapshot& final_state, const RunSummary& summary);

  // Gauge histories recorded so far, for tests and the summary:
  // columns[quantity name][gauge index] over sample times.
  struct GaugeSeries {
    std::string group;
    std::vector<std::string> gauge_names;
    std::vector<std::string> quantities;  // e.g. "velocity_x", "stress_xx", "pressure"
    std::vector<double> time;             // s
    // values[q][g][k]: quantity q of gauge g at sample k
    std::vector<std::vector<std::vector<double>>> values;
  };
  const std::vector<GaugeSeries>& gauges() const;

  // Checkpoints: the gauge rows so far and the
  // output schedule. A RunOutput built with options.restart set writes nothing
  // until it has been loaded this way; loading then rewrites each gauge CSV
  // from the restored rows (dropping rows written after the checkpoint) and
  // continues it.
  void visit_state(StateVisitor& visitor);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace camouflet
