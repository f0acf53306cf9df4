#pragma once
// Runs a command body and turns every way it can fail into a one-line message
// on stderr and the documented exit code (docs/exit-codes.md): bad input 2,
// numerical failure 1, I/O failure 3. Nothing escapes as an uncaught exception.
#include <functional>
#include <string>

#include "core/error.hpp"

namespace camouflet::app {

// "error: <file>:<line>: key '<key>': <message>" (parts that are unknown are left out).
std::string format_input_error(const InputError& e);

int run_guarded(const std::function<int()>& body);

}  // namespace camouflet::app
