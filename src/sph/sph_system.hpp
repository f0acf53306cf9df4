#pragma once
// The SPH package: particles, their material batches and the stages of the
// explicit cycle (architecture.md) that the solver calls for particles.
//
// Formulation (Monaghan 1992, 2005; Libersky & Petschek 1991/1993 for strength),
// written in "planar" form so that plane strain, axisymmetry and 3-D share one
// set of sums. Each particle carries its mass m (axisymmetric: the mass of the
// ring), its planar density eta = w rho with w = 2 pi r in r-z and w = 1
// otherwise, and the stress sigma from the shared material update.
//
//   continuity   d eta_i/dt = eta_i sum_j V_j (v_i - v_j) . grad_i W_ij        V_j = m_j / eta_j
//   vel. grad.   L_i = -sum_j V_j (v_i - v_j) (x) grad_i W_ij     [+ hoop L_tt = v_r / r]
//   momentum     dv_i/dt = sum_j m_j (S_i / eta_j + S_j / eta_i - Pi_ij I + f_ij^n (R_i + R_j)) . grad_i W_ij
//                          [- sigma_tt,i / (rho_i r_i) e_r]                  S = w sigma / eta = sigma / rho
// This is the "volume" form (Colagrossi & Landrini 2003, JCP 191, eqs. 9-10;
// Hu & Adams 2006): it stays smooth across density jumps (explosive/soil,
// Sod's 8:1 contact with equal spacing), where the classic "density" form
// sum m_j (sigma_i/rho_i^2 + sigma_j/rho_j^2) (Monaghan 1992, eq. 3.5;
// Libersky & Petschek 1991) lets a light particle next to heavy ones run away.
// Both are pairwise antisymmetric (momentum-conserving) and each is
// energy-conjugate to its own continuity equation; SphOptions::volume_form
// = false selects the classic pair (continuity weight m_j / eta_i instead).
// In every pair weight eta_j stands for quadrature_density(j) (below): eta_j,
// but no lower than m_j W(0, h_j), its own term of the summation density.
//   energy       Material::update from D and the density change (p dv is then
//                exactly the work of the pressure part of the momentum sum),
//                plus the viscous heating 1/2 sum_j m_j Pi_ij (v_i - v_j) . grad_i W_ij.
//
// In r-z this is the axisymmetric SPH of Brookshaw (2003, ANZIAM J. 44 C114)
// and Garcia-Senz, Relano, Cabezon & Bravo (2009, MNRAS 392, 346; "AxisSPH",
// Relano 2012): the 2-D kernel sums act on eta = 2 pi r rho, and the hoop
// terms come from writing the r-z divergence of the stress as
// div(r sigma) - sigma_tt e_r. The artificial stress has the hoop term of its own ring sum
// (and [sph] viscosity_hoop one for the viscosity), sph_forces.cpp. [sph] smoothed_hoop writes
// the stress's hoop term and the hoop rate with the ring sum's own kernel weights, energy
// conjugates of each other, and lets rho follow that rate (sph_options.hpp). The axis is a mirror
// plane (boundary/mirror_planes.hpp).
//
// Stages of one cycle (the solver, or step() for pure-SPH runs, calls them in order):
//   compute_accelerations()  forces at x(n) with sigma(n)       -> a(n)
//   advance(dt)              v(n+1/2) = v(n-1/2) + a dt; x(n+1) = x(n) + v dt
//   update_state(dt, t)      rates at x(n+1/2), v(n+1/2), pair weights m_j / eta_j(n+1/2)
//                            -> eta, rho, h at n+1, L; Material::update -> sigma(n+1)
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/state_visitor.hpp"
#include "core/sym_tensor.hpp"
#include "core/sym_tensor_vec.hpp"
#include "core/vec.hpp"
#include "materials/material.hpp"
#include "model/model.hpp"
#include "model/snapshot.hpp"
#include "model/run_summary.hpp"
#include "sph/active_pairs.hpp"
#include "sph/kernel.hpp"
#include "boundary/mirror_planes.hpp"
#include "sph/neighbour_search.hpp"
#include "sph/pair_point.hpp"
#include "sph/sph_options.hpp"
#include "sph/thread_sums.hpp"

