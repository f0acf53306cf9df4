// camouflet: the command line. Subcommands are in their own files (commands.hpp).
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Camouflet: explosions buried in soil and the structures they load"};
  app.set_version_flag("--version", std::string("camouflet ") + CAMOUFLET_VERSION);
  app.require_subcommand(1);
  camouflet::app::CommandResult result;
  camouflet::app::add_run_command(app, result);
  camouflet::app::add_check_command(app, result);
  camouflet::app::add_material_test_command(app, result);
  CLI11_PARSE(app, argc, argv);
  return result.exit_code;
}
