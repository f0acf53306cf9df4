// camouflet: the command line. Subcommands are in their own files (commands.hpp).
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "parallel/communicator.hpp"

int main(int argc, char** argv) {
  // Under mpirun, MPI's world (docs/parallel.md); without it, serial and MPI untouched.
  camouflet::ParallelSession session(argc, argv);
  // Only `run` spreads over ranks; any other command under mpirun would do its work once a rank.
  if (camouflet::world().size() > 1 && (argc < 2 || std::string(argv[1]) != "run")) {
    if (camouflet::world().rank() == 0)
      std::cerr << "error: camouflet was started on " << camouflet::world().size()
                << " MPI ranks: only `camouflet run` runs across ranks (docs/parallel.md); run '"
                << (argc < 2 ? "" : argv[1]) << "' without mpirun\n";
    return camouflet::exit_bad_input;
  }
  CLI::App app{"Camouflet: explosions buried in soil and the structures they load"};
  app.set_version_flag("--version", std::string("camouflet ") + CAMOUFLET_VERSION);
  app.require_subcommand(1);
  camouflet::app::CommandResult result;
  camouflet::app::add_run_command(app, result);
  camouflet::app::add_check_command(app, result);
  camouflet::app::add_empirical_command(app, result);
  camouflet::app::add_material_test_command(app, result);
  camouflet::app::add_generate_command(app, result);
  camouflet::app::add_report_command(app, result);
  camouflet::app::add_sweep_command(app, result);
  camouflet::app::add_compare_command(app, result);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // A malformed command line is bad input too (docs/exit-codes.md).
    app.exit(e);
    return camouflet::exit_bad_input;
  }
  return result.exit_code;
}
