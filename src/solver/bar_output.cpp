#include "solver/bar_output.hpp"

#include <fmt/format.h>

#include <cmath>

#include "output/history_resume.hpp"

namespace camouflet {

template <int D>
BarCsv<D>::BarCsv(const Model& model, const RunOptions& options, const EmbeddedBars<D>& bars,
                  const Communicator* comm)
    : comm_(comm && comm->size() > 1 ? comm : nullptr), interval_(model.output.gauge_interval) {
  if (bars.whole_segment_count() == 0 || options.output_dir.empty()) return;
  active_ = true;
  std::string previous;
  int k = 0;
  for (const BarSet& set : model.bars)
    for (int s = 0; s < set.segments; ++s) {
      k = set.name == previous ? k + 1 : 1;
      previous = set.name;
      names_.push_back(fmt::format("{}.{}", previous, k));
    }
  path_ = options.output_dir / "bars.csv";
  if (options.restart.empty()) start(0.0, bars);  // else resume() once the bars are restored
}

template <int D>
void BarCsv<D>::start(double time, const EmbeddedBars<D>& bars) {
  if (writes())
    csv_ = std::make_unique<GaugeCsv>(
        path_, names_,
        std::vector<std::string>{"axial_strain", "axial_stress", "axial_force", "plastic_strain"});
  next_ = 0.0;
  after_cycle(time, bars);
}

template <int D>
void BarCsv<D>::resume(double time, const EmbeddedBars<D>& bars) {
  if (!active_) return;
  // Rank 0 reads the file; every rank takes its schedule from there.
  double found[2] = {0.0, 0.0};  // {a file was left, the time of its last row}
  if (writes()) {
    const std::optional<double> last = cut_history_before(path_, time);
    found[0] = last ? 1.0 : 0.0;
    found[1] = last ? *last : 0.0;
  }
  if (comm_) {
    const std::vector<double> all = comm_->all_gather(std::span<const double>(found, 2));
    found[0] = all[0];
    found[1] = all[1];
  }
  if (found[0] == 0.0) return start(time, bars);  // no file left: the history starts at the restart
  if (writes()) csv_ = std::make_unique<GaugeCsv>(path_);
  next_ = std::isfinite(found[1]) ? found[1] + interval_ : 0.0;
  after_cycle(time, bars);  // the row of the checkpoint's cycle, when it was due
}

template <int D>
void BarCsv<D>::after_cycle(double time, const EmbeddedBars<D>& bars, bool last) {
  if (!active_ || (!last && time < next_)) return;
  next_ = time + interval_;
  // Each segment's values at its place in the whole model's list; on ranks the rows add up the
  // ranks' (each segment is stepped by one, the others add noughts, which leave it exact).
  row_.assign(4 * bars.whole_segment_count(), 0.0);
  for (std::size_t s = 0; s < bars.segment_count(); ++s) {
    const std::size_t k = 4 * bars.whole_segment(s);
    row_[k] = bars.axial_strain(s);
    row_[k + 1] = bars.axial_stress(s);
    row_[k + 2] = bars.axial_force(s);
    row_[k + 3] = bars.plastic_strain(s);
  }
  if (comm_) comm_->sum(row_);
  if (csv_) csv_->write_row(time, row_);
}

template class BarCsv<2>;
template class BarCsv<3>;

}  // namespace camouflet
