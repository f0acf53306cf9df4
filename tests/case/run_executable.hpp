#pragma once
// Runs the camouflet executable (CAMOUFLET_EXECUTABLE) and captures its exit
// status and combined output.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace camouflet::test {

struct Completed {
  int status = -1;  // exit status, or -1 when it did not exit normally (crash)
  std::string output;
};

// Any shell command line, output captured.
inline Completed run_camouflet_raw(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  Completed r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) r.output.append(buffer, n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

inline Completed run_camouflet(const std::string& arguments) {
  return run_camouflet_raw(std::string("'") + CAMOUFLET_EXECUTABLE + "' " + arguments);
}

}  // namespace camouflet::test
