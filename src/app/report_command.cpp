// `camouflet report OUTDIR`: figures and one HTML page from a run's output
// folder. The plotting is scripts/report.py (matplotlib from Debian's
// python3-matplotlib, run with /usr/bin/python3); this command finds the
// script next to the build, passes it this executable (for `empirical --csv`)
// and returns its status.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/python_scripts.hpp"
#include "core/error.hpp"

namespace camouflet::app {

namespace {

namespace fs = std::filesystem;

}  // namespace

void add_report_command(CLI::App& app, CommandResult& result) {
  auto outdir = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("report", "Figures and report.html from a run's output folder");
  cmd->add_option("OUTDIR", *outdir, "Output folder of `camouflet run`")->required();
  cmd->callback([outdir, &result] {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!fs::exists(fs::path(*outdir) / "summary.json")) {
      std::cerr << fmt::format("error: {}: no summary.json here: not the output folder of a run\n", *outdir);
      result.exit_code = exit_bad_input;
      return;
    }
    const fs::path script = find_python_script(self, "CAMOUFLET_REPORT_SCRIPT", "report.py");
    if (script.empty()) {
      std::cerr << "error: scripts/report.py not found (set CAMOUFLET_REPORT_SCRIPT)\n";
      result.exit_code = exit_io_failure;
      return;
    }
    result.exit_code = run_python_script(script, {*outdir, "--camouflet", self.string()});
  });
}

}  // namespace camouflet::app
