#pragma once
// The FEM method as a package of the cycle (model/package.hpp; docs/architecture.md): the
// nodes, the elements with their integration-point state (one MaterialPoints batch per
// material), hourglass control, embedded bars and element erosion, with their stages, vote,
// energies, checks and state. The driver (solver/) calls it at every stage as it calls the
// particles; the boundaries (boundary/boundaries.hpp) and the couplings (coupling/) act on its
// node arrays, which are public for them.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/state_visitor.hpp"
#include "fem/embedded_bars.hpp"
#include "fem/fem_elements.hpp"
#include "materials/material.hpp"
#include "materials/material_points.hpp"
#include "model/model.hpp"
#include "model/node_sharing.hpp"
#include "model/package.hpp"
#include "model/point_view.hpp"
#include "model/snapshot.hpp"

namespace camouflet {

template <int D>
class FemPackage final : public Package<D> {
 public:
  FemPackage() = default;
  // Nodes, elements and one MaterialPoints batch per material from the model; the geostatic
  // state of its soil parts under gravity, the lumped masses and the parts' initial velocities
  // (mass-weighted where parts meet); embedded bars, erosion criteria, hourglass and bulk
  // viscosity controls. Throws InputError for an inverted element or a part without a material.
  // On one of several ranks (`sharing`; model/node_sharing.hpp) the model's mesh is this rank's
  // part: the masses and momenta of the nodes it shares are added up over their holders here,
  // the forces at every step (add_forces), and messages name the whole mesh's ids. Embedded
  // bars there are the rank's share (NodeSharing::bar_share): their masses and forces join the
  // sums of the shared nodes.
  explicit FemPackage(const Model& model, const NodeSharing* sharing = nullptr);

  std::size_t node_count() const { return node_mass.size(); }

  // --- the stages of Package<D> (fem_package_stages.cpp) ---
  std::string name() const override { return "fem"; }
  // The force arrays zeroed unless the last step's node passes left them so; the ring factors
  // of r-z area-weighted momentum from x(t_n), which the boundaries' loads use (ring_factor()).
  void begin_step(const StepClock& clock) override;
  // Element stresses less q and hourglass resistance (clock.dt advances the stiffness-form
  // displacements), then the embedded bars' forces on their host nodes; on ranks, then the forces
  // of shared nodes (with the loads the boundaries added before) added up over their holders, so
  // that gravity, added after, counts once.
  void add_forces(const StepClock& clock) override { add_element_forces(clock.dt); }
  void add_gravity(const std::array<double, 3>& g, double& power) override;
  // v(n+1/2) = v(n-1/2) + F/m dt_mean (a kept, v(n-1/2) kept as velocity_old).
  void kick(const StepClock& clock) override { kick_nodes(clock.dt_mean()); }
  // The node pass: x(n+1), each node tested finite and inside the run's domain box (check()
  // reports the first that is not), the nodes' centred kinetic energy at t_n and the viscous
  // hourglass work from t_(n-1) to t_n.
  double drift(const StepClock& clock) override;
  // The first node the last drift found non-finite or outside the domain box; every node when
  // something else has written them since (mark_nodes_unchecked).
  void check() const override;
  // r-z nodes across the axis reported (a warning); V, rho at t_(n+1) and D, W, q at mid-step,
  // tangled elements reported (a warning); the material update of every batch and of the bars;
  // erosion; the element state the next forces and the vote read.
  void update_state(const StepClock& clock, EnergyBalance& energy) override;
  // The smallest l / (c + |v|) over the live elements (ties to the lowest index, the same on any
  // thread count), or L / c of a bar segment when smaller.
  typename Package<D>::Vote vote() const override;
  double kinetic_energy() const override;
  double internal_energy() const override { return element_internal_ + bars.internal_energy(); }
  double hourglass_energy() const override { return hourglass_dissipated + hourglass_stored; }
  std::string describe(EntityKind kind, std::int64_t id) const override;  // nodes and elements
  void fill_snapshot(FieldSnapshot& s) const override;  // node and element fields
  // The nodes, elements, material batches, erosion and hourglass sums and the bars by name, in
  // the driver's scope (fem_package_state.cpp).
  void visit_state(StateVisitor& visitor) override;
  bool relaxes() const override { return true; }
  void scale_velocities(double factor) override;
  void hold_still(const std::vector<char>& held_material) override;  // the nodes of those elements
  void come_to_rest() override;

