#pragma once
// Rebar strain histories: `bars.csv` in the output folder, one row
// per gauge interval (every cycle when 0) with `time_s` and, for every
// segment `<bar>.<k>` (k from 1 at the bar's `from` end), its axial (log)
// strain, axial stress (Pa), axial force (N; per metre of depth in plane
// strain, the whole ring in axisymmetric mode) and plastic strain.
//
// On ranks every rank keeps one (its calls are collective): each row gathers the segments every
// rank steps to rank 0, which writes the file.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "fem/embedded_bars.hpp"
#include "output/gauge_csv.hpp"
#include "parallel/communicator.hpp"
#include "solver/run.hpp"

namespace camouflet {

template <int D>
class BarCsv {
 public:
  // No file when the model has no bars or the run writes no output. `comm`: the ranks of a run
  // across ranks (rank 0 writes), or nullptr.
  BarCsv(const Model& model, const RunOptions& options, const EmbeddedBars<D>& bars,
         const Communicator* comm = nullptr);
  // Restarts: once the bars are restored, continue the file the interrupted
  // run left, cut back to the rows before the restart (output/history_resume.hpp).
  void resume(double time, const EmbeddedBars<D>& bars);
  void after_cycle(double time, const EmbeddedBars<D>& bars, bool last = false);

 private:
  void start(double time, const EmbeddedBars<D>& bars);
  bool writes() const { return !comm_ || comm_->rank() == 0; }
  const Communicator* comm_ = nullptr;
  bool active_ = false;
  std::filesystem::path path_;
  std::vector<std::string> names_;
  std::unique_ptr<GaugeCsv> csv_;
  double interval_ = 0.0, next_ = 0.0;
  std::vector<double> row_;
};

extern template class BarCsv<2>;
extern template class BarCsv<3>;

}  // namespace camouflet
