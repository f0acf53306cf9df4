#pragma once
// Energy history: `energy.csv` in the output folder, one row per gauge
// interval (every cycle when 0), `time_s` then `energy.<term>` in J (full
// revolution in axisymmetric mode, per metre of depth in plane strain):
// kinetic, internal, hourglass, eroded (EnergyBalance), viscous (FEM bulk
// viscosity heating, inside internal), boundary_work and its parts
// transmitting, constraints, join, contact (Solver::EnergySplit), join_face
// (the part of join done through the centre-face offset), the
// particles' and bars' shares sph_kinetic, sph_internal, bar_internal,
// residual = kinetic + internal + hourglass + eroded - initial - boundary_work
// (signed: negative = energy lost), and relative_error (EnergyBalance).
#include <filesystem>
#include <memory>

#include "output/gauge_csv.hpp"
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
class EnergyCsv {
 public:
  // No file when the run writes no output.
  EnergyCsv(const Model& model, const RunOptions& options, const Solver<D>& solver);
  // Restarts: once the solver is restored, continue the file the interrupted
  // run left, cut back to the rows before the restart (output/history_resume.hpp).
  void resume(const Solver<D>& solver);
  void after_cycle(const Solver<D>& solver);

 private:
  void start(const Solver<D>& solver);
  std::filesystem::path path_;
  std::unique_ptr<GaugeCsv> csv_;
  double interval_ = 0.0, next_ = 0.0;
  std::vector<double> row_;
};

extern template class EnergyCsv<2>;
extern template class EnergyCsv<3>;

}  // namespace camouflet
