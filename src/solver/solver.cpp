#include "solver/solver.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "fem/parallel.hpp"
#include "solver/domain_box.hpp"

namespace camouflet {

namespace {

// Element centre (m, padded to 3 components) for EquationOfState::place.
template <int D>
std::array<double, 3> centre(const std::vector<double>& x, const std::int64_t* conn) {
  constexpr int N = FemElements<D>::nodes;
  std::array<double, 3> c{};
  for (int a = 0; a < N; ++a)
    for (int i = 0; i < D; ++i) c[static_cast<std::size_t>(i)] += x[conn[a] * D + i] / N;
  return c;
}

}  // namespace

template <int D>
Solver<D>::Solver(const Model& model) : model_(model), mode_(model.run.mode) {
  const FemMesh& mesh = model.mesh;
  const bool has_mesh = mesh.node_count() > 0;
  if ((has_mesh && mesh.dimension != D) || model.dimension() != D)
    throw InputError(model.run.where, fmt::format("mesh dimension {} does not match geometry mode '{}'",
                                                  mesh.dimension, to_string(model.run.mode)));
  if (has_mesh && mesh.nodes_per_element != FemElements<D>::nodes)
    throw InputError(model.run.where, fmt::format("{}-D meshes need {}-node elements, got {}", D,
                                                  FemElements<D>::nodes, mesh.nodes_per_element));
  const std::size_t nn = mesh.node_count();
  position_ = mesh.coordinates;
  for (auto* v : {&velocity_, &velocity_old_, &acceleration_, &force_, &displacement_})
    v->assign(nn * D, 0.0);
  node_mass_.assign(nn, 0.0);

  try {
    elements_ = FemElements<D>(mesh, mode_, position_);
    elements_.set_area_weighted_momentum(mode_ == GeometryMode::axisymmetric &&
                                         model.run.area_weighted_momentum);
  } catch (const InputError& e) {  // name the case file the mesh came from
    throw InputError(SourceLocation{model.case_file, 0, 0, "mesh"}, e.message());
  }
  const std::size_t ne = elements_.size();

  // Elements -> material batches.
  batches_.resize(model.materials.size());
  std::vector<std::size_t> count(model.materials.size(), 0);
  for (std::size_t e = 0; e < ne; ++e) {
    const int part_index = mesh.element_part[e];
    if (part_index < 0 || static_cast<std::size_t>(part_index) >= model.parts.size())
      throw InputError(model.run.where, fmt::format("element {} belongs to no part", e + 1));
    const Part& part = model.parts[static_cast<std::size_t>(part_index)];
    if (part.material < 0 || static_cast<std::size_t>(part.material) >= model.materials.size())
      throw InputError(part.where, fmt::format("part '{}' has no material", part.name));
    elements_.material[e] = part.material;
    elements_.point[e] = count[static_cast<std::size_t>(part.material)]++;
  }
  std::vector<std::vector<std::array<double, 3>>> centres(model.materials.size());
  for (std::size_t e = 0; e < ne; ++e)
    centres[static_cast<std::size_t>(elements_.material[e])].push_back(
        centre<D>(position_, &elements_.connectivity[e * FemElements<D>::nodes]));
  for (std::size_t m = 0; m < batches_.size(); ++m) {
    const Material& mat = *model.materials[m].material;
    mat.setup(batches_[m], count[m]);
    mat.eos().place(batches_[m], centres[m], model.detonations);
  }
  set_geostatic_state();  // before the masses: they follow from the density that carries the overburden

  // Masses and initial velocities (mass-weighted where parts meet).
  std::vector<double> momentum(nn * D, 0.0);
  for (std::size_t e = 0; e < ne; ++e) {
    const MaterialPoints& pts = batches_[static_cast<std::size_t>(elements_.material[e])];
    const double rho0 = pts.density[elements_.point[e]];
    elements_.mass[e] = rho0 * elements_.volume[e];
    elements_.density[e] = rho0;
    const Part& part = model.parts[static_cast<std::size_t>(mesh.element_part[e])];
    const double m_node = elements_.mass[e] / FemElements<D>::nodes;
    for (int a = 0; a < FemElements<D>::nodes; ++a) {
      const std::int64_t n = elements_.connectivity[e * FemElements<D>::nodes + static_cast<std::size_t>(a)];
      node_mass_[static_cast<std::size_t>(n)] += m_node;
      for (int i = 0; i < D; ++i)
        momentum[static_cast<std::size_t>(n * D + i)] +=
            m_node * part.initial_velocity[static_cast<std::size_t>(i)];
    }
  }
  for (std::size_t n = 0; n < nn; ++n)
    for (int i = 0; i < D; ++i)
      velocity_[n * D + static_cast<std::size_t>(i)] =
          node_mass_[n] > 0.0 ? momentum[n * D + static_cast<std::size_t>(i)] / node_mass_[n] : 0.0;

  setup_reinforcement();  // embedded bars add their mass at their hosts' velocity

  hourglass_ = {model.run.hourglass, model.run.hourglass_coefficient};
  // Parts with their own hourglass control: every element gets its part's.
  if (std::any_of(model.parts.begin(), model.parts.end(),
                  [](const Part& p) { return p.hourglass.has_value(); })) {
    std::vector<HourglassControl> per_element(ne);
    for (std::size_t e = 0; e < ne; ++e)
      per_element[e] = model.hourglass_of(static_cast<std::size_t>(mesh.element_part[e]));
    elements_.set_hourglass(per_element);
  }
  // The viscous form's work is charged from its nodal forces; the stiffness
  // form holds its energy as a state (1/2 k q^2), like the internal energy.
  if (elements_.any_viscous_hourglass(hourglass_)) {
    hourglass_force_.assign(nn * D, 0.0);
    hourglass_force_previous_.assign(nn * D, 0.0);
  }
  viscosity_ = {model.run.viscosity_quadratic, model.run.viscosity_linear, model.run.viscosity_along_acceleration};
  boundaries_ = BoundaryConditions<D>(model);
  boundaries_.constrain(velocity_.data(), 0.0);
  transmitting_ = TransmittingBoundary<D>(model, elements_);

  // SPH particles: same materials, own batches (sph/sph_system.hpp); symmetry
  // boundaries on axis-aligned planes reflect particles too.
  if (model.particles.count() > 0) {
    const sph::SphOptions& options = model.sph;
    if (mode_ == GeometryMode::axisymmetric && !options.volume_form)
      fmt::print(stderr,
                 "warning: [sph] volume_form = false in r-z: the particle columns next to the axis feel a "
                 "stress divergence up to ~1.4x too large (mirror images with |r| ring weights; "
                 "docs/theory/sph.md, \"The first columns\")\n");
    particles_ = std::make_unique<sph::SphSystem<D>>(model, options, sph::symmetry_mirror_planes(model));
    if (!model.joins.empty()) {
      // The same planes as the particles' mirrors, axis first (SphSystem's order).
      std::vector<sph::MirrorPlane> planes = sph::symmetry_mirror_planes(model);
      if (mode_ == GeometryMode::axisymmetric)
        planes.insert(planes.begin(), sph::MirrorPlane{0, 0.0, sph::PlaneKind::axis});
      join_ = std::make_unique<SphFemJoin<D>>(model, elements_, position_.data(), velocity_.data(),
                                              *particles_, std::move(planes));
    }
    particles_->compute_accelerations();
  }
  contact_ = SlidingContact<D>(model);

  // The first step votes with the initial velocities like every later one
  // (the kinematics that measure |v| have not run yet).
  elements_.set_speeds(velocity_.data());
  gather_element_state();
  hold_transmitting_boundaries();  // needs the initial stresses gathered above
  start_energy_and_step();
}

template <int D>
void Solver<D>::set_initial_velocity(const std::vector<double>& v) {
  if (cycle_ != 0 || v.size() != velocity_.size())
    throw std::logic_error("set_initial_velocity: before the first step, one value per node and component");
  velocity_ = v;
  boundaries_.constrain(velocity_.data(), 0.0);
  elements_.set_speeds(velocity_.data());
  nodes_checked_cycle_ = -1;
  start_energy_and_step();
}

template <int D>
void Solver<D>::start_energy_and_step() {
  choose_time_step();
  const Model& model = model_;
  if (model.run.initial_dt > 0.0) {
    dt_next_ = std::min(model.run.initial_dt, model.run.max_dt);
    limit_.dt = dt_next_;
    limit_.reason = "initial_dt";
  }
  const std::size_t nn = node_mass_.size();
  double kinetic = 0.0;
  for (std::size_t n = 0; n < nn; ++n)
    for (int i = 0; i < D; ++i)
      kinetic += 0.5 * node_mass_[n] * velocity_[n * D + static_cast<std::size_t>(i)] *
                 velocity_[n * D + static_cast<std::size_t>(i)];
  if (particles_) kinetic += particles_->kinetic_energy();
  energy_.kinetic = kinetic;
  energy_.internal = internal_energy_;
  // The stiffness-form hourglass energy is nought at t = 0 unless a relaxation stored some.
  energy_.initial_total = kinetic + internal_energy_ + hourglass_stored_;
}

template <int D>
void Solver<D>::limit_next_step(double dt_max) {
  if (dt_max > 0.0 && dt_max < dt_next_) dt_next_ = dt_max;
}

template <int D>
void Solver<D>::step() {
  try {
    // The state at t_n: a NaN is named before forces spread it. FEM-only
    // models skip the nodes that the previous step's node pass checked.
    if (particles_ || !bars_.empty() || nodes_checked_cycle_ != cycle_) check_nodes_and_particles();
    // Forces at t_n.
    add_element_forces();          // FEM: face loads, element stresses and hourglass control (fem/)
    add_particle_forces();         // SPH: the particle sums, accelerations (sph/)
    add_coupling_forces();         // the join's reactions and the sliding contact (coupling/)
    add_gravity();                 // m g on nodes and particles (gravity.cpp)
    add_static_boundary_forces();  // the transmitting boundaries' static hold (gravity.cpp)
    add_bar_forces();              // embedded reinforcement bars onto their host nodes
    // Velocities at t_(n+1/2).
    advance_velocities();    // FEM: a = F / m, v(n+1/2) by the central difference
    kick_particles();        // SPH: v(n+1/2), the pair heating
    constrain_velocities();  // dashpots, fixed, prescribed, symmetry, axis; the join settles
    // Energies at t_n and positions at t_(n+1).
    drift_particles();                 // SPH: centred kinetic energy, x(n+1)
    drift_nodes_and_account_energy();  // FEM: x(n+1) = x(n) + v(n+1/2) dt; the energy balance at t_n
    advance_clock();                   // t_(n+1), the cycle count, dt(n+1/2)
    check_drifted_nodes();             // finite and inside the domain box (found by the drift's pass)
    check_particles();                 // the particles' half of check_nodes_and_particles (solver_checks.cpp)
    check_axis_crossings();            // r-z: a node across the axis is reported (a warning)
    // Kinematics and material state at t_(n+1).
    particle_kinematics();   // SPH: eta, rho, h, D, W and their material update (sph/)
    element_kinematics();    // FEM: V, rho at t_(n+1); D, W, q at mid-step
    update_materials();      // FEM: EOS + strength + damage, one call per material batch
    update_bars();           // embedded bars: uniaxial-stress material update
    erode_elements();        // elements past their material's erosion threshold (the join follows)
    gather_element_state();  // sigma = s - p I, wave speeds, internal energy, dt vote
    choose_time_step();      // dt(n+3/2) = CFL min l / (c + |v|), growth limited
  } catch (NumericalError& error) {
    if (error.cycle() < 0) error.set_context(cycle_, time_, describe(error.kind(), error.id()));
    throw;
  }
}

template <int D>
void Solver<D>::fail(NumericalError error) const {
  error.set_context(cycle_, time_, describe(error.kind(), error.id()));
  throw error;
}

template <int D>
void Solver<D>::add_element_forces() {
  // The node passes of the previous step zeroed both arrays as they read
  // them for the last time (node_forces_zeroed_); otherwise zero them here.
  if (!node_forces_zeroed_) std::fill(force_.begin(), force_.end(), 0.0);
  const double* ring_factor = nullptr;
  if (elements_.area_weighted_momentum()) {
    elements_.update_ring_factors(position_.data());
    ring_factor = elements_.ring_factors().data();
  }
  boundaries_.add_loads(position_.data(), time_, force_.data(), ring_factor);
  double* f_hourglass = nullptr;
  if (!hourglass_force_.empty()) {
    hourglass_force_.swap(hourglass_force_previous_);
    if (!node_forces_zeroed_) std::fill(hourglass_force_.begin(), hourglass_force_.end(), 0.0);
    f_hourglass = hourglass_force_.data();
  }
  node_forces_zeroed_ = false;
  hourglass_stored_ = elements_.add_internal_forces(position_.data(), velocity_.data(), force_.data(),
                                                    f_hourglass, hourglass_, dt_);
}

template <int D>
void Solver<D>::advance_velocities() {
  // Leapfrog with variable steps: the impulse at t_n spans the mean of the two half steps.
  const double dt_mean = centred_step();
  const std::int64_t nn = static_cast<std::int64_t>(node_mass_.size());
#pragma omp parallel for schedule(static) if (nn > parallel_threshold_nodes)
  for (std::int64_t n = 0; n < nn; ++n) {
    const double inv_m =
        node_mass_[static_cast<std::size_t>(n)] > 0.0 ? 1.0 / node_mass_[static_cast<std::size_t>(n)] : 0.0;
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      const double a = force_[k] * inv_m;
      force_[k] = 0.0;  // its last use: zeroed for the next add_element_forces
      acceleration_[k] = a;
      velocity_old_[k] = velocity_[k];
      velocity_[k] += a * dt_mean;
    }
  }
}

