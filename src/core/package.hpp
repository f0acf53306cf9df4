#pragma once
// A method of the explicit cycle as the driver (solver/) sees it: its stages
// in the order of Solver::step, its vote for the next step, its energies and
// its state. A package registered with Solver::add_package joins every stage
// beside the FEM and SPH packages, so a method is added without editing the
// driver (docs/architecture.md, "Add a method"). Here, in the lowest layer,
// so that a package of any layer can implement it.
#include <array>
#include <string>

#include "core/state_visitor.hpp"

namespace camouflet {

template <int D>
class Package {
 public:
  virtual ~Package() = default;

  // Names the package in messages, in the reason for a time step it sets and
  // as its checkpoint scope ("package.<name>"): one word, unique in a run.
  virtual std::string name() const = 0;

  // Forces at t_n, from x(t_n) and v(n-1/2), the body acceleration `gravity`
  // (m/s^2, zero without gravity) included. Returns the power of the body
  // force at v(n-1/2) (W): the driver books it over the last step as the work
  // of gravity, the potential energy given up, as it does for nodes and particles.
  virtual double add_forces(double time, const std::array<double, 3>& gravity) = 0;

  // v(n+1/2) = v(n-1/2) + a dt_mean (dt_mean: the interval of the central
  // difference at t_n), and the package's own constraints.
  virtual void kick(double dt_mean) = 0;

  // Its kinetic energy at t_n in the form the central difference conserves
  // (J), then x(n+1) = x(n) + v(n+1/2) dt.
  virtual double drift(double dt) = 0;

  // Kinematics and material state at t_(n+1) = time.
  virtual void update_state(double dt, double time) = 0;

  // The largest stable step (s, before the CFL factor) and what sets it; a
  // package that limits nothing returns infinity.
  struct Vote {
    double dt = 0.0;     // s
    std::string reason;  // e.g. "point 3: contact"
  };
  virtual Vote vote() const = 0;

  // Energies at t_n (J): kinetic (1/2 m v^2, for the balance at t = 0) and internal.
  virtual double kinetic_energy() const = 0;
  virtual double internal_energy() const = 0;

  // The first point found non-finite or otherwise lost, described for the
  // failure message (name, position); empty when every point is sound.
  virtual std::string check() const = 0;

  // Every array and scalar of its state by name, for checkpoints.
  virtual void visit_state(StateVisitor& visitor) = 0;
};

}  // namespace camouflet
