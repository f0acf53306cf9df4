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

// Running peaks of one gauge group, kept sample by sample so that the summary
// never needs the whole history in memory: peaks[q * gauges + g].
struct GroupPeaks {
  std::vector<Peak> peaks;
  std::vector<bool> seen;
  void add(std::size_t index, double value, double time);
};

// `gauges` gives the names and sample counts, `peaks` (same order) the values.
std::string summary_json(const Model& model, const RunSummary& summary,
                         const std::vector<RunOutput::GaugeSeries>& gauges,
                         const std::vector<GroupPeaks>& peaks, const std::vector<std::size_t>& samples);

// A JSON string literal with the needed escapes.
std::string json_string(const std::string& text);

}  // namespace camouflet
