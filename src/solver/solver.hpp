#pragma once
// The explicit Lagrangian cycle (architecture.md; Wang et al. 2005, Fig. 4)
// over FEM elements and SPH particles, driven one step at a time. run_model()
// drives it to the end time with output; tests drive it cycle by cycle.
//
// step() lists its stages. The FEM package (fem/fem_package.hpp) owns the
// nodes, elements, their material batches and bars, and is called by name at
// its stages; every other method is a Package<D> (model/package.hpp) in
// packages_, the SPH particles (sph/sph_package.hpp) first, and each stage
// loops over them. The join and the contact (coupling/) act between FEM and
// SPH. The solver keeps the clock, the step, the energy balance, the
// boundaries and the couplings.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "boundary/boundaries.hpp"
#include "core/state_visitor.hpp"
#include "coupling/sph_fem_coupling.hpp"
#include "fem/fem_package.hpp"
#include "materials/material_points.hpp"
#include "model/model.hpp"
#include "solver/run.hpp"
#include "model/package.hpp"
#include "sph/sph_package.hpp"

namespace camouflet {

template <int D>
class Solver {
 public:
  // Builds nodes, elements and one MaterialPoints batch per material from
  // the model. Throws InputError for an inverted element, a part without a
  // material or an unknown boundary set.
  explicit Solver(const Model& model);

  // One cycle: t_n -> t_{n+1}. Throws NumericalError (with cycle and time)
  // on a collapsed element, a non-finite state or a time-step collapse.
  void step();

  // Before the first step: a nodal velocity field (n * D, m/s) in place of the
  // parts' uniform ones (a radial inflow, a rotation), constrained by the
  // boundaries, voted into the first time step and counted in the initial energy.
  void set_initial_velocity(const std::vector<double>& v);

  // Before the first step: dynamic relaxation ([run.dynamic_relaxation]; solver/dynamic_relaxation.cpp).
  // Cycles under gravity and the t = 0 loads with every velocity damped at the rate 4 pi / period
  // until the kinetic energy has stayed below tolerance x its peak for a whole period; then the
  // nodes and particles are set at rest where they are (displacements zeroed), the clock, cycle
  // and energy balance restart at 0, and transmitting boundaries, held still meanwhile, take the
  // relaxed state's reaction as their static load.
  // The clock stays at t = 0 throughout: no burn starts, no load moves on. Throws
  // NumericalError when the model has not settled within max_time.
  struct Relaxation {
    double time = 0.0;  // s of relaxation
    std::int64_t cycles = 0;
    double kinetic_ratio = 0.0;  // kinetic energy at the end over its peak
    double peak_kinetic = 0.0;   // J
  };
  // `after_cycle`, if given, sees the relaxation so far after every cycle (progress lines).
  Relaxation relax(const RunControl::DynamicRelaxation& relaxation,
                   const std::function<void(const Relaxation&)>& after_cycle = {});

  // Before the first step: a further method, run after FEM and SPH at every stage of step()
  // (model/package.hpp; solver/package_stages.cpp): its forces, gravity with its work, kick,
  // drift with its kinetic energy in the balance, state update, internal energy, vote for the
  // step, checks and checkpoint state. relax() refuses to run with a package that is not
  // damped (Package::relaxes). Throws std::logic_error after the first step or for a name
  // already registered.
  void add_package(std::unique_ptr<Package<D>> package);

  // Caps the next time step (the driver uses it to land on the end time).
  void limit_next_step(double dt_max);

