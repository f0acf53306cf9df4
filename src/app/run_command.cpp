// `camouflet run CASE [-o DIR] [--quiet] [--threads N]`
#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/error_report.hpp"
#include "case/case_fingerprint.hpp"
#include "parallel/communicator.hpp"
#include "case/case_reader.hpp"
#include "solver/interrupt.hpp"
#include "solver/run.hpp"

namespace camouflet::app {

namespace {

// Ctrl-C or a kill: the first signal asks run_model() to write a checkpoint
// after the current cycle and stop (exit 130, docs/exit-codes.md); a second
// one ends the process at once (every gauge row and snapshot written so far
// is complete on disk, the previous checkpoint intact). Only
// async-signal-safe calls here.
extern "C" void on_interrupt(int signal) {
  if (stop_requested() == 0) {
    request_stop(signal);
    return;
  }
  static const char message[] = "\ncamouflet: interrupted again; output written so far is complete\n";
  [[maybe_unused]] const auto n = write(STDERR_FILENO, message, sizeof message - 1);
  _exit(exit_interrupted);
}

struct RunArguments {
  std::string case_file;
  std::string output_dir;
  bool quiet = false;
  int threads = 0;
  std::string restart;
};
}  // namespace

void add_run_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<RunArguments>();
  auto* cmd = app.add_subcommand("run", "Run a case and write its output folder");
  cmd->add_option("CASE", args->case_file, "Case file (TOML, see docs/case-format.md)")->required();
  cmd->add_option("-o,--output", args->output_dir, "Output folder (default: results/<case name>)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line");
  cmd->add_option("-t,--threads", args->threads, "OpenMP threads (default: all)")->check(CLI::PositiveNumber);
  cmd->add_option(
      "--restart", args->restart,
      "Continue from a checkpoint file, or 'latest' (the newest usable one in the output folder)");
  cmd->callback([args, &result] {
    result.exit_code = run_guarded([&] {
      // Installed first: a signal while the case is read stops the run at its first cycle.
      std::signal(SIGINT, on_interrupt);
      std::signal(SIGTERM, on_interrupt);
      const Model model = read_case(args->case_file);
      RunOptions options;
      options.output_dir = args->output_dir.empty() ? std::filesystem::path("results") /
                                                          std::filesystem::path(args->case_file).stem()
                                                    : std::filesystem::path(args->output_dir);
      options.progress = args->quiet ? ProgressStyle::none : ProgressStyle::automatic;
      options.threads = args->threads;
      options.restart = args->restart;
      options.case_fingerprint = case_fingerprint(args->case_file);
      if (args->threads > 0) omp_set_num_threads(args->threads);
      const RunSummary summary = run_model(model, options);
      if (world().rank() != 0) return summary.failed ? static_cast<int>(exit_numerical_failure) : static_cast<int>(exit_ok);
      if (!args->quiet)
        std::cerr << fmt::format(
            "{}: t = {:g} s after {} cycles in {:.1f} s wall time, energy error {:.2e}\n",
            summary.stop_reason, summary.time, summary.cycles, summary.wall_seconds,
            summary.energy.relative_error);
      std::cout << "results in " << options.output_dir.string() << '\n';
      return summary.failed ? static_cast<int>(exit_numerical_failure) : static_cast<int>(exit_ok);
    });
  });
}

}  // namespace camouflet::app
