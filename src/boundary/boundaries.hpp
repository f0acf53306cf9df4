#pragma once
// The model's boundaries as one object of the cycle: each kind acts on every package it
// touches, and the driver (solver/) calls it at its stages without knowing the kinds.
//
//   kind          FEM nodes                                      particles
//   fixed         every velocity component held at 0             -
//   velocity      the named components prescribed (history)      -
//   symmetry      no velocity along the plane's normal           mirrored in the plane (normal along an axis)
//   axis (r-z)    no radial velocity                             mirrored in r = 0 (PlaneKind::axis)
//   pressure      face loads on the current geometry             -
//   transmitting  Lysmer-Kuhlemeyer dashpots and the static hold -
//
// The particles' side is the list of mirror planes (mirror_planes.hpp), which the particle
// package takes at its construction and the join takes from it; the axis of an r-z model
// reflects particles whether or not a node set carries an `axis` condition. Adding a kind:
// docs/architecture.md, "Add a boundary kind".
#include <array>
#include <vector>

#include "boundary/boundary_conditions.hpp"
#include "boundary/mirror_planes.hpp"
#include "boundary/transmitting_boundary.hpp"
#include "core/state_visitor.hpp"
#include "fem/fem_package.hpp"
#include "model/model.hpp"

namespace camouflet {

template <int D>
class Boundaries {
 public:
  Boundaries() = default;
  // Resolves the model's boundaries onto the FEM package's nodes and faces and lists the
  // particles' planes. Throws InputError (at the condition's `where`) as BoundaryConditions and
  // TransmittingBoundary do.
  Boundaries(const Model& model, const FemPackage<D>& fem);

  // The planes particles are mirrored in, in the order their images are made: the axis of an
  // r-z model first, then the symmetry planes normal to a coordinate axis, each once.
  const std::vector<sph::MirrorPlane>& mirror_planes() const { return mirror_planes_; }

  // --- stages of the cycle, in their order in Solver::step ---
  // Forces at t_n: the pressure loads onto the FEM nodes at `time`, before the elements' forces
  // (ring_factor: FemPackage::begin_forces).
  void add_loads(FemPackage<D>& fem, double time, const double* ring_factor) {
    conditions_.add_loads(fem.position.data(), time, fem.force.data(), ring_factor);
  }
  // Forces at t_n, after gravity: the transmitting boundaries' static hold. Returns its work
  // from t_(n-1) to t_n over dt_old (J).
  double add_static_forces(FemPackage<D>& fem, double dt_old) const;
  // After every kick: the FEM nodes' v(n+1/2) for the half step centred on `time`, dashpots
  // first, then the node constraints. During a dynamic relaxation (`relaxing`) the dashpot
  // nodes are held at rest instead. The work from t_(n-1) to t_n (J):
  struct Work {
    double transmitting = 0.0;  // dashpots (<= 0)
    double constraints = 0.0;   // reactions of fixed, prescribed, symmetry and axis nodes; the loads
  };
  Work constrain(FemPackage<D>& fem, double time, double dt_old, double dt_mean, bool relaxing);
  // The constraints alone, no work (initial velocities).
  void constrain(std::vector<double>& velocity, double time) const { conditions_.constrain(velocity.data(), time); }

  // The transmitting boundaries' static load at t = 0 (transmitting_boundary.hpp): the reaction
  // that holds their nodes in the initial state under gravity g, or after a relaxation
  // (`relaxed`). A stress-free start without gravity holds nothing.
  void hold_initial_state(FemPackage<D>& fem, const std::array<double, 3>& g, bool has_gravity, bool relaxed);

  // The forces of earlier cycles that the centred boundary work needs, and the static hold.
  void visit_state(StateVisitor& visitor) {
    conditions_.visit_state(visitor);
    transmitting_.visit_state(visitor);
  }

 private:
  BoundaryConditions<D> conditions_;
  TransmittingBoundary<D> transmitting_;
  std::vector<sph::MirrorPlane> mirror_planes_;
};

extern template class Boundaries<2>;
extern template class Boundaries<3>;

}  // namespace camouflet
