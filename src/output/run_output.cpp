// The run's output folder (architecture.md, "Contracts"): gauges, CSVs, field
// snapshots and the summary, each written by its own small file; this one
// only schedules them.
#include "output/run_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "output/gauge_csv.hpp"
#include "output/gauges.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"
#include "output/vtu_writer.hpp"

namespace camouflet {

namespace fs = std::filesystem;

namespace {
// Sampling instants are compared with a relative slack so that an interval
// that is an exact multiple of dt is not missed by round-off.
constexpr double time_slack = 1e-9;
// When a folder is written, the CSVs hold every sample; the in-memory
// histories (gauges()) then stop growing at this many values (1 GiB), so a
// long run sampling every cycle cannot exhaust memory. Peaks for the summary
// are kept sample by sample and stay exact.
constexpr std::size_t memory_values_limit = std::size_t{1} << 27;
}  // namespace

struct RunOutput::Impl {
  const Model& model;
  fs::path dir;  // empty: sample only, write nothing
  std::vector<std::vector<LocatedGauge>> located;
  std::vector<GaugeSeries> series;
  std::vector<GroupPeaks> peaks;
  std::vector<std::size_t> samples;  // rows taken per group (written to the CSV)
  std::size_t values_in_memory = 0;
  std::vector<std::unique_ptr<GaugeCsv>> csv;
  PvdIndex pvd;
  int snapshots = 0;
  double next_field = 0.0, next_gauge = 0.0;
  std::int64_t last_field_cycle = -1, last_gauge_cycle = -1;
  std::vector<double> row;
  std::vector<double> snapshot_times;  // s, of each snapshot written (the .pvd is rebuilt from them)
  bool restarting = false;             // write nothing until the checkpoint is loaded
  int pieces = 0;                      // on MPI ranks: the pieces of each snapshot (.pvtu); 0: one .vtu
  std::vector<std::int64_t> sampled_nodes, sampled_elements;  // what the gauges read

  explicit Impl(const Model& m) : model(m) {}
  std::string mesh_name(int index) const {
    return fmt::format("fields_{:04}.{}", index, pieces > 0 ? "pvtu" : "vtu");
  }

  void sample(const FieldSnapshot& s) {
    for (std::size_t g = 0; g < located.size(); ++g) {
      row.clear();
      for (const auto& gauge : located[g]) sample_gauge(gauge, s, row);
      auto& ser = series[g];
      const std::size_t nq = ser.quantities.size(), np = located[g].size();
      for (std::size_t p = 0; p < np; ++p)
        for (std::size_t q = 0; q < nq; ++q) peaks[g].add(q * np + p, row[p * nq + q], s.time);
      ++samples[g];
      if (dir.empty() || values_in_memory + row.size() <= memory_values_limit) {
        ser.time.push_back(s.time);
        for (std::size_t p = 0; p < np; ++p)
          for (std::size_t q = 0; q < nq; ++q) ser.values[q][p].push_back(row[p * nq + q]);
        values_in_memory += row.size() + 1;
      }
      if (!dir.empty()) csv[g]->write_row(s.time, row);
    }
    last_gauge_cycle = s.cycle;
  }