namespace camouflet::sph {

// Structure of arrays over particles (real ones first; the first `real` entries
// of the point arrays are particles, the rest ghosts).
template <int D>
struct ParticleArrays {
  std::size_t real = 0;
  // --- points (particles, then ghosts) ---
  std::vector<Vec<D>> position;          // m
  std::vector<Vec<D>> velocity;          // m/s, v(n-1/2) before advance(), v(n+1/2) after
  std::vector<double> mass;              // kg (axisymmetric: ring mass)
  std::vector<double> planar_density;    // eta = w rho: kg/m^3 (3-D, plane), kg/m^2 per radian x 2 pi (r-z)
  std::vector<double> smoothing_length;  // m
  std::vector<SymTensor> stress_term;    // S = w sigma / eta (= sigma / rho), m^2/s^2
  std::vector<SymTensor> tensile_term;   // artificial stress R, scaled as sigma / rho^2
  std::vector<double> wave_speed;        // m/s, sqrt(c^2 + 4G/3rho)
  std::vector<double> stable_wave_speed;  // m/s, the same with the stable sound speed (the dt vote's)
  std::vector<SymTensor> correction;     // kernel-gradient correction B = M^-1 (identity when off)
  std::vector<double> viscosity_alpha;   // linear viscosity coefficient (SphOptions::viscosity_switch)
  // --- particles only ---
  // Persistent particle id (0-based index in model.particles): memory order
  // changes when particles are re-sorted by cell (SphOptions::sort_interval);
  // output, gauges and messages use the id.
  std::vector<std::uint32_t> id;
  std::vector<Vec<D>> acceleration;                // m/s^2
  std::vector<Vec<D>> displacement;                // m, from the initial position
  std::vector<double> density;                     // kg/m^3
  std::vector<double> reference_smoothing_length;  // m, h0 = factor x spacing
  std::vector<double> reference_planar_density;
  std::vector<double> spacing;    // m, initial particle spacing (for the artificial-stress dp)
  std::vector<SymTensor> stress;  // Pa, sigma = s - p I (tension positive)
  std::vector<double> pressure;   // Pa
  std::vector<double> plastic_strain;
  std::vector<double> damage;
  std::vector<double> temperature;       // K, copied from the material point like the damage
  std::vector<int> material;             // index into Model::materials
  std::vector<int> part;                 // index into Model::parts
  std::vector<std::uint32_t> slot;       // index in the material's batch
  std::vector<double> heating;           // J/kg, artificial-viscosity heating of the last kick (pending)
  std::vector<double> compression_rate;  // 1/s, largest mu_ij (viscous time-step term)
  std::vector<int> neighbour_count;
  std::vector<SymTensor> strain_rate;  // 1/s
  std::vector<Spin> spin;              // 1/s
};

template <int D>
class SphSystem {
 public:
  // Particles from model.particles (their parts give material and initial
  // velocity; mass = reference density x volume), mirrored in `planes`, in their order (the
  // model's: particle_mirror_planes, boundary/boundaries.hpp; the axis of an r-z model among
  // them). The two-argument form mirrors in the planes of the geometry alone (the axis in r-z).
  SphSystem(const Model& model, const SphOptions& options, std::vector<MirrorPlane> planes);
  SphSystem(const Model& model, const SphOptions& options)
      : SphSystem(model, options, axis_mirror_planes(model.run.mode)) {}

  std::size_t size() const { return p_.real; }
  ParticleArrays<D>& particles() { return p_; }
  const ParticleArrays<D>& particles() const { return p_; }
  GeometryMode mode() const { return mode_; }
  const SphOptions& options() const { return options_; }
  // The planes the particles are mirrored in, in the order their images are made.
  const std::vector<MirrorPlane>& mirror_planes() const { return planes_; }

  // --- stages of the cycle ---
  void compute_accelerations();
  void advance(double dt) {
    kick(dt);
    drift(dt);
  }
  // The two halves of advance() for a driver with variable steps (the solver):
  // kick spans the impulse at t_n (mean of the two half steps), drift the new step.
  void kick(double dt);
  void drift(double dt);
  void update_state(double dt, double time);
  // One whole cycle for pure-SPH runs and tests: advance, update_state, compute_accelerations.
  // Call compute_accelerations() once before the first step.
  void step(double dt, double time_end_of_step);

  // Stable time step h / (c + |v| + 1.2 (alpha c + beta mu_max)) (Monaghan 1992,
  // section 10), the smallest over particles, without the CFL factor; the reason names the particle.
  TimeStepLimit stable_time_step() const;

  // Dynamic relaxation (solver/dynamic_relaxation.cpp): every velocity times `factor` (the
  // damping of one step), and at its end every particle at rest where it stands, its
  // displacement counted from there.
  void scale_velocities(double factor);
  void come_to_rest();
  // Particles of the flagged materials (one entry per Model::materials entry) at rest: their
  // velocities zeroed after the kick, before the drift (held charges in a relaxation).
  void hold_still(const std::vector<char>& held_material);

