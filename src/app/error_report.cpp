#include "app/error_report.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <new>

#include "parallel/communicator.hpp"
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
  // Under mpirun (docs/parallel.md) a bad case, a numerical failure and a signal reach every rank
  // alike (each reads the case; the solver agrees on failures and signals), so rank 0 alone says
  // them. Anything else happened on one rank while the others may wait for it in an exchange: it
  // is said where it happened and stops every rank.
  const Communicator& ranks = world();
  const auto shared = [&ranks](const std::string& message, int code) {
    if (ranks.rank() == 0) std::cerr << message << '\n';
    return code;
  };
  const auto alone = [&ranks](const std::string& message, int code) {
    std::cerr << (ranks.size() > 1 ? fmt::format("rank {}: ", ranks.rank()) : std::string()) << message << '\n';
    if (ranks.size() > 1) abort_world(code);
    return code;
  };
  try {
    return body();
  } catch (const RunInterrupted& e) {
    return shared(std::string("camouflet: ") + e.what(), exit_interrupted);
  } catch (const InputError& e) {
    return shared(format_input_error(e), exit_bad_input);
  } catch (const NumericalError& e) {
    return shared(std::string("error: numerical failure: ") + e.what(), exit_numerical_failure);
  } catch (const std::filesystem::filesystem_error& e) {
    return alone(std::string("error: I/O failure: ") + e.what(), exit_io_failure);
  } catch (const std::ios_base::failure& e) {
    return alone(std::string("error: I/O failure: ") + e.what(), exit_io_failure);
  } catch (const std::bad_alloc&) {
    return alone("error: out of memory (the model is too large for this machine)", exit_numerical_failure);
  } catch (const std::exception& e) {
    // A defect, not the user's fault: still a clean message and a non-zero status.
    return alone(std::string("error: internal error: ") + e.what(), exit_numerical_failure);
  } catch (...) {
    return alone("error: internal error: unknown exception", exit_numerical_failure);
  }
}

}  // namespace camouflet::app
