#pragma once
// Running a model: the public entry point of the solver layer, used by
// `camouflet run` and by tests.
#include "model/model.hpp"
#include "model/run_options.hpp"
#include "model/run_summary.hpp"

namespace camouflet {

// Runs the model to its end time and writes the output folder. A numerical
// failure throws NumericalError (with cycle and time set) after writing what
// was computed so far.
RunSummary run_model(const Model& model, const RunOptions& options);

}  // namespace camouflet