  // The nodes as the couplings read them (model/point_view.hpp).
  PointView<D> nodes() const { return {position, velocity, node_mass}; }
  // The ring factors begin_step made (null outside r-z area-weighted momentum).
  const double* ring_factor() const { return ring_factor_; }
  // At set-up (the driver's constructor, initial velocities, the end of a relaxation): the
  // elements' speeds from the node velocities and their gathered state. Throws NumericalError
  // for a non-finite element state.
  void start();
  // On ranks: how this rank shares nodes with the others (null on one rank), for the boundaries
  // that assemble node quantities from faces or elements.
  const NodeSharing* sharing() const { return sharing_; }
  // On ranks: per local node, whether this rank counts it in global sums; null on one rank.
  const char* owned_nodes() const { return sharing_ ? sharing_->owned_nodes().data() : nullptr; }
  // The 1-based id a message gives a local node or element (0-based): its id in the whole mesh.
  std::int64_t node_id(std::int64_t n) const { return (sharing_ ? sharing_->global_nodes()[static_cast<std::size_t>(n)] : n) + 1; }
  std::int64_t element_id(std::int64_t e) const {
    return (sharing_ ? sharing_->global_elements()[static_cast<std::size_t>(e)] : e) + 1;
  }
  // After anything but the node pass wrote the nodes: the next check() tests them all.
  void mark_nodes_unchecked() { nodes_checked_ = false; }
  // The first element found tangled (edges crossed, area still positive) and the first r-z node
  // found across the axis, 1-based, with their cycles; 0 and -1 while none was.
  struct Reports {
    std::int64_t first_tangled_element = 0, first_tangled_cycle = -1, last_tangled_element = 0;
    int tangled_lines = 0;  // warnings printed (at most 20)
    std::int64_t first_axis_node = 0, first_axis_cycle = -1;
    std::vector<char> axis_reported;  // per node: its crossing was reported
    int axis_lines = 0;
  };
  const Reports& reports() const { return reports_; }

  // Elements past their material's erosion criteria leave the sums; their internal energy
  // joins `eroded_energy` (J). Returns whether any element eroded in this call.
  bool erode(double dt, double& eroded_energy);

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
  // The parts of the stages (fem_package.cpp).
  void add_element_forces(double dt_previous);
  void kick_nodes(double dt_mean);
  struct Drift {
    double kinetic = 0.0;        // J, the nodes' at t_n
    std::int64_t bad_node = -1;  // 0-based: the first node non-finite or outside the box; -1: none
  };
  Drift drift_nodes(double dt_minus, double dt_mean, double dt);
  void update_materials(const MaterialContext& context);
  void update_bars(double dt, double time);
  struct State {
    double internal = 0.0;          // J, sum m e over the live elements
    std::int64_t bad_element = -1;  // 0-based: the first with a non-finite state; -1: none
  };
  State gather_state();  // sigma = s - p I, wave speeds from the batches
  struct ElementVote {
    double dt = 0.0;  // s, before the CFL factor
    std::int64_t element = -1;
  };
  ElementVote element_vote() const;
  void gather_and_check();  // gather_state, its internal energy kept, a non-finite state thrown
  void report_axis_crossings(const StepClock& clock);
  void report_tangled(const KinematicsResult& r, const StepClock& clock);
  NumericalError node_failure(std::int64_t n) const;  // 0-based

  // The local index (0-based) of a node or element a message names by its 1-based id; -1 when
  // this rank does not hold it.
  std::int64_t local_index(EntityKind kind, std::int64_t id) const;

  const Model* model_ = nullptr;
  const NodeSharing* sharing_ = nullptr;  // null on one rank
  const double* ring_factor_ = nullptr;
  double element_internal_ = 0.0;  // J, the live elements' at the last gather
  std::int64_t drift_bad_node_ = -1;
  bool nodes_checked_ = false;  // the last node pass tested every node, and nothing wrote them since
  Reports reports_;
  std::vector<char> held_material_;         // the last hold_still's flags ...
  std::vector<std::int64_t> held_nodes_;    // ... and the nodes of their elements
  // Snapshot buffers gathered from the material batches.
  mutable std::vector<double> element_pressure_, element_plastic_strain_, element_damage_,
      element_temperature_;
};

extern template class FemPackage<2>;
extern template class FemPackage<3>;

}  // namespace camouflet