  double kinetic_energy() const;  // J (axisymmetric: full revolution)
  // Time-centred kinetic energy at t_n, 1/2 m v(n-1/2) . v(n+1/2) (after kick()).
  double centred_kinetic_energy() const;
  double internal_energy() const;  // J
  Vec<D> momentum() const;         // kg m/s

  // Particle fields of a FieldSnapshot, in id order: spans into this object,
  // or, once particles have been re-sorted, into copies gathered by id.
  void fill_snapshot(FieldSnapshot& snapshot) const;
  // Number of re-sorts by cell so far (sort_by_cell()).
  std::int64_t sorts() const { return sorts_; }
  const NeighbourSearch<D>& neighbours() const { return search_; }

  // --- coupling seam (coupling/sph_fem_join.hpp) ---
  // `count` points of another package (FEM elements beside the particles)
  // join the particle sums as neighbours, stored after the mirror ghosts from
  // external_begin() on. `provider` writes their position, velocity, mass,
  // planar density, smoothing length, stress and tensile terms, wave speed and
  // correction whenever the ghosts are refreshed. No force on them is computed
  // here: the coupling returns the reactions of the pair forces.
  using ExternalProvider = std::function<void(ParticleArrays<D>&, std::size_t begin)>;
  void set_external_points(std::size_t count, ExternalProvider provider) {
    external_count_ = count;
    external_provider_ = std::move(provider);
  }
  std::size_t external_begin() const { return external_begin_; }
  std::size_t external_count() const { return external_count_; }
  // Kernel-corrected pair gradient, as used by the momentum sum (public for the coupling).
  Vec<D> corrected_gradient(std::size_t i, std::size_t j, const Vec<D>& grad) const {
    return pair_gradient(i, j, grad);
  }
  // Planar density of point k as the pair sums weigh it (volume m / eta_q in the continuity,
  // velocity gradient, momentum and viscosity): eta itself, but never below m W(0, h), the
  // point's own term of the summation density, so that V_q W(0, h) <= 1: no point fills
  // more than the whole partition of unity at its own position. Inactive while h follows
  // the density (there m W(0, h) = 0.32 eta in 2-D, 0.18 eta in 3-D at h = 1.2 spacings);
  // it binds only particles expanded far past h_max_factor, whose weight in their
  // neighbours' sums would otherwise grow without bound (docs/theory/sph.md, "Ejecta").
  // The particle's own eta, rho and pressure are not limited. Coupling points (FEM): none.
  double quadrature_density(std::size_t k) const {
    if (k >= p_.real + ghosts_.size()) return p_.planar_density[k];
    return std::max(p_.planar_density[k], p_.mass[k] * kernel_.value(0.0, p_.smoothing_length[k]));
  }
  // Particles whose planar density is below that limit after the last update_state().
  std::size_t volume_limited_count() const { return volume_limited_; }
  const Kernel<D>& kernel() const { return kernel_; }
  // Every array and scalar a restart needs (checkpoints; sph_state.cpp).
  void visit_state(StateVisitor& visitor);

