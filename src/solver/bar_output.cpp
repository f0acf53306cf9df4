#include "solver/bar_output.hpp"

#include <fmt/format.h>

namespace camouflet {

template <int D>
BarCsv<D>::BarCsv(const Model& model, const RunOptions& options, const EmbeddedBars<D>& bars)
    : interval_(model.output.gauge_interval) {
  if (bars.empty() || options.output_dir.empty()) return;
  std::vector<std::string> names;
  std::string previous;
  int k = 0;
  for (std::size_t s = 0; s < bars.segment_count(); ++s) {
    k = bars.set_name(s) == previous ? k + 1 : 1;
    previous = bars.set_name(s);
    names.push_back(fmt::format("{}.{}", previous, k));
  }
  csv_ = std::make_unique<GaugeCsv>(
      options.output_dir / "bars.csv", names,
      std::vector<std::string>{"axial_strain", "axial_stress", "axial_force", "plastic_strain"});
  after_cycle(0.0, bars);
}

template <int D>
void BarCsv<D>::after_cycle(double time, const EmbeddedBars<D>& bars, bool last) {
  if (!csv_ || (!last && time < next_)) return;
  next_ = time + interval_;
  row_.clear();
  for (std::size_t s = 0; s < bars.segment_count(); ++s)
    row_.insert(row_.end(),
                {bars.axial_strain(s), bars.axial_stress(s), bars.axial_force(s), bars.plastic_strain(s)});
  csv_->write_row(time, row_);
}

template class BarCsv<2>;
template class BarCsv<3>;

}  // namespace camouflet