  double time() const { return time_; }
  std::int64_t cycle() const { return cycle_; }
  double next_dt() const { return dt_next_; }
  // 2-D: the first element found tangled (edges crossed, area still positive; fem_elements.hpp),
  // 1-based, and the cycle it was found at; 0 and -1 while none was. Reported on stderr, not
  // fatal (docs/reliability.md).
  std::int64_t first_tangled_element() const { return first_tangled_element_; }
  std::int64_t first_tangled_cycle() const { return first_tangled_cycle_; }
  // r-z: the first node found at r < 0 after moving inwards (crossed the axis), 1-based, and the
  // cycle; 0 and -1 while none did. Reported on stderr like a tangled element (solver_checks.cpp).
  std::int64_t first_axis_crossing_node() const { return first_axis_node_; }
  std::int64_t first_axis_crossing_cycle() const { return first_axis_cycle_; }
  const TimeStepLimit& time_step_limit() const { return limit_; }
  const EnergyBalance& energy() const { return energy_; }
  // Where the energy sits and what the boundary work is made of (energy.csv).
  struct EnergySplit {
    double transmitting = 0.0;  // J, dashpot work (negative: energy radiated out)
    double constraints = 0.0;   // J, reactions of fixed/prescribed/symmetry nodes and applied loads
    double join = 0.0;          // J, SPH-FEM join work booked by no internal energy (docs/theory/coupling.md)
    double join_face = 0.0;     // J, the part of `join` done through the coupling points' centre-face offset
    double contact = 0.0;       // J, particle-face contact work
    // J, the parts of EnergyBalance::kinetic and ::internal each package holds, in packages_'
    // order (energy.csv's sph_kinetic and sph_internal are the share named "sph").
    struct Share {
      std::string name;
      double kinetic = 0.0, internal = 0.0;
    };
    std::vector<Share> packages;
    double bar_internal = 0.0;  // J, part of EnergyBalance::internal held by embedded bars
    double gravity = 0.0;       // J, work of gravity (the potential energy given up; solver/gravity.cpp)
  };
  const EnergySplit& energy_split() const { return split_; }
  FieldSnapshot snapshot() const;
  // Every array and scalar of the run's state, for checkpoints (solver_state.cpp).
  void visit_state(StateVisitor& visitor);

  // --- state, for tests and output ---
  std::size_t node_count() const { return fem_.node_count(); }
  const std::vector<double>& position() const { return fem_.position; }
  const std::vector<double>& velocity() const { return fem_.velocity; }
  std::vector<double>& velocity() {  // tests impose initial fields
    nodes_checked_cycle_ = -1;       // so the next step checks them
    return fem_.velocity;
  }
  const std::vector<double>& displacement() const { return fem_.displacement; }
  const std::vector<double>& node_mass() const { return fem_.node_mass; }
  const FemElements<D>& elements() const { return fem_.elements; }
  const std::vector<MaterialPoints>& batches() const { return fem_.batches; }
  const FemPackage<D>& fem() const { return fem_; }
  // The SPH particles of the model (null when it has none).
  sph::SphSystem<D>* particles() { return sph_ ? &sph_->system() : nullptr; }
  const sph::SphSystem<D>* particles() const { return sph_ ? &sph_->system() : nullptr; }
  const EmbeddedBars<D>& bars() const { return fem_.bars; }
  std::size_t eroded_count() const { return fem_.eroded_count; }

 private:
  // Stages of step(), in order (the FEM and coupling parts of each stage by name, the
  // packages' in package_stages.cpp).
  void add_element_forces();
  void add_coupling_forces();
  void add_gravity();  // the body force m g and its work (solver/gravity.cpp)
  void add_static_boundary_forces();  // the transmitting boundaries' static load and its work (gravity.cpp)
  void constrain_velocities();
  void drift_nodes_and_account_energy();
  void advance_clock();        // dt, time and cycle move on to the step just taken
  void check_drifted_nodes();  // the first node the drift found non-finite or outside the box stops the run
  // t_(n+1/2) - t_(n-1/2): the interval of the velocity update at t_n (central difference).
  double centred_step() const { return 0.5 * (dt_ + dt_next_); }
  void element_kinematics();
  void gather_element_state();
  void choose_time_step();
  void start_energy_and_step();  // the first step's vote and the initial energy (constructor, set_initial_velocity)
  void erode_elements();  // FEM erosion, which the join follows (coupling_stages.cpp)
  // The packages' parts of the stages, each a loop over packages_ in order (package_stages.cpp).
  void register_package(std::unique_ptr<Package<D>> package);
  void add_package_forces();
  void add_package_gravity(const std::array<double, 3>& g, double& power);
  void kick_packages();
  void drift_packages();
  void update_packages();
  void check_packages() const;
  double package_internal_energy();  // and the shares in split_
  double package_kinetic_energy() const;
  void vote_packages(double& dt, std::string& reason) const;
  std::string describe_package_point(EntityKind kind, std::int64_t id) const;
  void visit_package_state(StateVisitor& visitor);

