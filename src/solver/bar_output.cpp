#include "solver/bar_output.hpp"

#include <fmt/format.h>

#include <cmath>

#include "output/history_resume.hpp"

namespace camouflet {

template <int D>
BarCsv<D>::BarCsv(const Model& model, const RunOptions& options, const EmbeddedBars<D>& bars)
    : interval_(model.output.gauge_interval) {
  if (bars.empty() || options.output_dir.empty()) return;
  std::string previous;
  int k = 0;
  for (std::size_t s = 0; s < bars.segment_count(); ++s) {
    k = bars.set_name(s) == previous ? k + 1 : 1;
    previous = bars.set_name(s);
    names_.push_back(fmt::format("{}.{}", previous, k));
  }
  path_ = options.output_dir / "bars.csv";
  if (options.restart.empty()) start(0.0, bars);  // else resume() once the bars are restored
}

template <int D>
void BarCsv<D>::start(double time, const EmbeddedBars<D>& bars) {
  csv_ = std::make_unique<GaugeCsv>(
      path_, names_,
      std::vector<std::string>{"axial_strain", "axial_stress", "axial_force", "plastic_strain"});
  next_ = 0.0;
  after_cycle(time, bars);
}

template <int D>
void BarCsv<D>::resume(double time, const EmbeddedBars<D>& bars) {
  if (path_.empty()) return;
  const std::optional<double> last = cut_history_before(path_, time);
  if (!last) return start(time, bars);  // no file left: the history starts at the restart
  csv_ = std::make_unique<GaugeCsv>(path_);
  next_ = std::isfinite(*last) ? *last + interval_ : 0.0;
  after_cycle(time, bars);  // the row of the checkpoint's cycle, when it was due
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
