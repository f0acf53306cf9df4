#pragma once
// The explicit Lagrangian cycle (architecture.md; Wang et al. 2005, Fig. 4)
// over FEM elements and SPH particles, driven one step at a time. run_model()
// drives it to the end time with output; tests drive it cycle by cycle.
//
// step() lists its stages, each a loop over the packages (model/package.hpp):
// FEM (fem/fem_package.hpp), the SPH particles (sph/sph_package.hpp) when the
// model has any, then those registered with add_package. Between them act the
// boundaries (boundary/boundaries.hpp) and the couplings between FEM and SPH
// (coupling/). The solver keeps the clock, the step, the energy balance and
// the failure diagnostics.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "boundary/boundaries.hpp"
#include "core/state_visitor.hpp"
#include "coupling/slide_surface.hpp"
#include "coupling/sph_fem_coupling.hpp"
#include "fem/fem_package.hpp"
#include "materials/material_points.hpp"
#include "model/model.hpp"
#include "solver/run.hpp"
#include "model/package.hpp"
#include "parallel/rank_part.hpp"
#include "sph/sph_package.hpp"

namespace camouflet {

template <int D>
class Solver {
 public:
  // Builds nodes, elements and one MaterialPoints batch per material from
  // the model. Throws InputError for an inverted element, a part without a
  // material or an unknown boundary set.
  explicit Solver(const Model& model) : Solver(model, nullptr) {}
  // This rank's part of a run across MPI ranks (parallel/rank_part.hpp): its cut model, stepped
  // here, with the shared nodes' forces and masses added up over their holders (FemPackage), and
  // the time step and the energy balance decided over every rank through part.comm(), the same
  // bits on each. `part` must outlive the solver. Every rank constructs and steps together.
  explicit Solver(const RankPart& part) : Solver(part.model(), &part) {}

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

  // Before the first step: a further method, run after FEM and SPH at the force stages and the
  // kick and before them at the drift and the update, as model/package.hpp orders the stages
  // (solver/package_stages.cpp): its forces, gravity with its work, kick,
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
  std::int64_t first_tangled_element() const { return fem_.reports().first_tangled_element; }
  std::int64_t first_tangled_cycle() const { return fem_.reports().first_tangled_cycle; }
  // r-z: the first node found at r < 0 after moving inwards (crossed the axis), 1-based, and the
  // cycle; 0 and -1 while none did. Reported on stderr like a tangled element
  // (fem/fem_package_stages.cpp).
  std::int64_t first_axis_crossing_node() const { return fem_.reports().first_axis_node; }
  std::int64_t first_axis_crossing_cycle() const { return fem_.reports().first_axis_cycle; }
  const TimeStepLimit& time_step_limit() const { return limit_; }
  // The whole run's balance (on ranks: every rank's share added up in rank order).
  const EnergyBalance& energy() const { return ranks_ ? global_energy_ : energy_; }
  // Where the energy sits and what the boundary work is made of (energy.csv).
  struct EnergySplit {
    double transmitting = 0.0;  // J, dashpot work (negative: energy radiated out)
    double constraints = 0.0;   // J, reactions of fixed/prescribed/symmetry nodes and applied loads
    double join = 0.0;          // J, SPH-FEM join work booked by no internal energy (docs/theory/coupling.md)
    double join_face = 0.0;     // J, the part of `join` done through the coupling points' centre-face offset
    double contact = 0.0;       // J, contact work: particle-face contacts and FEM slide surfaces
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
  const EnergySplit& energy_split() const { return ranks_ ? global_split_ : split_; }
  FieldSnapshot snapshot() const;
  // Every array and scalar of the run's state, for checkpoints (solver_state.cpp).
  void visit_state(StateVisitor& visitor);

