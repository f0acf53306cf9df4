// `camouflet check CASE`: read and validate only, print a short summary.
#include <iostream>

#include "app/commands.hpp"
#include "app/error_report.hpp"
#include "case/case_reader.hpp"

namespace camouflet::app {

void add_check_command(CLI::App& app, CommandResult& result) {
  auto case_file = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("check", "Read and validate a case without running it");
  cmd->add_option("CASE", *case_file, "Case file (TOML, see docs/case-format.md)")->required();
  cmd->callback([case_file, &result] {
    result.exit_code = run_guarded([&] {
      const Model model = read_case(*case_file);
      std::cout << *case_file << ": OK\n" << describe_model(model);
      return static_cast<int>(exit_ok);
    });
  });
}

}  // namespace camouflet::app
