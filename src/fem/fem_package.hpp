#pragma once
// The FEM method as one package of the cycle (docs/architecture.md): the nodes,
// the elements with their integration-point state (one MaterialPoints batch per
// material), hourglass control, embedded bars and element erosion, with the
// stages the driver (solver/) calls in its step. The driver owns time, the
// step size, the energy balance and every boundary and coupling; it reads and
// writes the node arrays here through the package, and adds the SPH package's
// and the couplings' parts of each stage beside this one's.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/state_visitor.hpp"
#include "fem/embedded_bars.hpp"
#include "fem/fem_elements.hpp"
#include "materials/material.hpp"
#include "materials/material_points.hpp"
#include "model/model.hpp"
#include "model/snapshot.hpp"

namespace camouflet {

template <int D>
class FemPackage {
 public:
  FemPackage() = default;
  // Nodes, elements and one MaterialPoints batch per material from the model; the geostatic
  // state of its soil parts under gravity, the lumped masses and the parts' initial velocities
  // (mass-weighted where parts meet); embedded bars, erosion criteria, hourglass and bulk
  // viscosity controls. Throws InputError for an inverted element or a part without a material.
  explicit FemPackage(const Model& model);

  std::size_t node_count() const { return node_mass.size(); }

  // --- stages of the cycle, in their order in Solver::step ---
  // Forces at t_n, first part: the force arrays zeroed unless the last step's node passes left
  // them so, the ring factors of r-z area-weighted momentum from x(t_n) (null otherwise), which
  // the boundary loads the driver adds next also use.
  const double* begin_forces();
  // Forces at t_n, second part: element stresses less q and hourglass resistance (dt_previous
  // advances the stiffness-form displacements); then the embedded bars onto their hosts.
  void add_element_forces(double dt_previous);
  void add_bar_forces();
  // v(n+1/2) = v(n-1/2) + F/m dt_mean; a kept, v(n-1/2) kept as velocity_old.
  void kick(double dt_mean);
  // The node pass (solver.cpp describes its centring): x(n+1) = x(n) + v(n+1/2) dt, each node
  // tested finite and inside the run's domain box, the nodes' centred kinetic energy at t_n and
  // the viscous hourglass work from t_(n-1) to t_n.
  struct Drift {
    double kinetic = 0.0;         // J, the nodes' at t_n
    std::int64_t bad_node = -1;   // 0-based: the first node non-finite or outside the box; -1: none
  };
  Drift drift(double dt_minus, double dt_mean, double dt);
  // V, rho at t_(n+1); D, W, q at mid-step (fem_elements.hpp).
  KinematicsResult kinematics(double dt) {
    return elements.kinematics(position.data(), velocity.data(), velocity_old.data(), dt, viscosity, batches);
  }
  // Material::update on every FEM batch; the bars' uniaxial update.
  void update_materials(const MaterialContext& context);
  void update_bars(double dt, double time);
  // Elements past their material's erosion criteria leave the sums; their internal energy
  // joins `eroded_energy` (J). Returns whether any element eroded in this call.
  bool erode(double dt, double& eroded_energy);
  // sigma = s - p I, wave speeds from the batches; the elements' internal energy (J).
  struct State {
    double internal = 0.0;          // J, sum m e over the live elements
    std::int64_t bad_element = -1;  // 0-based: the first with a non-finite state; -1: none
  };
  State gather_state();
  // The smallest l / (c + |v|) over the live elements, ties to the lowest index (the same on any
  // thread count); element -1 when none is live.
  struct Vote {
    double dt = 0.0;  // s, before the CFL factor
    std::int64_t element = -1;
  };
  Vote element_vote() const;
  double hourglass_energy() const { return hourglass_dissipated + hourglass_stored; }
  // The element fields of a snapshot (the node fields too).
  void fill_snapshot(FieldSnapshot& s) const;
  // The nodes, elements and material batches by name, for checkpoints (fem_package_state.cpp); the
  // bars visit theirs themselves.
  void visit_state(StateVisitor& visitor);

  // --- state ---
  // Nodes (SoA, n * D each).
  std::vector<double> position, velocity, velocity_old, acceleration, force, displacement;
  std::vector<double> hourglass_force;           // N, the viscous hourglass part of force at t_n
  std::vector<double> hourglass_force_previous;  // N, the same at t_(n-1) (empty without viscous control)
  std::vector<double> node_mass;                 // kg (plane strain: per metre of depth)
  FemElements<D> elements;
  std::vector<MaterialPoints> batches;  // one per Model::materials entry
  EmbeddedBars<D> bars;
  HourglassControl hourglass;
  ViscosityControl viscosity;
  double hourglass_stored = 0.0;      // J, stiffness-form hourglass energy at t_n
  double hourglass_dissipated = 0.0;  // J, work absorbed by the viscous form
  bool erosion = false;                 // some material erodes
  std::vector<SymTensor> total_strain;  // per element, sum D dt (geometric-strain erosion)
  std::size_t eroded_count = 0;
  // force and hourglass_force_previous hold zeros: the node passes zero them at their last read
  // in a step, so begin_forces need not fill them again (false after a restore: a checkpoint
  // holds the forces of its last step).
  bool forces_zeroed = false;

 private:
  void set_geostatic_state();  // fem_package_setup.cpp
  const Model* model_ = nullptr;
  // Snapshot buffers gathered from the material batches.
  mutable std::vector<double> element_pressure_, element_plastic_strain_, element_damage_,
      element_temperature_;
};

extern template class FemPackage<2>;
extern template class FemPackage<3>;

}  // namespace camouflet
