#pragma once
// Each subcommand lives in its own file and adds itself to the application
// here; main.cpp only lists them. A command's callback returns the exit code
// through `exit_code` (docs/exit-codes.md).
#include <CLI/CLI.hpp>

namespace camouflet::app {

struct CommandResult {
  int exit_code = 0;
};

void add_run_command(CLI::App& app, CommandResult& result);
void add_check_command(CLI::App& app, CommandResult& result);
void add_empirical_command(CLI::App& app, CommandResult& result);
void add_material_test_command(CLI::App& app, CommandResult& result);
void add_generate_command(CLI::App& app, CommandResult& result);
void add_report_command(CLI::App& app, CommandResult& result);
void add_sweep_command(CLI::App& app, CommandResult& result);
void add_compare_command(CLI::App& app, CommandResult& result);

}  // namespace camouflet::app
