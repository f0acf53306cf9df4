#pragma once
// Where the tests that run a model write, and how: a fresh folder under
// <build>/test-output and run options that print nothing.
#include <filesystem>

#include "solver/run.hpp"

namespace camouflet::test {

// <build>/test-output/<relative>, removed if it was there (run_model creates it).
inline std::filesystem::path fresh_test_output(const std::filesystem::path& relative) {
  const std::filesystem::path dir = std::filesystem::path(CAMOUFLET_BINARY_DIR) / "test-output" / relative;
  std::filesystem::remove_all(dir);
  return dir;
}

// A test run writing to `out` with no progress line, on `threads` OpenMP
// threads (1: reproducible bit for bit; 0: the OpenMP default).
inline RunOptions quiet_run_options(const std::filesystem::path& out, int threads = 1) {
  RunOptions options;
  options.output_dir = out;
  options.progress = ProgressStyle::none;
  options.threads = threads;
  return options;
}

}  // namespace camouflet::test