template <int D>
void Solver<D>::constrain_velocities() {
  const double dt_mean = centred_step();
  // Transmitting boundaries first: centred dashpots on v(n+1/2) (boundary/transmitting_boundary.hpp).
  if (relaxing_) hold_charges_still();
  if (!transmitting_.empty() && relaxing_) {
    transmitting_.hold_still(velocity_.data());
  } else if (!transmitting_.empty()) {
    const double damping_work = transmitting_.damp(position_.data(), velocity_old_.data(), velocity_.data(),
                                                   node_mass_.data(), elements_, batches_, dt_mean);
    energy_.boundary_work += damping_work;
    split_.transmitting += damping_work;
  }
  const double reaction_work = boundaries_.constrain(velocity_.data(), velocity_old_.data(),
                                                     node_mass_.data(), time_ + 0.5 * dt_next_, dt_, dt_mean);
  const double constraint_work = reaction_work + boundaries_.load_work(velocity_old_.data(), dt_);
  energy_.boundary_work += constraint_work;
  split_.constraints += constraint_work;
  if (join_) {  // the elements' half of the viscous heating, and the join work (coupling/sph_fem_join.hpp)
    const double work = join_->settle(*particles_, dt_mean, batches_);
    join_power_ = dt_mean > 0.0 ? work / dt_mean : 0.0;
    split_.join_face += join_->face_offset_work();
  }
  energy_.boundary_work += (join_power_ + contact_power_) * dt_mean;  // join and contact work (coupling/)
  split_.join += join_power_ * dt_mean;
  split_.contact += contact_power_ * dt_mean;
}

