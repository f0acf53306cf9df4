// Placeholder so the solver can link before the output layer lands: records
// nothing, writes nothing. Replaced by the output work (issue 2).
#include "output/run_output.hpp"

namespace camouflet {

struct RunOutput::Impl {
  std::vector<GaugeSeries> gauges;
};

RunOutput::RunOutput(const Model&, const RunOptions&, const FieldSnapshot&) : impl_(std::make_unique<Impl>()) {}
RunOutput::~RunOutput() = default;
void RunOutput::after_cycle(const FieldSnapshot&) {}
void RunOutput::finish(const FieldSnapshot&, const RunSummary&) {}
const std::vector<RunOutput::GaugeSeries>& RunOutput::gauges() const { return impl_->gauges; }

}  // namespace camouflet