  void snapshot(const FieldSnapshot& s) {
    last_field_cycle = s.cycle;
    if (dir.empty()) return;
    const std::string mesh_file = mesh_name(snapshots);
    if (pieces > 0) {  // the ranks wrote their pieces already (RunOutput::piece_path)
      std::vector<std::string> sources;
      for (int r = 0; r < pieces; ++r)
        sources.push_back(RunOutput::piece_path({}, snapshots, r).generic_string());
      write_mesh_pvtu(dir / mesh_file, sources);
      pvd.add(s.time, 0, mesh_file);
    } else if (s.element_count() > 0) {
      write_mesh_vtu(dir / mesh_file, s);
      pvd.add(s.time, 0, mesh_file);
    }
    if (s.particle_count() > 0) {
      const std::string particle_file = fmt::format("particles_{:04}.vtu", snapshots);
      write_particle_vtu(dir / particle_file, s);
      pvd.add(s.time, 1, particle_file);
    }
    ++snapshots;
    snapshot_times.push_back(s.time);
    pvd.write(dir / "fields.pvd");
  }
};

RunOutput::RunOutput(const Model& model, const RunOptions& options, const FieldSnapshot& initial,
                     bool write_initial_now)
    : impl_(std::make_unique<Impl>(model)) {
  Impl& o = *impl_;
  // Gauges first: a gauge outside the mesh is bad input and must leave no folder behind.
  const auto quantities = gauge_quantities(initial.dimension);
  for (const auto& group : model.gauges) {
    std::vector<LocatedGauge> located;
    for (const auto& point : group.points) located.push_back(locate_gauge(point, initial));
    GaugeSeries ser;
    ser.group = group.name;
    for (const auto& point : group.points) ser.gauge_names.push_back(point.name);
    ser.quantities = quantities;
    ser.values.assign(quantities.size(), std::vector<std::vector<double>>(group.points.size()));
    for (const LocatedGauge& gauge : located) {
      if (gauge.element >= 0) {
        o.sampled_elements.push_back(gauge.element);
        const auto npe = static_cast<std::size_t>(initial.nodes_per_element);
        for (std::size_t a = 0; a < npe; ++a)
          o.sampled_nodes.push_back(initial.connectivity[static_cast<std::size_t>(gauge.element) * npe + a]);
      }
      for (const auto& [node, share] : gauge.member_nodes) o.sampled_nodes.push_back(node);
      for (const auto& [element, share] : gauge.member_elements) o.sampled_elements.push_back(element);
    }
    o.located.push_back(std::move(located));
    o.series.push_back(std::move(ser));
    o.peaks.emplace_back();
    o.samples.push_back(0);
  }

  for (auto* ids : {&o.sampled_nodes, &o.sampled_elements}) {
    std::sort(ids->begin(), ids->end());
    ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
  }

  o.dir = options.output_dir;
  o.next_field = model.output.field_interval;
  o.next_gauge = model.output.gauge_interval;
  o.restarting = !options.restart.empty();
  if (o.restarting) {
    // visit_state() restores the schedule and rows and reopens the files.
    if (!o.dir.empty()) fs::create_directories(o.dir);
    return;
  }
  if (!o.dir.empty()) {
    fs::create_directories(o.dir);
    if (!model.case_file.empty() && fs::is_regular_file(model.case_file))
      fs::copy_file(model.case_file, o.dir / "case.toml", fs::copy_options::overwrite_existing);
    for (const auto& ser : o.series)
      o.csv.push_back(
          std::make_unique<GaugeCsv>(o.dir / (ser.group + ".csv"), ser.gauge_names, ser.quantities));
  }
  if (write_initial_now) write_initial(initial);
}

void RunOutput::write_initial(const FieldSnapshot& initial) {
  Impl& o = *impl_;
  if (o.restarting) return;  // the checkpoint's rows and schedule go on instead
  o.snapshot(initial);
  o.sample(initial);
}

RunOutput::~RunOutput() = default;

void RunOutput::after_cycle(const FieldSnapshot& state) {
  Impl& o = *impl_;
  const double gi = o.model.output.gauge_interval, fi = o.model.output.field_interval;
  if (gi <= 0.0 || state.time >= o.next_gauge * (1.0 - time_slack)) {
    o.sample(state);
    if (gi > 0.0)
      while (o.next_gauge <= state.time * (1.0 + time_slack)) o.next_gauge += gi;
  }
  if (fi > 0.0 && state.time >= o.next_field * (1.0 - time_slack)) {
    o.snapshot(state);
    while (o.next_field <= state.time * (1.0 + time_slack)) o.next_field += fi;
  }
}

void RunOutput::write_fields_in_pieces(int ranks) { impl_->pieces = ranks; }

const std::vector<std::int64_t>& RunOutput::sampled_nodes() const { return impl_->sampled_nodes; }
const std::vector<std::int64_t>& RunOutput::sampled_elements() const { return impl_->sampled_elements; }

int RunOutput::snapshot_due(double time) const {
  const Impl& o = *impl_;
  const double fi = o.model.output.field_interval;
  return !o.dir.empty() && fi > 0.0 && time >= o.next_field * (1.0 - time_slack) ? o.snapshots : -1;
}

int RunOutput::final_snapshot_due(std::int64_t cycle) const {
  const Impl& o = *impl_;
  return !o.dir.empty() && o.last_field_cycle != cycle ? o.snapshots : -1;
}

int RunOutput::initial_snapshot() const {
  const Impl& o = *impl_;
  return !o.dir.empty() && !o.restarting ? o.snapshots : -1;
}

fs::path RunOutput::piece_path(const fs::path& dir, int index, int rank) {
  return dir / fmt::format("fields_{:04}", index) / fmt::format("piece_{}.vtu", rank);
}

bool RunOutput::due(double time) const {
  const Impl& o = *impl_;
  const double gi = o.model.output.gauge_interval, fi = o.model.output.field_interval;
  return gi <= 0.0 || time >= o.next_gauge * (1.0 - time_slack) ||
         (fi > 0.0 && time >= o.next_field * (1.0 - time_slack));
}

void RunOutput::finish(const FieldSnapshot& final_state, const RunSummary& summary) {
  Impl& o = *impl_;
  if (o.last_gauge_cycle != final_state.cycle) o.sample(final_state);
  if (o.last_field_cycle != final_state.cycle) o.snapshot(final_state);
  if (o.dir.empty()) return;
  for (auto& c : o.csv) c->close();
  write_file_atomically(o.dir / "summary.json", summary_json(o.model, summary, o.series, o.peaks, o.samples));
}

const std::vector<RunOutput::GaugeSeries>& RunOutput::gauges() const {
  return impl_->series;
}

}  // namespace camouflet