template <int D>
void Solver<D>::drift_nodes_and_account_energy() {
  // Kinetic energy at t_n in the form the central difference conserves:
  // (1/2) m (v_n^2 - a^2 dt-^2 / 4) with v_n = v(n-1/2) + a dt- / 2 and a the
  // applied (constrained) acceleration; for equal steps it is (1/2) m
  // v(n-1/2) . v(n+1/2), and a short next step (landing on the end time)
  // does not disturb it. The
  // viscous hourglass work from t_(n-1) to t_n is the trapezoid of its forces
  // against v(n-1/2), the same centring as the internal energy's.
  // The same pass moves each node (x(n+1) = x(n) + v(n+1/2) dt) and tests it
  // (check_nodes_and_particles' test; check_drifted_nodes reports the first
  // failed one once the clock has moved on): the node arrays are read once. The
  // energy sums keep their grouping (one thread's share per contiguous block
  // of nodes, the threshold of the former energy loop).
  const std::int64_t nn = static_cast<std::int64_t>(node_mass_.size());
  const bool hourglass = !hourglass_force_.empty();
  const double dt_minus = dt_, dt_mean = centred_step();
  const double dt = dt_next_;
  double kinetic = 0.0, hourglass_power = 0.0;
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
#pragma omp parallel for schedule(static) reduction(+ : kinetic, hourglass_power) reduction(min : bad) if (nn > parallel_threshold_nodes)
  for (std::int64_t n = 0; n < nn; ++n) {
    double vv = 0.0, fv = 0.0;
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      const double a = (velocity_[k] - velocity_old_[k]) / dt_mean;
      const double v_n = velocity_old_[k] + 0.5 * a * dt_minus;
      vv += v_n * v_n - 0.25 * a * a * dt_minus * dt_minus;
      if (hourglass) {
        fv += 0.5 * (hourglass_force_[k] + hourglass_force_previous_[k]) * velocity_old_[k];
        hourglass_force_previous_[k] = 0.0;  // its last use: the next add_element_forces fills it
      }
    }
    kinetic += 0.5 * node_mass_[static_cast<std::size_t>(n)] * vv;
    hourglass_power -= fv;
    bool ok = true;
    for (int i = 0; i < D; ++i) {
      const std::size_t k = static_cast<std::size_t>(n * D + i);
      const double dx = velocity_[k] * dt;
      position_[k] += dx;
      displacement_[k] += dx;
      ok = ok && std::isfinite(velocity_[k]);
    }
    if (!ok || first_outside_domain<D>(model_.run, &position_[static_cast<std::size_t>(n * D)]) >= 0)
      bad = std::min(bad, n);
  }
  kinetic += split_.sph_kinetic;
  EnergyBalance& e = energy_;
  e.kinetic = kinetic;
  e.internal = internal_energy_;
  hourglass_dissipated_ += hourglass_power * dt_minus;
  e.hourglass = hourglass_dissipated_ + hourglass_stored_;
  const double total = e.kinetic + e.internal + e.hourglass + e.eroded;
  const double scale = std::max(e.initial_total + std::abs(e.boundary_work), std::abs(total));
  e.relative_error = scale > 0.0 ? std::abs(total - e.initial_total - e.boundary_work) / scale : 0.0;

  drifted_bad_node_ = bad == std::numeric_limits<std::int64_t>::max() ? -1 : bad;
  node_forces_zeroed_ = true;  // force_ in advance_velocities, hourglass_force_previous_ above
}

