// `camouflet sweep SWEEP.toml [-o OUTDIR] [--jobs N] [--threads T]`: a
// parameter study of the buried-structure generator (docs/buried-structure.md,
// "Parameter studies"). Each case's parameter file and case file are written
// and generated here (library calls); each case runs as a child `camouflet
// run` process, so one failing case never stops the others. The per-case
// status goes to OUTDIR/cases.csv; scripts/sweep.py then adds the headline
// results of every run (the report's definitions, scripts/run_metrics.py) into
// OUTDIR/sweep.csv and draws OUTDIR/sweep.png.
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "app/commands.hpp"
#include "app/error_report.hpp"
#include "app/python_scripts.hpp"
#include "app/sweep_jobs.hpp"
#include "case/buried_structure_params.hpp"
#include "case/sweep_spec.hpp"

namespace camouflet::app {

namespace {

namespace fs = std::filesystem;

struct SweepArguments {
  std::string sweep_file;
  std::string output_dir;
  int jobs = 0;
  int threads = 1;
};

// "x.sweep.toml" -> "x"; anything else -> its stem.
std::string sweep_name(const fs::path& file) {
  const std::string name = file.filename().string();
  const std::string suffix = ".sweep.toml";
  if (name.size() > suffix.size() && name.ends_with(suffix))
    return name.substr(0, name.size() - suffix.size());
  return file.stem().string();
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out || !(out << text) || !out.flush())
    throw std::ios_base::failure(fmt::format("cannot write {}", path.string()));
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
}

// Writes the case's parameter file and generates its case file; false (with
// status 2 and the message) when the generator refuses this combination.
bool prepare_case(const SweepSpec& sweep, const SweepCase& c, const fs::path& dir, SweepJob& job) {
  fs::remove_all(dir);  // a previous sweep's snapshots must not mix with this run's
  fs::create_directories(dir);
  const fs::path params = dir / "input.params.toml";
  const fs::path case_file = dir / "input.toml";
  write_file(params, sweep_case_params_text(sweep, c));
  try {
    const BuriedStructureSpec spec = read_buried_structure_params(params);
    write_file(case_file, buried_structure_case(spec, fmt::format("camouflet sweep {} (case {})",
                                                                  sweep.file.string(), c.name)));
  } catch (const InputError& e) {
    job.status = exit_bad_input;
    job.message = format_input_error(e);
    write_file(job.log, job.message + '\n');
    return false;
  }
  return true;
}

std::string case_label(const SweepSpec& sweep, const SweepCase& c) {
  std::string s;
  for (std::size_t k = 0; k < sweep.varied_keys.size(); ++k)
    if (!c.values[k].empty())
      s += fmt::format("{}{} = {}", s.empty() ? "" : ", ", sweep.varied_keys[k], c.values[k]);
  return s;
}

int run_sweep(const SweepArguments& args) {
  const SweepSpec sweep = read_sweep(args.sweep_file);
  const fs::path out =
      args.output_dir.empty() ? fs::path("results") / sweep_name(args.sweep_file) : fs::path(args.output_dir);
  fs::create_directories(out);
  if (!fs::exists(out / "sweep.toml") || !fs::equivalent(args.sweep_file, out / "sweep.toml"))
    fs::copy_file(args.sweep_file, out / "sweep.toml", fs::copy_options::overwrite_existing);
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int jobs = args.jobs > 0 ? args.jobs : std::max(1, cores / args.threads);
  std::cout << fmt::format("sweep {}: {} cases of {} (varying {}), {} at a time, {} thread{} each\n",
                           args.sweep_file, sweep.cases.size(), sweep.base.string(),
                           fmt::join(sweep.varied_keys, ", "), jobs, args.threads,
                           args.threads == 1 ? "" : "s");
  std::cout.flush();

  std::vector<SweepJob> list(sweep.cases.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const fs::path dir = out / sweep.cases[i].name;
    list[i].arguments = {"run",       (dir / "input.toml").string(), "-o", dir.string(),
                         "--threads", std::to_string(args.threads)};
    list[i].log = dir / "run.log";
  }
  std::size_t finished = 0;
  run_sweep_jobs(
      list, jobs,
      [&](std::size_t i) { return prepare_case(sweep, sweep.cases[i], out / sweep.cases[i].name, list[i]); },
      [&](std::size_t i) {
        const SweepJob& j = list[i];
        std::cout << fmt::format("[{}/{}] {} ({}): {}\n", ++finished, list.size(), sweep.cases[i].name,
                                 case_label(sweep, sweep.cases[i]),
                                 j.status == 0 ? fmt::format("done in {:.1f} s", j.wall_seconds)
                                               : fmt::format("FAILED (status {}): {}", j.status, j.message));
        std::cout.flush();
      });

  std::string csv = "case";
  for (const std::string& k : sweep.varied_keys) csv += "," + csv_field(k);
  csv += ",status,message,wall_s\n";
  for (std::size_t i = 0; i < list.size(); ++i) {
    csv += csv_field(sweep.cases[i].name);
    for (const std::string& v : sweep.cases[i].values) csv += "," + csv_field(v);
    csv += fmt::format(",{},{},{:.3f}\n", list[i].status, csv_field(list[i].message), list[i].wall_seconds);
  }
  write_file(out / "cases.csv", csv);
  const auto failed =
      std::count_if(list.begin(), list.end(), [](const SweepJob& j) { return j.status != 0; });

  // The results of every run, by the report's definitions, and the chart.
  const fs::path self = self_executable();
  const fs::path script = find_python_script(self, "CAMOUFLET_SWEEP_SCRIPT", "sweep.py");
  if (script.empty()) {
    std::cerr << "error: scripts/sweep.py not found (set CAMOUFLET_SWEEP_SCRIPT); per-case status in "
              << (out / "cases.csv").string() << '\n';
    return exit_io_failure;
  }
  if (run_python_script(script, {out.string(), "--camouflet", self.string()}) != 0) {
    std::cerr << fmt::format("error: collecting the results failed ({}); per-case status in {}\n",
                             script.string(), (out / "cases.csv").string());
    return exit_io_failure;
  }
  std::cout << fmt::format("{} of {} cases ran to their end; results in {}\n", list.size() - failed,
                           list.size(), (out / "sweep.csv").string());
  return failed == 0 ? static_cast<int>(exit_ok) : static_cast<int>(exit_numerical_failure);
}

}  // namespace

void add_sweep_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<SweepArguments>();
  auto* cmd = app.add_subcommand("sweep", "Run a parameter study of the buried-structure generator");
  cmd->add_option("SWEEP", args->sweep_file, "Sweep file (TOML, see docs/buried-structure.md)")->required();
  cmd->add_option("-o,--output", args->output_dir, "Output folder (default: results/<sweep name>)");
  cmd->add_option("-j,--jobs", args->jobs, "Cases run at once (default: cores / threads, at least 1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("-t,--threads", args->threads, "OpenMP threads of each case (default 1)")
      ->check(CLI::PositiveNumber);
  cmd->callback([args, &result] { result.exit_code = run_guarded([&] { return run_sweep(*args); }); });
}

}  // namespace camouflet::app
