#include "solver/energy_guard.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "parallel/communicator.hpp"

namespace camouflet {

// kinetic + internal + hourglass + eroded - initial = boundary_work, and the
// boundary work's parts (Solver::EnergySplit).
template <int D>
const std::array<const char*, EnergyGuard<D>::term_count> EnergyGuard<D>::term_names = {
    "kinetic", "internal", "hourglass", "eroded", "boundary_work", "transmitting", "constraints", "join",
    "contact"};

template <int D>
typename EnergyGuard<D>::Terms EnergyGuard<D>::terms_of(const Solver<D>& solver) {
  const EnergyBalance& e = solver.energy();
  const typename Solver<D>::EnergySplit& s = solver.energy_split();
  return {e.kinetic, e.internal, e.hourglass, e.eroded, e.boundary_work, s.transmitting, s.constraints, s.join,
          s.contact};
}

template <int D>
EnergyGuard<D>::EnergyGuard(const RunControl& run, const Solver<D>& solver)
    : limit_(run.energy_error_limit),
      reference_(terms_of(solver)),
      reference_cycle_(solver.cycle()),
      reference_time_(solver.time()),
      start_cycle_(solver.cycle()) {}

template <int D>
void EnergyGuard<D>::after_cycle(const Solver<D>& solver) {
  if (!std::isfinite(limit_)) return;
  const double error = solver.energy().relative_error;
  if (!(error > 0.5 * limit_) || solver.cycle() - start_cycle_ < warm_up_cycles) {
    reference_ = terms_of(solver);
    reference_cycle_ = solver.cycle();
    reference_time_ = solver.time();
    return;
  }
  if (!(error > limit_)) {
    if (!warned_ && world().rank() == 0)  // on ranks every rank holds the same balance: said once
      fmt::print(stderr,
                 "warning: relative energy error {:.3e} at cycle {}, time {:.6g} s is past half of "
                 "energy_error_limit {:.3e} (energy.csv has the terms)\n",
                 error, solver.cycle(), solver.time(), limit_);
    warned_ = true;
    return;
  }
  NumericalError failure(EntityKind::model, 0, "energy balance", describe_failure(solver));
  failure.set_context(solver.cycle(), solver.time(), "");
  throw failure;
}

template <int D>
std::string EnergyGuard<D>::describe_failure(const Solver<D>& solver) const {
  const EnergyBalance& e = solver.energy();
  const Terms now = terms_of(solver);
  const Terms& before = reference_;
  const double residual = e.kinetic + e.internal + e.hourglass + e.eroded - e.initial_total - e.boundary_work;
  // The stored energies and the boundary work as a whole (its parts are listed, not ranked).
  int worst = 0;
  for (int k = 1; k < 5; ++k)
    if (std::abs(now[k] - before[k]) > std::abs(now[worst] - before[worst])) worst = k;
  std::string changes;
  for (int k = 0; k < term_count; ++k)
    changes += fmt::format("{}{} {:+.4e}", k ? ", " : "", term_names[k], now[k] - before[k]);
  return fmt::format(
      "relative energy error {:.3e} exceeds energy_error_limit {:.3e} (residual {:+.4e} J); the largest change "
      "since cycle {} (t = {:.6g} s, the last within half the limit) is {} {:+.4e} J; changes in J: {}",
      e.relative_error, limit_, residual, reference_cycle_, reference_time_, term_names[worst],
      now[worst] - before[worst], changes);
}

template class EnergyGuard<2>;
template class EnergyGuard<3>;

}  // namespace camouflet