template <int D>
void Solver<D>::advance_clock() {
  dt_ = dt_next_;
  time_ += dt_;
  ++cycle_;
}

template <int D>
void Solver<D>::check_drifted_nodes() {
  if (drifted_bad_node_ >= 0) fail_node(drifted_bad_node_);
  nodes_checked_cycle_ = cycle_;
}

template <int D>
void Solver<D>::element_kinematics() {
  const KinematicsResult r =
      elements_.kinematics(position_.data(), velocity_.data(), velocity_old_.data(), dt_, viscosity_, batches_);
  energy_.viscous += r.viscous_work;
  if (r.bad_element >= 0)
    fail(NumericalError(
        EntityKind::element, r.bad_element + 1, "volume",
        fmt::format("volume {:.6g} m^3 is not positive (element inverted or collapsed)", r.bad_volume)));
  if (r.tangled_element >= 0) {
    // Not fatal: the buried-structure cases tangle an element now and then
    // (docs/reliability.md); a run must not carry one silently. Each newly tangled element is
    // reported, at most 20 lines.
    const std::int64_t id = r.tangled_element + 1;
    if (first_tangled_cycle_ < 0) first_tangled_element_ = id, first_tangled_cycle_ = cycle_;
    if (id != last_tangled_element_ && tangled_reports_ < 20) {
      ++tangled_reports_;
      fmt::print(stderr,
                 "warning: element {} ({}) at cycle {}, time {:.6e} s: {} of its 4 corner Jacobians are "
                 "negative: its edges cross (element tangled, a bow-tie; its area is still positive){}\n",
                 id, describe(EntityKind::element, id), cycle_, time_, r.tangled_corners,
                 tangled_reports_ == 20 ? " (no more such warnings)" : "");
    }
    last_tangled_element_ = id;
  }
}

