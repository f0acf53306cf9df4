#include "app/python_scripts.hpp"

#include <sys/wait.h>

#include <cstdlib>

#include "core/error.hpp"

namespace camouflet::app {

namespace fs = std::filesystem;

fs::path find_python_script(const fs::path& self, const char* env_var, const std::string& name) {
  if (const char* env = std::getenv(env_var)) return env;
  for (const fs::path& p : {self.parent_path().parent_path() / "scripts" / name,
                            self.parent_path() / "scripts" / name, fs::path("scripts") / name})
    if (fs::exists(p)) return p;
  return {};
}

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

int run_python_script(const fs::path& script, const std::vector<std::string>& args) {
  std::string command = "/usr/bin/python3 " + shell_quoted(script.string());
  for (const std::string& a : args) command += " " + shell_quoted(a);
  const int status = std::system(command.c_str());
  return status == -1        ? static_cast<int>(exit_io_failure)
         : WIFEXITED(status) ? WEXITSTATUS(status)
                             : static_cast<int>(exit_numerical_failure);
}

}  // namespace camouflet::app
