#pragma once
// summary.json: final time, cycles, wall time, stop reason, the energy balance
// with its relative error, the last time-step limit, and for every gauge
// quantity its peak (the sample of largest magnitude, with its sign) and the
// time of that peak.
#include <string>
#include <vector>

#include "output/run_output.hpp"

namespace camouflet {

struct Peak {
  double value = 0.0;  // signed value of largest magnitude
  double time = 0.0;   // s
};

// Peak of one series; {0, 0} when empty.
Peak peak_of(const std::vector<double>& values, const std::vector<double>& time);

std::string summary_json(const Model& model, const RunSummary& summary,
                         const std::vector<RunOutput::GaugeSeries>& gauges);

// A JSON string literal with the needed escapes.
std::string json_string(const std::string& text);

}  // namespace camouflet