template <int D>
void Solver<D>::update_materials() {
  const MaterialContext ctx{dt_, time_};
  for (std::size_t m = 0; m < batches_.size(); ++m)
    if (batches_[m].size() > 0) model_.materials[m].material->update(batches_[m], ctx);
}

template <int D>
void Solver<D>::gather_element_state() {
  const std::int64_t ne = static_cast<std::int64_t>(elements_.size());
  double internal = 0.0;
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
  // The same static split and per-thread sums as a parallel for; each thread
  // keeps the batch of its previous element, so the batch is looked up only
  // where the material changes.
#pragma omp parallel reduction(+ : internal) reduction(min : bad) if (ne > parallel_threshold)
  {
    int batch_index = -1;
    const MaterialPoints* pts = nullptr;
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < ne; ++k) {
      const std::size_t e = static_cast<std::size_t>(k);
      if (elements_.eroded[e]) {
        elements_.stress[e] = SymTensor{};  // its energy went to EnergyBalance::eroded
        continue;
      }
      if (elements_.material[e] != batch_index) {
        batch_index = elements_.material[e];
        pts = &batches_[static_cast<std::size_t>(batch_index)];
      }
      const std::size_t p = elements_.point[e];
      const double pressure = pts->pressure[p];
      SymTensor s = pts->deviator[p];
      s.xx -= pressure;
      s.yy -= pressure;
      s.zz -= pressure;
      elements_.stress[e] = s;
      elements_.wave_speed[e] = pts->wave_speed(p);
      elements_.stable_wave_speed[e] = pts->stable_wave_speed(p);
      const double energy = elements_.mass[e] * pts->specific_energy[p];
      internal += energy;
      if (!std::isfinite(s.xx + s.yy + s.zz + s.xy + s.yz + s.zx) ||
          !std::isfinite(elements_.wave_speed[e]) || !std::isfinite(energy))
        bad = std::min(bad, k);
    }
  }
  split_.sph_internal = particles_ ? particles_->internal_energy() : 0.0;
  split_.bar_internal = bars_.internal_energy();
  internal_energy_ = internal + split_.sph_internal + split_.bar_internal;
  if (bad != std::numeric_limits<std::int64_t>::max()) {
    const std::size_t e = static_cast<std::size_t>(bad);
    const MaterialPoints& pts = batches_[static_cast<std::size_t>(elements_.material[e])];
    const std::size_t p = elements_.point[e];
    fail(NumericalError(
        EntityKind::element, bad + 1, "stress",
        fmt::format("non-finite state: pressure {} Pa, specific energy {} J/kg, sound speed {} m/s",
                    pts.pressure[p], pts.specific_energy[p], pts.sound_speed[p])));
  }
}

