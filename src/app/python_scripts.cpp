#include "app/python_scripts.hpp"

#include <cstdlib>

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

}  // namespace camouflet::app
