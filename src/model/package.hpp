#pragma once
// A method of the explicit cycle as the driver (solver/) sees it: its stages
// in the order of Solver::step, its vote for the next step, its energies, its
// checks and its state. FEM (fem/fem_package.hpp) and the SPH particles
// (sph/sph_package.hpp) are two; a package registered with
// Solver::add_package joins every stage beside them, so a method is added
// without editing the driver (docs/architecture.md, "Add a method"). Here in
// `model`, under every layer that holds a method, so that the interface can
// speak of the model's records (the field snapshot, the energy balance).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/state_visitor.hpp"
#include "model/run_summary.hpp"
#include "model/snapshot.hpp"

namespace camouflet {

// The clock as a stage sees it (s). Before the clock advances (the force stages, kick, drift):
// time t_n, dt the step that ended there, dt_next the step being taken. After it (check,
// update_state): time t_(n+1), dt the step just taken, dt_next not chosen yet (equal to dt).
struct StepClock {
  std::int64_t cycle = 0;
  double time = 0.0;
  double dt = 0.0;
  double dt_next = 0.0;
  // t_(n+1/2) - t_(n-1/2): the interval of the velocity update at t_n (central difference).
  double dt_mean() const { return 0.5 * (dt + dt_next); }
};

template <int D>
class Package {
 public:
  virtual ~Package() = default;

  // Names the package in messages and in its energy shares (energy.csv's
  // "<name>_kinetic", "<name>_internal" where the file has such columns): one
  // word, unique in a run.
  virtual std::string name() const = 0;

  // --- stages, in the order of Solver::step. The force stages and the kick run in the order the
  // packages were registered (FEM, SPH, then those of add_package); drift and update_state in
  // the reverse order, so that a coupling that reads another package's points during a stage
  // (the join reads the FEM nodes and elements while the particles refresh their neighbours)
  // sees them kicked to v(n+1/2) in the first and still at x(t_n) and their t_n state in the
  // second. ---

  // Before any force of the step: what the package prepares for the forces the boundaries add
  // to its points first (FEM: its force arrays zeroed, the ring factors of r-z).
  virtual void begin_step(const StepClock& clock) { (void)clock; }

  // Its own forces at t_n from x(t_n) and v(n-1/2) (the accelerations set
  // afresh). The couplings add theirs after this, gravity after them.
  virtual void add_forces(const StepClock& clock) = 0;

  // The body acceleration g (m/s^2) on every point, and the power of the body
  // force at v(n-1/2) added to `power` (W): the driver books it over the last
  // step as the work of gravity, the potential energy given up. Added to the
  // running sum, not returned, so that the sum runs over nodes and points in one order.
  virtual void add_gravity(const std::array<double, 3>& g, double& power) = 0;

  // v(n+1/2) = v(n-1/2) + a clock.dt_mean(), and the package's own constraints (after the
  // boundaries' static forces).
  virtual void kick(const StepClock& clock) = 0;

  // Its kinetic energy at t_n in the form the central difference conserves
  // (J), then x(n+1) = x(n) + v(n+1/2) clock.dt_next.
  virtual double drift(const StepClock& clock) = 0;

  // Throws NumericalError naming the first point found non-finite or lost
  // (kind and 1-based id; the driver adds cycle, time and describe()). Called at the start of
  // a step and after the drift.
  virtual void check() const = 0;

  // Kinematics and material state at t_(n+1) = clock.time. The energy the update takes out of
  // the kinetic and internal energy is added to `energy.viscous` (hourglass and bulk viscosity)
  // and `energy.eroded` (points that left the sums): added to the running sums, not returned,
  // so that each keeps its order.
  virtual void update_state(const StepClock& clock, EnergyBalance& energy) = 0;

  // The largest stable step (s, before the CFL factor) and what sets it, in
  // words that name the package's point; a package that limits nothing
  // returns infinity.
  // A step below the run's min_dt stops the run naming the point that set it: `kind` and `id`
  // (1-based; the model when it names none) and `detail`, the numbers of its rule.
  struct Vote {
    double dt = 0.0;     // s
    std::string reason;  // e.g. "particle 3 (soil): h/(c+|v|+...)"
    EntityKind kind = EntityKind::model;
    std::int64_t id = 0;
    std::string detail;  // e.g. "l = 0.1 m, c = 1500 m/s, |v| = 3 m/s"
  };
  virtual Vote vote() const = 0;

  // Energies at t_n (J): kinetic (1/2 m v^2, for the balance at t = 0), internal, and the
  // hourglass energy (stored by a stiffness form, dissipated by a viscous one) that the balance
  // counts beside them.
  virtual double kinetic_energy() const = 0;
  virtual double internal_energy() const = 0;
  virtual double hourglass_energy() const { return 0.0; }

  // A point of this package as a failure message names it (material, position); empty when
  // the kind is not the package's or the id unknown.
  virtual std::string describe(EntityKind kind, std::int64_t id) const {
    (void)kind, (void)id;
    return {};
  }

  // Its fields of a snapshot (gauges, field output); a package without such fields adds none.
  virtual void fill_snapshot(FieldSnapshot& snapshot) const { (void)snapshot; }

  // Every array and scalar of its state by name, in a scope of its own, for checkpoints.
  virtual void visit_state(StateVisitor& visitor) = 0;

  // Dynamic relaxation (Solver::relax): a package that returns true is damped with the rest
  // (every velocity times `factor` after each step), holds the points of the flagged materials
  // (one entry per Model::materials entry) still after its kick, and comes to rest where it
  // stands at the end. relax() refuses to run with a package that returns false.
  virtual bool relaxes() const { return false; }
  virtual void scale_velocities(double factor) { (void)factor; }
  virtual void hold_still(const std::vector<char>& held_material) { (void)held_material; }
  virtual void come_to_rest() {}
};

}  // namespace camouflet