template <int D>
void Solver<D>::choose_time_step() {
  // Smallest l / (c + |v|) over the elements; ties go to the lowest index so
  // the limiting element does not depend on the thread count.
  const std::int64_t ne = static_cast<std::int64_t>(elements_.size());
  double best = std::numeric_limits<double>::infinity();
  std::int64_t best_e = -1;
#pragma omp parallel if (ne > parallel_threshold)
  {
    double local = std::numeric_limits<double>::infinity();
    std::int64_t local_e = -1;
#pragma omp for schedule(static) nowait
    for (std::int64_t k = 0; k < ne; ++k) {
      const std::size_t e = static_cast<std::size_t>(k);
      if (elements_.eroded[e]) continue;
      double t = elements_.length[e] / (elements_.stable_wave_speed[e] + elements_.speed[e]);
      if (!(t >= 0.0)) t = -1.0;  // NaN: this element is reported as the collapse
      if (t < local) {
        local = t;
        local_e = k;
      }
    }
#pragma omp critical
    if (local_e >= 0 && (local < best || (local == best && local_e < best_e))) {
      best = local;
      best_e = local_e;
    }
  }
  const RunControl& run = model_.run;
  double dt = run.cfl * best;
  std::string reason;
  if (best_e >= 0) {
    const auto m = static_cast<std::size_t>(elements_.material[static_cast<std::size_t>(best_e)]);
    reason = fmt::format("element {} ({}): l/(c+|v|)", best_e + 1, model_.materials[m].name);
  }
  if (particles_) {
    const TimeStepLimit vote = particles_->stable_time_step();
    if (run.cfl * vote.dt < dt) {
      dt = run.cfl * vote.dt;
      reason = vote.reason;
    }
  }
  if (!bars_.empty()) {
    std::size_t s = 0;
    const double t = bars_.stable_time_step(position_.data(), s);
    if (run.cfl * t < dt || !(t >= 0.0)) {
      dt = run.cfl * t;
      reason = fmt::format("bar '{}' segment {}: L/c", bars_.set_name(s), s + 1);
    }
  }
  // Hold the step while the limit sits within 2 % above it: a step that
  // follows |v| every cycle pumps energy in or out of a vibration (the
  // central difference conserves energy only between changes of dt).
  if (dt_ > 0.0 && dt >= dt_ && dt < 1.02 * dt_ && dt_ <= run.max_dt) dt = dt_;
  if (dt_ > 0.0 && dt > run.dt_growth * dt_) {
    dt = run.dt_growth * dt_;
    reason = "growth limit dt_growth";
  }
  if (dt > run.max_dt) {
    dt = run.max_dt;
    reason = "max_dt";
  }
  if (!(dt > run.min_dt) || !std::isfinite(dt)) {
    if (best_e >= 0 && (!particles_ || reason.rfind("element", 0) == 0))
      fail(NumericalError(
          EntityKind::element, best_e + 1, "time step",
          fmt::format("dt {:.6g} s is below min_dt {:.6g} s (l = {:.6g} m, c = {:.6g} m/s, |v| = {:.6g} m/s)",
                      dt, run.min_dt, elements_.length[static_cast<std::size_t>(best_e)],
                      elements_.stable_wave_speed[static_cast<std::size_t>(best_e)],
                      elements_.speed[static_cast<std::size_t>(best_e)])));
    fail(NumericalError(EntityKind::model, 0, "time step", fmt::format("dt {:.6g} s is not usable", dt)));
  }
  dt_next_ = dt;
  limit_ = {dt, reason};
}