  // --- state, for tests and output ---
  std::size_t node_count() const { return fem_.node_count(); }
  const std::vector<double>& position() const { return fem_.position; }
  const std::vector<double>& velocity() const { return fem_.velocity; }
  std::vector<double>& velocity() {  // tests impose initial fields
    fem_.mark_nodes_unchecked();     // so the next step checks them
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
  Solver(const Model& model, const RankPart* ranks);
  // On ranks: global_energy_ and global_split_, every rank's shares added up in rank order, and
  // their relative error (solver_ranks.cpp); whether any rank says it `failed` (one exchange).
  bool reduce_energy(bool failed);
  static void set_relative_error(EnergyBalance& e);
  // On ranks: the smallest of every rank's step and the reason of the rank that holds it (the
  // lowest on a tie); whether this rank holds it.
  bool reduce_time_step(double& dt, std::string& reason) const;
  // On ranks, when reduce_energy found that a rank failed (`failure` on it, at the step's guarded
  // stage `stage`): every rank throws the error the serial run would have thrown, the earliest
  // stage's with the lowest id (the lowest rank on a tie), named as its rank describes it.
  void agree_on_failure(std::optional<NumericalError>& failure, int stage) const;

  // Stages of step() that are not loops over the packages, in order (the loops are in
  // package_stages.cpp, the couplings' in coupling_stages.cpp).
  void add_coupling_forces();
  void add_gravity();                 // the body force m g on every package's points, its work (gravity.cpp)
  void add_static_boundary_forces();  // the transmitting boundaries' static load and its work (gravity.cpp)
  void constrain_velocities();        // boundaries on v(n+1/2); the couplings settle
  void account_energy();              // the balance at t_n, once every package has drifted
  void follow_packages();             // the couplings follow the packages' erosion
  void gather_energies();             // the packages' internal energy at t_(n+1) and the shares
  void choose_time_step();            // dt(n+3/2) = CFL min over the packages' votes, growth limited
  void advance_clock();               // dt, time and cycle move on to the step just taken
  StepClock clock() const { return {cycle_, time_, dt_, dt_next_}; }
  // t_(n+1/2) - t_(n-1/2): the interval of the velocity update at t_n (central difference).
  double centred_step() const { return clock().dt_mean(); }
  void start_energy_and_step();  // the first step's vote and the initial energy (constructor, set_initial_velocity)
  // The packages' stages, each a loop over packages_ (package_stages.cpp).
  void register_package(Package<D>& package);                 // held elsewhere (FEM, a member)
  void register_package(std::unique_ptr<Package<D>> package);  // owned here
  void begin_packages();
  void add_package_forces();
  void kick_packages();
  void drift_packages();   // reverse order; their centred kinetic energies into split_
  void check_packages() const;
  void update_packages();  // reverse order
  double package_kinetic_energy() const;    // 1/2 m v^2 at t_n, summed in packages_' order
  double package_hourglass_energy() const;  // J, summed in packages_' order
  std::string describe(EntityKind kind, std::int64_t id) const;  // the first package that knows the point
  void visit_package_state(StateVisitor& visitor);

  [[noreturn]] void fail(NumericalError error) const;

  const Model& model_;
  GeometryMode mode_;
  const RankPart* ranks_ = nullptr;  // null on one rank (no communicator at all)

  FemPackage<D> fem_;  // nodes, elements, material batches, bars, erosion (fem/)
  // Every method in the order of their stages: FEM, the SPH particles (when the model has any),
  // then those registered with add_package. FEM is a member (the boundaries and the couplings
  // hold it); the others are owned here.
  std::vector<Package<D>*> packages_;
  std::vector<std::unique_ptr<Package<D>>> owned_packages_;
  sph::SphPackage<D>* sph_ = nullptr;  // the particle package in packages_ (particles())
  // The join and the contact between the particles and FEM (coupling/); null without particles.
  std::unique_ptr<SphFemCoupling<D>> coupling_;
  // Node constraints, loads, dashpots and the particles' mirror planes (boundary/boundaries.hpp).
  Boundaries<D> boundaries_;
  // The FEM-FEM slide surfaces (coupling/slide_surface.hpp), their work booked with the contact's.
  SlideSurfaces<D> slides_;

  double time_ = 0.0;
  std::int64_t cycle_ = 0;
  bool relaxing_ = false;  // in relax(): transmitting boundaries hold their nodes still
  // In relax(): the materials of explosives under programmed burn, whose nodes and particles are
  // held still (EquationOfState::programmed_burn).
  std::vector<char> relaxation_held_materials_;
  double dt_ = 0.0;       // s, the step just taken (t_{n-1/2})
  double dt_next_ = 0.0;  // s, the step to take next (t_{n+1/2})
  // s, the packages' stable step times cfl at the last vote, before the growth limit and the
  // driver's cuts: the slide surfaces' stiffness follows it (coupling/slide_surface.hpp).
  double dt_stable_ = 0.0;
  TimeStepLimit limit_;
  // This rank's shares of the balance, accumulated step by step (the whole run's on one rank).
  EnergyBalance energy_;
  EnergySplit split_;
  EnergyBalance global_energy_;  // on ranks: the shares added up (energy())
  EnergySplit global_split_;
  double internal_energy_ = 0.0;  // J, sum m e at t_n: elements, particles and bars
};

extern template class Solver<2>;
extern template class Solver<3>;

}  // namespace camouflet
