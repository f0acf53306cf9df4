// Dynamic relaxation before t = 0 (docs/theory/gravity.md, "Dynamic relaxation"): the explicit
// cycle with every velocity damped, until the model rests under gravity and its t = 0 loads.
// A geostatic state is exact for level layers; a structure in the soil, lighter and stiffer
// than the soil it replaces, is not in equilibrium in it, and this settles it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/solver.hpp"

namespace camouflet {

template <int D>
typename Solver<D>::Relaxation Solver<D>::relax(const RunControl::DynamicRelaxation& relaxation,
                                                const std::function<void(const Relaxation&)>& after_cycle) {
  if (cycle_ != 0) throw std::logic_error("relax: before the first step");
  for (const auto& package : packages_)
    if (!package->relaxes())
      throw std::logic_error("relax: the package '" + package->name() +
                             "' is not damped by a relaxation; register it after the relaxation");
  // Mass-proportional damping dv/dt = -c v at c = 2 omega_1 = 4 pi / T: critical for the
  // fundamental mode, which then settles within about a period; the higher modes ring down at
  // the same rate. Applied as v <- v exp(-c dt) after each step, exact for the damping alone.
  const double rate = 4.0 * std::numbers::pi / relaxation.period;
  Relaxation r;
  double quiet_since = -1.0;  // s of relaxation at which the kinetic energy last fell below the bar
  // Charges held still: nodes of their elements, particles of their materials.
  relaxation_held_materials_.assign(model_.materials.size(), 0);
  for (std::size_t m = 0; m < model_.materials.size(); ++m)
    relaxation_held_materials_[m] = model_.materials[m].material->eos().programmed_burn() ? 1 : 0;
  relaxing_ = true;
  while (true) {
    // Each cycle ends on t = 0: programmed burns stay unlit and time-dependent loads hold their
    // t = 0 values.
    time_ = -dt_next_;
    step();
    ++r.cycles;
    r.time += dt_;
    const double factor = std::exp(-rate * dt_);
    for (Package<D>* package : packages_) package->scale_velocities(factor);
    const double kinetic = energy().kinetic;  // at t_n of this cycle, before its damping
    r.peak_kinetic = std::max(r.peak_kinetic, kinetic);
    r.kinetic_ratio = r.peak_kinetic > 0.0 ? kinetic / r.peak_kinetic : 0.0;
    if (after_cycle) after_cycle(r);
    if (kinetic <= relaxation.tolerance * r.peak_kinetic) {
      if (quiet_since < 0.0) quiet_since = r.time;
    } else {
      quiet_since = -1.0;
    }
    // A whole period below the bar: a mode passing through its turning point (where its kinetic
    // energy is nought for an instant) does not end the relaxation.
    if (quiet_since >= 0.0 && r.time - quiet_since >= relaxation.period) break;
    if (r.time >= relaxation.max_time) {
      relaxing_ = false;
      fail(NumericalError(
          EntityKind::model, 0, "dynamic relaxation",
          fmt::format(
              "not at rest after {:.6g} s of relaxation ({} cycles): kinetic energy {:.6g} J is {:.3g} of "
              "its peak {:.6g} J, tolerance {:.3g}; a longer period (the model's fundamental period, "
              "now {:.6g} s) or max_time",
              r.time, r.cycles, kinetic, r.kinetic_ratio, r.peak_kinetic, relaxation.tolerance,
              relaxation.period)));
    }
  }
  relaxing_ = false;

  // At rest where it stands: the transient counts its displacements, time, cycles and energy
  // from here.
  for (Package<D>* package : packages_) package->come_to_rest();
  time_ = 0.0;
  cycle_ = 0;
  dt_ = 0.0;
  energy_ = EnergyBalance{};
  EnergySplit fresh;
  for (const auto& share : split_.packages) fresh.packages.push_back({share.name});
  split_ = fresh;
  fem_.start();
  gather_energies();
  // The boundary now holds the relaxed state's load, which differs from the initial one where
  // the relaxation moved the soil next to it.
  boundaries_.hold_initial_state(fem_, model_.run.gravity, model_.run.has_gravity(), true);
  start_energy_and_step();
  return r;
}

template Solver<2>::Relaxation Solver<2>::relax(const RunControl::DynamicRelaxation&,
                                                const std::function<void(const Relaxation&)>&);
template Solver<3>::Relaxation Solver<3>::relax(const RunControl::DynamicRelaxation&,
                                                const std::function<void(const Relaxation&)>&);

}  // namespace camouflet