 private:
  void prepare_neighbours();
  // Reorders the particle arrays into the cell order of the last neighbour
  // build (real particles only; ghosts and lists are rebuilt next), so that
  // neighbours sit close in memory. Ids, batch slots and v(n-1/2) follow.
  void sort_by_cell();
  template <class T>
  void permute(std::vector<T>& a, const std::vector<std::uint32_t>& order) const;
  void compute_correction();
  // Kernel gradient of the pair: grad_i W_ij, or with the correction the
  // antisymmetric 1/2 (B_i + B_j) grad_i W_ij (so momentum stays conserved).
  Vec<D> pair_gradient(std::size_t i, std::size_t j, const Vec<D>& grad) const {
    if (!options_.kernel_correction) return grad;
    return apply<D>((p_.correction[i] + p_.correction[j]) * 0.5, grad);
  }
  void refresh_ghosts();
  // r-z: books as heat the work of the images' signed ring weights (refresh_ghosts), which
  // the conservative pairing with |r| would not do; after the kick, with its mean velocities.
  void book_axis_image_work(double dt);
  void set_geostatic_state(const Model& model);  // SPH soil parts under gravity, before the masses
  void gather_material_state();
  // The momentum sum (compute_accelerations) over the current lists at x(n),
  // storing per list entry the pair terms kick() books as heat; with
  // write_rates = false only those are stored (kick() after a restart).
  void force_pass(bool write_rates);
  // eta_q, 1/eta_q and the volume m/eta_q of every point (particles, ghosts, coupling points), and
  // their packed records for the SIMD pair loops (pair_point.hpp), in one pass: size_point_factors()
  // outside a parallel region, then fill_point_factors() by every thread of the region that runs
  // the pair loop (an orphaned `omp for`: the pass and the pair loop share one region). Only what
  // the pass's rows and the stages up to the next fill read is written (pair_point.hpp).
  enum class FactorPass { forces, kinematics };
  void size_point_factors();
  void fill_point_factors(FactorPass pass);
  double geometric_weight(const Vec<D>& x) const;  // w = 2 pi |r| (r-z), 1 otherwise
  // r-z, [sph] smoothed_hoop: each particle's and ghost's share beta of the smoothed hoop sums at
  // the present positions, min(1, |r| / (smoothed_hoop_width h)), a ghost its source's, into
  // hoop_share_ (sph_kinematics.cpp).
  void fill_hoop_shares();
  // The point term's weight in the hoop force and rate of a particle: the part of its smoothed
  // weight sum the shares took away, 1 - norm / full (in [0, 1]: every real pair's weight is >= 0).
  static double hoop_point_share(double norm, double full) {
    return full > 0.0 ? std::clamp(1.0 - norm / full, 0.0, 1.0) : 1.0;
  }