namespace camouflet {

namespace {
// Keeps the first `lines` lines of a text file (throws when it has fewer).
void truncate_lines(const fs::path& path, std::size_t lines) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f)
    throw fs::filesystem_error("cannot reopen gauge CSV", path, std::make_error_code(std::errc::io_error));
  std::uintmax_t offset = 0;
  std::size_t seen = 0;
  for (int c; seen < lines && (c = std::fgetc(f)) != EOF;) {
    ++offset;
    if (c == '\n') ++seen;
  }
  std::fclose(f);
  if (seen < lines)
    throw fs::filesystem_error("gauge CSV holds fewer rows than the checkpoint", path,
                               std::make_error_code(std::errc::io_error));
  fs::resize_file(path, offset);
}
}  // namespace

void RunOutput::visit_state(StateVisitor& v) {
  Impl& o = *impl_;
  StateScope scope(v, "output");
  visit(v, "snapshots", o.snapshots);
  visit(v, "next_field", o.next_field);
  visit(v, "next_gauge", o.next_gauge);
  visit(v, "last_field_cycle", o.last_field_cycle);
  visit(v, "last_gauge_cycle", o.last_gauge_cycle);
  visit(v, "snapshot_times", o.snapshot_times);
  for (std::size_t g = 0; g < o.series.size(); ++g) {
    GaugeSeries& ser = o.series[g];
    StateScope group(v, "gauges." + ser.group);
    visit(v, "time", ser.time);
    for (std::size_t q = 0; q < ser.quantities.size(); ++q)
      for (std::size_t p = 0; p < ser.gauge_names.size(); ++p)
        visit(v, ser.gauge_names[p] + "." + ser.quantities[q], ser.values[q][p]);
    // Running peaks (summary.json) and the rows written, which the in-memory series may not all hold.
    GroupPeaks& peaks = o.peaks[g];
    std::vector<double> peak_value, peak_time;
    std::vector<int> seen;
    for (std::size_t k = 0; k < peaks.peaks.size(); ++k) {
      peak_value.push_back(peaks.peaks[k].value);
      peak_time.push_back(peaks.peaks[k].time);
      seen.push_back(k < peaks.seen.size() && peaks.seen[k] ? 1 : 0);
    }
    visit(v, "peak_value", peak_value);
    visit(v, "peak_time", peak_time);
    visit(v, "peak_seen", seen);
    if (v.loading()) {
      peaks.peaks.resize(peak_value.size());
      peaks.seen.assign(seen.size(), false);
      for (std::size_t k = 0; k < peak_value.size() && k < peak_time.size(); ++k)
        peaks.peaks[k] = {peak_value[k], peak_time[k]};
      for (std::size_t k = 0; k < seen.size(); ++k) peaks.seen[k] = seen[k] != 0;
    }
    std::uint64_t samples = o.samples[g];
    visit(v, "samples", samples);
    o.samples[g] = samples;
  }
  std::uint64_t in_memory = o.values_in_memory;
  visit(v, "values_in_memory", in_memory);
  o.values_in_memory = in_memory;
  if (!v.loading() || o.dir.empty()) return;

  // The .pvd lists the snapshots up to the checkpoint; later ones are overwritten as the run goes on.
  o.pvd = PvdIndex();
  const bool mesh = o.model.mesh.element_count() > 0, particles = o.model.particles.count() > 0;
  for (std::size_t k = 0; k < o.snapshot_times.size(); ++k) {
    if (mesh) o.pvd.add(o.snapshot_times[k], 0, o.mesh_name(static_cast<int>(k)));
    if (particles) o.pvd.add(o.snapshot_times[k], 1, fmt::format("particles_{:04}.vtu", k));
  }
  if (!o.snapshot_times.empty()) o.pvd.write(o.dir / "fields.pvd");

  // Each CSV is cut back to the rows of the checkpoint, so rows written after
  // it are not duplicated, then continued. When memory holds every row the
  // file is rewritten from them (the same digits the run wrote), which also
  // repairs a damaged or missing file; otherwise it is truncated in place.
  o.csv.clear();
  for (std::size_t g = 0; g < o.series.size(); ++g) {
    const GaugeSeries& ser = o.series[g];
    const fs::path path = o.dir / (ser.group + ".csv");
    if (ser.time.size() != o.samples[g]) {
      truncate_lines(path, o.samples[g] + 1);
      o.csv.push_back(std::make_unique<GaugeCsv>(path));
      continue;
    }
    fs::path tmp = path;
    tmp += ".tmp";
    {
      GaugeCsv rewrite(tmp, ser.gauge_names, ser.quantities);
      std::vector<double> row;
      for (std::size_t k = 0; k < ser.time.size(); ++k) {
        row.clear();
        for (std::size_t p = 0; p < ser.gauge_names.size(); ++p)
          for (std::size_t q = 0; q < ser.quantities.size(); ++q) row.push_back(ser.values[q][p][k]);
        rewrite.write_row(ser.time[k], row);
      }
      rewrite.close();
    }
    fs::rename(tmp, path);
    o.csv.push_back(std::make_unique<GaugeCsv>(path));
  }
  o.restarting = false;
}

}  // namespace camouflet
