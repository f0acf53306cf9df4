// Placeholder `run` and `check` until the case reader lands (issue 2).
#include <iostream>

#include "app/commands.hpp"

namespace camouflet::app {

void add_run_command(CLI::App& app, CommandResult& result) {
  auto* cmd = app.add_subcommand("run", "Run a case");
  cmd->callback([&result] {
    std::cerr << "camouflet run: not yet implemented\n";
    result.exit_code = 2;
  });
}

void add_check_command(CLI::App& app, CommandResult& result) {
  auto* cmd = app.add_subcommand("check", "Read and validate a case without running it");
  cmd->callback([&result] {
    std::cerr << "camouflet check: not yet implemented\n";
    result.exit_code = 2;
  });
}

}  // namespace camouflet::app
