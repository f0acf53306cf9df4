#pragma once
// The energy balance as a run-time check: a warning once the relative error
// passes half of run.energy_error_limit, a numerical failure above it. The
// failure names the balance term that moved most since the last cycle that
// was still within half the limit, with every term's change, so the reader
// sees where the energy came from (docs/reliability.md, "Energy balance").
//
// The first warm_up_cycles cycles are not judged: a velocity or load applied
// as a step at t = 0 puts the centred balance off by about half a step's
// work, which in the first cycles is of the order of all the energy the
// model has received (the relative error falls as 1/cycle after it).
#include <array>
#include <cstdint>
#include <string>

#include "solver/solver.hpp"

namespace camouflet {

template <int D>
class EnergyGuard {
 public:
  // From the solver's state at the start (or at a restart).
  EnergyGuard(const RunControl& run, const Solver<D>& solver);
  // After each cycle. Throws NumericalError (kind model, quantity "energy balance").
  void after_cycle(const Solver<D>& solver);

  // The balance terms in J, in the order of term_names.
  static constexpr int term_count = 9;
  static constexpr std::int64_t warm_up_cycles = 100;
  static const std::array<const char*, term_count> term_names;

 private:
  using Terms = std::array<double, term_count>;
  static Terms terms_of(const Solver<D>& solver);
  std::string describe_failure(const Solver<D>& solver) const;

  double limit_;
  bool warned_ = false;
  Terms reference_{};  // the terms at the last cycle within half the limit
  std::int64_t reference_cycle_ = 0;
  double reference_time_ = 0.0;
  std::int64_t start_cycle_ = 0;  // the run's first cycle (a restart's cycle)
};

extern template class EnergyGuard<2>;
extern template class EnergyGuard<3>;

}  // namespace camouflet
