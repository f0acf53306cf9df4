#pragma once
// The Python scripts some commands run (`report`: scripts/report.py, `sweep`:
// scripts/sweep.py, `compare`: scripts/compare_runs.py; matplotlib from Debian's python3-matplotlib).
#include <filesystem>
#include <string>
#include <vector>

namespace camouflet::app {

// The script `name`: $`env_var` when set, else scripts/<name> beside the
// build folder of this executable (`self`), else under the current folder;
// empty when none exists.
std::filesystem::path find_python_script(const std::filesystem::path& self, const char* env_var,
                                         const std::string& name);
// `s` as one single-quoted word for /bin/sh.
std::string shell_quoted(const std::string& s);
// Runs `/usr/bin/python3 script args...` and returns the command's exit code: the script's own status,
// exit_io_failure when it could not be started, exit_numerical_failure when it was killed.
int run_python_script(const std::filesystem::path& script, const std::vector<std::string>& args);

}  // namespace camouflet::app
