// `camouflet compare OUTDIR...`: the headline results of several runs side by
// side (a Markdown table on standard output, optionally CSV), each by the
// report's definition. Made for convergence tables (the same case at three
// resolutions) and for comparing variants of a case; the table itself is
// scripts/compare_runs.py.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/python_scripts.hpp"
#include "core/error.hpp"

namespace camouflet::app {

namespace fs = std::filesystem;

void add_compare_command(CLI::App& app, CommandResult& result) {
  struct Options {
    std::vector<std::string> outdirs, labels;
    std::string csv;
    double refinement = 0.0;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("compare", "Headline results of several runs side by side (Markdown table)");
  cmd->add_option("OUTDIR", o->outdirs, "Output folders of `camouflet run`")->required();
  // One word per --label, so that folders after it stay positional.
  cmd->add_option("--label", o->labels, "Column heading of each OUTDIR, in order (default: the folder names)")
      ->allow_extra_args(false);
  cmd->add_option("--csv", o->csv, "Also write the numbers as CSV to this file");
  cmd->add_option("--refinement", o->refinement,
                  "Three runs, coarse to fine, each finer by this ratio: add each quantity's observed order of "
                  "convergence and Richardson estimate");
  cmd->callback([o, &result] {
    for (const std::string& d : o->outdirs)
      if (!fs::exists(fs::path(d) / "summary.json")) {
        std::cerr << fmt::format("error: {}: no summary.json here: not the output folder of a run\n", d);
        result.exit_code = exit_bad_input;
        return;
      }
    if (!o->labels.empty() && o->labels.size() != o->outdirs.size()) {
      std::cerr << fmt::format("error: --label: {} labels for {} output folders\n", o->labels.size(),
                               o->outdirs.size());
      result.exit_code = exit_bad_input;
      return;
    }
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    const fs::path script = find_python_script(self, "CAMOUFLET_COMPARE_SCRIPT", "compare_runs.py");
    if (script.empty()) {
      std::cerr << "error: scripts/compare_runs.py not found (set CAMOUFLET_COMPARE_SCRIPT)\n";
      result.exit_code = exit_io_failure;
      return;
    }
    std::vector<std::string> args = o->outdirs;
    for (const std::string& l : o->labels) args.insert(args.end(), {"--label", l});
    if (!o->csv.empty()) args.insert(args.end(), {"--csv", o->csv});
    if (o->refinement != 0.0) {
      if (o->outdirs.size() != 3 || !(o->refinement > 1.0)) {
        std::cerr << fmt::format(
            "error: --refinement: needs three output folders (coarse to fine) and a ratio above 1, got {} folders "
            "and {}\n",
            o->outdirs.size(), o->refinement);
        result.exit_code = exit_bad_input;
        return;
      }
      args.insert(args.end(), {"--refinement", fmt::format("{}", o->refinement)});
    }
    args.insert(args.end(), {"--camouflet", self.string()});
    result.exit_code = run_python_script(script, args);
  });
}

}  // namespace camouflet::app
