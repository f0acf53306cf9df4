#pragma once
// A method of the explicit cycle as the driver (solver/) sees it: its stages
// in the order of Solver::step, its vote for the next step, its energies, its
// checks and its state. The SPH particles are one (sph/sph_package.hpp); a
// package registered with Solver::add_package joins every stage beside them,
// so a method is added without editing the driver (docs/architecture.md, "Add
// a method"). Here in `model`, under every layer that holds a method, so that
// the interface can speak of the model's records (the field snapshot).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/state_visitor.hpp"
#include "model/snapshot.hpp"

namespace camouflet {

template <int D>
class Package {
 public:
  virtual ~Package() = default;

  // Names the package in messages and in its energy shares (energy.csv's
  // "<name>_kinetic", "<name>_internal" where the file has such columns): one
  // word, unique in a run.
  virtual std::string name() const = 0;

  // Its own forces at t_n from x(t_n) and v(n-1/2) (the accelerations set
  // afresh). The couplings add theirs after this, gravity after them.
  virtual void add_forces(double time) = 0;

  // The body acceleration g (m/s^2) on every point, and the power of the body
  // force at v(n-1/2) added to `power` (W): the driver books it over the last
  // step as the work of gravity, the potential energy given up. Added to the
  // running sum, not returned, so that the sum runs over nodes and points in one order.
  virtual void add_gravity(const std::array<double, 3>& g, double& power) = 0;

  // v(n+1/2) = v(n-1/2) + a dt_mean (dt_mean: the interval of the central
  // difference at t_n), and the package's own constraints.
  virtual void kick(double dt_mean) = 0;

  // Its kinetic energy at t_n in the form the central difference conserves
  // (J), then x(n+1) = x(n) + v(n+1/2) dt.
  virtual double drift(double dt) = 0;

  // Kinematics and material state at t_(n+1) = time. Called before the FEM
  // elements' own update, whose element state a coupling may still read.
  virtual void update_state(double dt, double time) = 0;

  // The largest stable step (s, before the CFL factor) and what sets it, in
  // words that name the package's point; a package that limits nothing
  // returns infinity.
  struct Vote {
    double dt = 0.0;     // s
    std::string reason;  // e.g. "particle 3 (soil): h/(c+|v|+...)"
  };
  virtual Vote vote() const = 0;

  // Energies at t_n (J): kinetic (1/2 m v^2, for the balance at t = 0) and internal.
  virtual double kinetic_energy() const = 0;
  virtual double internal_energy() const = 0;

  // Throws NumericalError naming the first point found non-finite or lost
  // (kind and 1-based id; the driver adds cycle, time and describe()).
  virtual void check() const = 0;
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