  [[noreturn]] void fail(NumericalError error) const;
  // Numerical-failure diagnostics (solver_checks.cpp): a node or particle outside the
  // domain box or with a non-finite position or velocity stops the run; an
  // entity is described by material and position in every failure message.
  void check_nodes_and_packages() const;
  [[noreturn]] void fail_node(std::int64_t n) const;  // 0-based; non-finite or outside the box
  void check_axis_crossings();                        // r-z: nodes moved to r < 0, reported (a warning)
  std::string describe(EntityKind kind, std::int64_t id) const;

  const Model& model_;
  GeometryMode mode_;

  FemPackage<D> fem_;  // nodes, elements, material batches, bars, erosion (fem/)
  // Every method but FEM, in the order of their stages: the SPH particles first (when the
  // model has any), then those registered with add_package.
  std::vector<std::unique_ptr<Package<D>>> packages_;
  sph::SphPackage<D>* sph_ = nullptr;  // the particle package in packages_ (particles())
  double package_kinetic_ = 0.0;       // J, the packages' centred kinetic energy at t_n
  // The join and the contact between the particles and FEM (coupling/); null without particles.
  std::unique_ptr<SphFemCoupling<D>> coupling_;
  std::int64_t first_tangled_element_ = 0, first_tangled_cycle_ = -1;  // see first_tangled_element()
  std::int64_t last_tangled_element_ = 0;
  int tangled_reports_ = 0;                                   // warnings printed (at most 20)
  std::int64_t first_axis_node_ = 0, first_axis_cycle_ = -1;  // see first_axis_crossing_node()
  std::vector<char> axis_reported_;                           // per node: its crossing was reported
  int axis_reports_ = 0;
  // Node constraints, loads, dashpots and the particles' mirror planes (boundary/boundaries.hpp).
  Boundaries<D> boundaries_;

  double time_ = 0.0;
  std::int64_t cycle_ = 0;
  // The cycle whose end state (x(n+1), v(n+1/2)) the node pass of
  // drift_nodes_and_account_energy found finite and inside the domain
  // box; -1 once anything else may have written the nodes (the non-const
  // velocity(), visit_state). A FEM-only step skips its start check of the
  // nodes while this equals cycle_: nothing writes them in between.
  std::int64_t nodes_checked_cycle_ = -1;
  std::int64_t drifted_bad_node_ = -1;  // the drift's first failed node (0-based), -1: none
  bool relaxing_ = false;  // in relax(): transmitting boundaries hold their nodes still
  // In relax(): the nodes and particle materials of explosives under programmed burn, held still
  // (EquationOfState::programmed_burn).
  std::vector<std::int64_t> relaxation_held_nodes_;
  std::vector<char> relaxation_held_materials_;
  void hold_charges_still();  // dynamic_relaxation.cpp
  double dt_ = 0.0;       // s, the step just taken (t_{n-1/2})
  double dt_next_ = 0.0;  // s, the step to take next (t_{n+1/2})
  TimeStepLimit limit_;
  EnergyBalance energy_;
  EnergySplit split_;
  double internal_energy_ = 0.0;  // J, sum m e at t_n: elements, particles and bars
};

extern template class Solver<2>;
extern template class Solver<3>;

}  // namespace camouflet