  GeometryMode mode_;
  SphOptions options_;
  Kernel<D> kernel_;
  std::vector<MirrorPlane> planes_;
  std::vector<Ghost> ghosts_;
  std::vector<signed char> image_sign_;  // per ghost: -1 across the axis (an odd number of times), else +1
  // -1 for point j an image across the axis with a signed ring weight (refresh_ghosts), else +1.
  double ring_sign(std::size_t j) const {
    const std::size_t n = p_.real;
    return j >= n && j - n < image_sign_.size() && image_sign_[j - n] < 0 ? -1.0 : 1.0;
  }
  // r-z: the hoop terms of the artificial viscosity and stress of each particle (radial
  // acceleration, m/s^2), kept for the booking of their work (book_axis_image_work).
  std::vector<double> pair_hoop_;
  // r-z, [sph] smoothed_hoop: the radial acceleration the axis images give each particle through
  // the smoothed hoop term (m/s^2), for the booking of the images' mismatch.
  std::vector<double> image_hoop_;
  // r-z, [sph] smoothed_hoop: the hoop stress sigma_tt (Pa) of every particle and ghost, a ghost's
  // its source's (force_pass()).
  std::vector<double> hoop_sigma_;
  // r-z, [sph] smoothed_hoop: beta of every particle and ghost (fill_hoop_shares()); a pair's
  // smoothed hoop terms carry min(beta_i, beta_j).
  std::vector<double> hoop_share_;
  NeighbourSearch<D> search_;
  bool correction_current_ = false;
  double skin_ = 0.0;
  double ghost_reach_ = 0.0;
  ParticleArrays<D> p_;
  std::vector<Vec<D>> velocity_old_;  // v(n-1/2), kept by kick() for the centred kinetic energy
  std::vector<std::shared_ptr<const Material>> materials_;   // by Model::materials index
  std::vector<MaterialPoints> batches_;                      // by Model::materials index
  std::vector<std::vector<std::uint32_t>> batch_particles_;  // particle of each slot
  bool force_rebuild_ = false;                               // after a re-sort
  std::int64_t builds_at_sort_ = 0, sorts_ = 0;              // re-sort bookkeeping
  // Per material: the first material with the same EOS type; the artificial
  // conductivity only joins particles of one family (SphOptions::conductivity).
  std::vector<int> eos_family_;
  void conduct_heat(double dt);  // the conductivity's share of kick() (sph_motion.cpp)
  // Copies in id order for fill_snapshot() once the memory order differs.
  struct IdOrderCopy {
    std::vector<Vec<D>> position, displacement, velocity, acceleration;
    std::vector<double> density, pressure, plastic_strain, damage, temperature, smoothing_length, mass;
    std::vector<SymTensor> stress;
    std::vector<int> material, neighbour_count;
  };
  mutable IdOrderCopy id_order_;
  // The pair list the sums run over (active_pairs.hpp), refreshed at the start of each sum.
  ActivePairs<D> active_;
  void refresh_active_pairs() { active_.refresh(search_, p_.position, p_.smoothing_length, p_.real); }
  std::span<const std::uint32_t> active_upper_neighbours(std::size_t i) const { return active_.upper_neighbours(i); }
  // Per upper active entry (j > i; entry e of i at active_.upper_index()[i] + e): Pi_ij grad W - f^n (R_i + R_j) .
  // grad W, the viscous and artificial-stress part of the pair force of the last force_pass() per unit mass
  // product, whose work kick() books as heat without evaluating the kernel again.
  std::vector<Vec<D>> pair_dissipation_;
  // Row blocks of the pair-symmetric loops and their copies of the sums
  // (thread_sums.hpp), rebuilt with each extraction of the active lists.
  RowBlocks row_blocks_;
  std::int64_t row_blocks_extraction_ = -1;  // extraction the blocks belong to
  void prepare_row_blocks();
  struct ForceSum {
    Vec<D> acceleration{};
    double compression_rate = 0.0;
    int count = 0;
    // r-z: sum_j (m_j / |r_j|) (r_j - r_i) f^n dW/dr_i, the artificial stress's hoop weight, and
    // sum_j (m_j / |r_j|) (|r_j| - r_i) Pi_ij dW/dr_i, the artificial viscosity's hoop term
    // (force_pass(), "The hoop terms of the artificial viscosity and stress").
    double tensile_hoop_weight = 0.0;
    double viscous_hoop = 0.0;
    // r-z, [sph] smoothed_hoop: sum_j V_j (r_j - r_i) dW/dr_i min(beta_i, beta_j) sigma_tt,j over
    // every neighbour but coupling points, and the part of it from images across the axis.
    double hoop_stress = 0.0, image_hoop_stress = 0.0;
    double hoop_norm = 0.0;  // the same sum with sigma_tt = 1
    double hoop_full = 0.0;  // and that without the shares beta
  };
  struct KinematicSum {
    double rate = 0.0;    // sum_j weight_j v_ij . grad W
    double L[D][D] = {};  // -sum_j weight_j v_ij (x) grad W
    double hoop = 0.0;    // r-z, [sph] smoothed_hoop: sum_j V_j (r_j - r_i) dW/dr_i min(beta_i, beta_j) v_r,j
    double hoop_norm = 0.0;  // the same sum with v_r = 1
    double hoop_full = 0.0;  // and that without the shares beta
  };
  BlockSums<ForceSum> force_sums_;
  BlockSums<KinematicSum> kinematic_sums_;
  // The pair loops on SIMD lanes (pair_lanes.cpp; without the kernel
  // correction): row i of force_pass() and of update_state()'s kinematics,
  // adding to own (the copy of the sums of the row's block), from the packed records.
  void force_row_lanes(std::size_t i, ForceSum* own);
  void kinematics_row_lanes(std::size_t i, KinematicSum* own);
  // The stages of update_state() (sph_kinematics.cpp): x and eta to mid-step; row i's
  // kinematic sums with the kernel correction (scalar); row i's end of the step from its
  // summed rates (strain rate, spin, viscosity switch, eta, h, x(n+1), its material point's
  // inputs), false where eta fell below the particle's own kernel term; the material update.
  void predict_mid_step(double dt);
  void corrected_kinematics_row(std::size_t i, KinematicSum* own);
  bool end_step_of_row(std::size_t i, const KinematicSum& total, double dt);
  void update_material_batches(const MaterialContext& ctx);
  BlockSums<double> heat_sums_;
  struct alignas(32) HeatPoint {  // what kick()'s heating loop reads of a neighbour
    Vec<D> velocity_sum;          // m/s, v(n-1/2) + v(n+1/2)
    double mass;                  // kg
  };
  std::vector<HeatPoint> heat_points_;
  std::vector<Vec<D>> scratch_x_;    // update_state(): x(n+1) while the rates use x(n+1/2)
  std::vector<double> scratch_eta_;  // update_state(): eta(n) while the pair weights use eta(n+1/2)
  bool pair_dissipation_current_ = false;
  std::int64_t pair_dissipation_extraction_ = -1;  // extraction the stored terms belong to
  PointFactors<D> factors_;  // per point, the pair sums' scratch (pair_point.hpp), by fill_point_factors()
  double tensile_shape_inverse_ = 1.0;             // 1 / w(1 / smoothing_factor): W(dp, h) = C w / h^D
  int tensile_power_integer_ = 0;                  // artificial_stress_power when a small integer, else 0
  std::size_t volume_limited_ = 0;                 // volume_limited_count()
  std::size_t external_begin_ = 0, external_count_ = 0;  // coupling seam
  ExternalProvider external_provider_;
};

}  // namespace camouflet::sph
