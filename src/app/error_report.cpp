#include "app/error_report.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <new>

#include "solver/interrupt.hpp"

namespace camouflet::app {

std::string format_input_error(const InputError& e) {
  const SourceLocation& w = e.where();
  std::string s = "error: ";
  s += w.file.empty() ? "<input>" : w.file;
  if (w.line > 0) s += fmt::format(":{}", w.line);
  if (!w.key.empty()) s += fmt::format(": key '{}'", w.key);
  return s + ": " + e.message();
}

int run_guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const RunInterrupted& e) {
    std::cerr << "camouflet: " << e.what() << '\n';
    return exit_interrupted;
  } catch (const InputError& e) {
    std::cerr << format_input_error(e) << '\n';
    return exit_bad_input;
  } catch (const NumericalError& e) {
    std::cerr << "error: numerical failure: " << e.what() << '\n';
    return exit_numerical_failure;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "error: I/O failure: " << e.what() << '\n';
    return exit_io_failure;
  } catch (const std::ios_base::failure& e) {
    std::cerr << "error: I/O failure: " << e.what() << '\n';
    return exit_io_failure;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory (the model is too large for this machine)\n";
    return exit_numerical_failure;
  } catch (const std::exception& e) {
    // A defect, not the user's fault: still a clean message and a non-zero status.
    std::cerr << "error: internal error: " << e.what() << '\n';
    return exit_numerical_failure;
  } catch (...) {
    std::cerr << "error: internal error: unknown exception\n";
    return exit_numerical_failure;
  }
}

}  // namespace camouflet::app