template <int D>
FieldSnapshot Solver<D>::snapshot() const {
  const std::size_t ne = elements_.size();
  element_pressure_.resize(ne);
  element_plastic_strain_.resize(ne);
  element_damage_.resize(ne);
  element_temperature_.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    const MaterialPoints& pts = batches_[static_cast<std::size_t>(elements_.material[e])];
    const std::size_t p = elements_.point[e];
    element_pressure_[e] = pts.pressure[p];
    element_plastic_strain_[e] = pts.plastic_strain[p];
    element_damage_[e] = pts.damage[p];
    element_temperature_[e] = pts.temperature[p];
  }
  FieldSnapshot s;
  s.dimension = D;
  s.mode = mode_;
  s.time = time_;
  s.cycle = cycle_;
  s.node_position = position_;
  s.node_displacement = displacement_;
  s.node_velocity = velocity_;
  s.node_acceleration = acceleration_;
  s.nodes_per_element = FemElements<D>::nodes;
  s.connectivity = elements_.connectivity;
  s.element_density = elements_.density;
  s.element_pressure = element_pressure_;
  s.element_stress = elements_.stress;
  s.element_plastic_strain = element_plastic_strain_;
  s.element_damage = element_damage_;
  s.element_temperature = element_temperature_;
  s.element_material = elements_.material;
  if (particles_) particles_->fill_snapshot(s);
  return s;
}

template class Solver<2>;
template class Solver<3>;

}  // namespace camouflet
