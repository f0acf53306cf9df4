#include "solver/energy_output.hpp"

#include <cmath>

#include "output/history_resume.hpp"

namespace camouflet {

template <int D>
EnergyCsv<D>::EnergyCsv(const Model& model, const RunOptions& options, const Solver<D>& solver)
    : interval_(model.output.gauge_interval) {
  if (options.output_dir.empty()) return;
  path_ = options.output_dir / "energy.csv";
  if (options.restart.empty()) start(solver);  // else resume() once the solver is restored
}

template <int D>
void EnergyCsv<D>::start(const Solver<D>& solver) {
  csv_ = std::make_unique<GaugeCsv>(
      path_, std::vector<std::string>{"energy"},
      std::vector<std::string>{"kinetic", "internal", "hourglass", "eroded", "viscous", "boundary_work",
                               "transmitting", "constraints", "join", "join_face", "contact", "sph_kinetic",
                               "sph_internal", "bar_internal", "gravity", "residual", "relative_error"});
  next_ = 0.0;
  after_cycle(solver);
}

template <int D>
void EnergyCsv<D>::resume(const Solver<D>& solver) {
  if (path_.empty()) return;
  const std::optional<double> last = cut_history_before(path_, solver.time());
  if (!last) return start(solver);  // no file left: the history starts at the restart
  csv_ = std::make_unique<GaugeCsv>(path_);
  next_ = std::isfinite(*last) ? *last + interval_ : 0.0;
  after_cycle(solver);  // the row of the checkpoint's cycle, when it was due
}

template <int D>
void EnergyCsv<D>::after_cycle(const Solver<D>& solver) {
  const double time = solver.time();
  if (!csv_ || time < next_) return;
  next_ = time + interval_;
  const EnergyBalance& e = solver.energy();
  const typename Solver<D>::EnergySplit& s = solver.energy_split();
  const double residual = e.kinetic + e.internal + e.hourglass + e.eroded - e.initial_total - e.boundary_work;
  double sph_kinetic = 0.0, sph_internal = 0.0;  // the particle package's share
  for (const auto& share : s.packages)
    if (share.name == "sph") sph_kinetic = share.kinetic, sph_internal = share.internal;
  row_.assign({e.kinetic, e.internal, e.hourglass, e.eroded, e.viscous, e.boundary_work, s.transmitting,
               s.constraints, s.join, s.join_face, s.contact, sph_kinetic, sph_internal, s.bar_internal,
               s.gravity, residual, e.relative_error});
  csv_->write_row(time, row_);
}

template class EnergyCsv<2>;
template class EnergyCsv<3>;

}  // namespace camouflet
