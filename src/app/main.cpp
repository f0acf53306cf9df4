// camouflet: command line entry point (placeholder until the CLI lands).
#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"Camouflet: explosions buried in soil and the structures they load"};
  app.set_version_flag("--version", std::string("camouflet ") + CAMOUFLET_VERSION);
  app.require_subcommand(0, 1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
