// The particle kinematics of one cycle, which feed the shared material
// update: the kernel-gradient correction, continuity density, velocity
// gradient and smoothing length.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/sym_tensor_vec.hpp"
#include "sph/pair_terms.hpp"
#include "sph/sph_system.hpp"

namespace camouflet::sph {

namespace {

template <int D>
bool invert(const double m[D][D], double inv[D][D]) {
  if constexpr (D == 2) {
    const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if (!(std::abs(det) > 1e-12)) return false;
    inv[0][0] = m[1][1] / det;
    inv[0][1] = -m[0][1] / det;
    inv[1][0] = -m[1][0] / det;
    inv[1][1] = m[0][0] / det;
  } else {
    const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    if (!(std::abs(det) > 1e-12)) return false;
    inv[0][0] = c00 / det;
    inv[1][0] = c01 / det;
    inv[2][0] = c02 / det;
    inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
    inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
    inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
    inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
    inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
    inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  }
  return true;
}

}  // namespace

template <int D>
void SphSystem<D>::compute_correction() {
  // B_i = M_i^-1, M_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij (Randles & Libersky
  // 1996, eq. 20; Bonet & Lok 1999): symmetric for a radial kernel. Where M is
  // near singular (a particle with too few neighbours) B = I.
  const std::size_t n = p_.real;
  prepare_neighbours();
  const auto& x = p_.position;
  const auto& h = p_.smoothing_length;
#pragma omp parallel for schedule(dynamic, 128)
  for (std::size_t i = 0; i < n; ++i) {
    double moment[D][D] = {};
    for (const std::uint32_t j : search_.neighbours(i)) {
      const Vec<D> dx = x[i] - x[j];
      const double r2 = dot(dx, dx);
      const double hij = pair_smoothing_length(h[i], h[j]);
      if (r2 >= support_factor * support_factor * hij * hij) continue;
      const double f = kernel_.gradient_factor(std::sqrt(r2), hij) * p_.mass[j] / quadrature_density(j);
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) moment[a][b] -= f * dx[a] * dx[b];
    }
    double inv[D][D];
    SymTensor b = SymTensor::identity();
    double det = 1.0;
    if constexpr (D == 2) {
      det = moment[0][0] * moment[1][1] - moment[0][1] * moment[1][0];
    } else {
      det = moment[0][0] * (moment[1][1] * moment[2][2] - moment[1][2] * moment[2][1]) -
            moment[0][1] * (moment[1][0] * moment[2][2] - moment[1][2] * moment[2][0]) +
            moment[0][2] * (moment[1][0] * moment[2][1] - moment[1][1] * moment[2][0]);
    }
    if (std::abs(det) > 0.05 && invert<D>(moment, inv)) {
      b.xx = inv[0][0];
      b.yy = inv[1][1];
      b.xy = 0.5 * (inv[0][1] + inv[1][0]);
      if constexpr (D == 3) {
        b.zz = inv[2][2];
        b.yz = 0.5 * (inv[1][2] + inv[2][1]);
        b.zx = 0.5 * (inv[2][0] + inv[0][2]);
      }
    }
    p_.correction[i] = b;
  }
  refresh_ghosts();
  correction_current_ = true;
}

template <int D>
void SphSystem<D>::fill_hoop_shares() {
  const std::size_t n = p_.real;
  hoop_share_.resize(n + ghosts_.size());
  const double width = options_.smoothed_hoop_width;
  for (std::size_t i = 0; i < n; ++i)
    hoop_share_[i] = width > 0.0 ? std::min(1.0, std::abs(p_.position[i][0]) / (width * p_.smoothing_length[i])) : 1.0;
  for (std::size_t g = 0; g < ghosts_.size(); ++g) hoop_share_[n + g] = hoop_share_[ghosts_[g].source];
}

template <int D>
void SphSystem<D>::update_state(double dt, double time) {
  const std::size_t n = p_.real;
  prepare_neighbours();
  predict_mid_step(dt);
  refresh_ghosts();
  const bool corrected = options_.kernel_correction;
  const bool smoothed_hoop = mode_ == GeometryMode::axisymmetric && options_.smoothed_hoop;
  if (corrected) compute_correction();
  if (smoothed_hoop) fill_hoop_shares();  // at the mid-step positions
  refresh_active_pairs();
  size_point_factors();
  // Pair-symmetric like force_pass(): v_ji (x) grad_j W_ji = v_ij (x) grad_i W_ij, so each
  // pair of particles is evaluated once and adds to both with its own weight
  // (volume form V_j for i and V_i for j; density form m_j / eta_i and m_i / eta_j).
  prepare_row_blocks();
  const RowBlocks& blocks = row_blocks_;
  kinematic_sums_.prepare(blocks, n);
  std::size_t limited = 0;
  // One parallel region from the point factors to the material batches (docs/performance.md,
  // "Fewer parallel regions"): the point factors (barrier), the rows (barrier), then
  // each row's sums, its end-of-step eta, h and x and its material point's inputs in one pass.
#pragma omp parallel reduction(+ : limited)
  {
    fill_point_factors(FactorPass::kinematics);
    // Blocks handed out one at a time, as in force_pass().
    for_each_row_block(blocks, kinematic_sums_, [&](std::size_t i, KinematicSum* own) {
      if (corrected || smoothed_hoop)
        corrected_kinematics_row(i, own);
      else
        kinematics_row_lanes(i, own);  // SIMD lanes (pair_lanes.cpp), the same sums
    });
    auto add = [](KinematicSum& total, const KinematicSum& part) {
      total.rate += part.rate;
      total.hoop += part.hoop;
      total.hoop_norm += part.hoop_norm;
      total.hoop_full += part.hoop_full;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) total.L[a][b] += part.L[a][b];
    };
    for_each_row_total(blocks, kinematic_sums_, add, [&](std::size_t i, const KinematicSum& total) {
      if (!end_step_of_row(i, total, dt)) ++limited;
    });
  }
  refresh_ghosts();
  volume_limited_ = limited;
  correction_current_ = false;
  pair_dissipation_current_ = false;
  update_material_batches(MaterialContext{dt, time});
}

template <int D>
void SphSystem<D>::predict_mid_step(double dt) {
  // The rates are evaluated at the mid-step positions x(n+1/2) = x(n+1) - v dt/2
  // with v(n+1/2), and with the pair weights (m_j / eta_j) at mid-step too:
  // eta(n+1/2) predicted from the last step's rate of eta (the trace of the
  // strain rate it produced, without the hoop term). Weights at eta(n) would
  // make the p dV work lag the kinetic energy the forces exchange by a
  // first-order term, which in a fast expansion (a detonation's products)
  // creates energy in proportion to the time step.
  const std::size_t n = p_.real;
  // Scratch kept between steps (no allocation in the cycle): every entry is written before it is read.
  scratch_x_.resize(n);
  scratch_eta_.resize(n);
  const int planar_axes = mode_ == GeometryMode::axisymmetric ? 2 : D;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    scratch_x_[i] = p_.position[i];
    p_.position[i] -= p_.velocity[i] * (0.5 * dt);
    scratch_eta_[i] = p_.planar_density[i];
    const SymTensor& d_last = p_.strain_rate[i];
    const double rate_last = -(d_last.xx + d_last.yy + (planar_axes == 3 ? d_last.zz : 0.0));
    p_.planar_density[i] *= std::exp(0.5 * dt * rate_last);
  }
}

template <int D>
void SphSystem<D>::corrected_kinematics_row(std::size_t i, KinematicSum* own) {
  // Continuity with the pair gradient of the momentum sum (conjugate); L with each
  // particle's own correction, exact for linear fields. The uncorrected row runs on
  // SIMD lanes (kinematics_row_lanes).
  const std::size_t n = p_.real;
  const auto& x = p_.position;
  const auto& v = p_.velocity;
  const auto& m = p_.mass;
  const auto& h = p_.smoothing_length;
  const bool volume_form = options_.volume_form;
  const auto& volume = factors_.volume;
  const auto& inv_eta = factors_.inverse_density;
  const bool smoothed_hoop = mode_ == GeometryMode::axisymmetric && options_.smoothed_hoop;
  const bool corrected = options_.kernel_correction;
  const std::size_t coupling_begin = external_begin_;
  KinematicSum mine;
  for (const std::uint32_t j : active_upper_neighbours(i)) {
    const Vec<D> dx = x[i] - x[j];
    const double r2 = dot(dx, dx);
    const double hij = pair_smoothing_length(h[i], h[j]);
    if (r2 >= support_factor * support_factor * hij * hij) continue;
    const Vec<D> grad = dx * kernel_.pair_terms(std::sqrt(r2), 1.0 / hij).gradient_factor;
    const Vec<D> dv = v[i] - v[j];
    const double weight_i = volume_form ? volume[j] : m[j] * inv_eta[i];
    const double weight_j = volume_form ? volume[i] : m[i] * inv_eta[j];
    // The pair terms on one pair (pair_terms.hpp), the source the SIMD rows run too.
    const Vec<D> pair_grad = pair_gradient(i, j, grad);
    double dv_a[D], pair_grad_a[D];
    for (int a = 0; a < D; ++a) dv_a[a] = dv[a], pair_grad_a[a] = pair_grad[a];
    const KinematicPair<D, double> k = kinematic_pair<D>(dv_a, pair_grad_a, weight_i, weight_j);
    if (smoothed_hoop && j < coupling_begin) {
      // The smoothed hoop rate's sum, the same weights as the smoothed hoop force (sph_forces.cpp).
      const double full = (x[j][0] - x[i][0]) * pair_grad_a[0];
      const double w = full * std::min(hoop_share_[i], hoop_share_[j]);
      mine.hoop += volume[j] * w * v[j][0];
      mine.hoop_norm += volume[j] * w;
      mine.hoop_full += volume[j] * full;
      if (j < n) {
        own[j].hoop += volume[i] * w * v[i][0];
        own[j].hoop_norm += volume[i] * w;
        own[j].hoop_full += volume[i] * full;
      }
    }
    // Without the correction B is the identity: the gradient itself (r-z with the smoothed hoop
    // term runs this row uncorrected, for the hoop sums the SIMD row does not have).
    const Vec<D> b_grad_i = corrected ? apply<D>(p_.correction[i], grad) : grad;
    mine.rate += k.rate_i;
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) mine.L[a][b] -= k.weighted_dv_i[a] * b_grad_i[b];
    if (j < n) {
      const Vec<D> b_grad_j = corrected ? apply<D>(p_.correction[j], grad) : grad;
      own[j].rate += k.rate_j;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) own[j].L[a][b] -= k.weighted_dv_j[a] * b_grad_j[b];
    }
  }
  own[i].rate += mine.rate;
  own[i].hoop += mine.hoop;
  own[i].hoop_norm += mine.hoop_norm;
  own[i].hoop_full += mine.hoop_full;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) own[i].L[a][b] += mine.L[a][b];
}

template <int D>
bool SphSystem<D>::end_step_of_row(std::size_t i, const KinematicSum& total, double dt) {
  const auto& x_end = scratch_x_;
  const auto& h = p_.smoothing_length;
  const double eta_rate = total.rate;
  double L[3][3] = {};
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) L[a][b] = total.L[a][b];
  // L = -sum_j weight_j v_ij (x) grad W: the velocity gradient whose work
  // matches the momentum sum (energy-consistent).
  const bool smoothed_hoop = mode_ == GeometryMode::axisymmetric && options_.smoothed_hoop;
  if (smoothed_hoop) {
    // The conjugate of the smoothed hoop force, (2 pi rho / eta) sum_j V_j w_ij v_r,j, and of its
    // point part (hoop_point_share) times v_r / r (mid-step x, v).
    const double scale = 2.0 * std::numbers::pi * p_.density[i] / p_.planar_density[i];
    const double r = p_.position[i][0];
    L[2][2] = scale * total.hoop + hoop_point_share(total.hoop_norm, total.hoop_full) * p_.velocity[i][0] / r;
  } else if (mode_ == GeometryMode::axisymmetric)
    L[2][2] = p_.velocity[i][0] / p_.position[i][0];  // hoop: v_r / r
  SymTensor d{L[0][0],
              L[1][1],
              L[2][2],
              0.5 * (L[0][1] + L[1][0]),
              0.5 * (L[1][2] + L[2][1]),
              0.5 * (L[2][0] + L[0][2])};
  p_.strain_rate[i] = d;
  if (options_.viscosity_switch) {
    // Morris & Monaghan (1997) over the step with frozen coefficients, solved exactly:
    // d alpha/dt = a - b alpha stays within [alpha_min, alpha_max] for any dt.
    const double tau = h[i] / (options_.viscosity_switch_decay * std::max(p_.wave_speed[i], 1e-30));
    const double source = std::max(-d.trace(), 0.0);
    const double a = options_.viscosity_alpha_min / tau + source * options_.viscosity_alpha;
    const double b = 1.0 / tau + source;
    const double target = a / b;
    p_.viscosity_alpha[i] = target + (p_.viscosity_alpha[i] - target) * std::exp(-b * dt);
  }
  p_.spin[i] = Spin{0.5 * (L[0][1] - L[1][0]), 0.5 * (L[1][2] - L[2][1]), 0.5 * (L[2][0] - L[0][2])};
  // Continuity, integrated as d ln(eta) so that eta stays positive.
  const double eta_new = scratch_eta_[i] * std::exp(dt * eta_rate);
  double hi = h[i];
  if (options_.variable_smoothing_length) {
    const double h0 = p_.reference_smoothing_length[i];
    // The D-th root by sqrt and cbrt rather than pow(x, 1.0 / D): the root itself, not the power
    // of a rounded third (no faster: glibc's cbrt costs what pow did, docs/performance.md).
    const double ratio = p_.reference_planar_density[i] / eta_new;
    hi = h0 * (D == 3 ? std::cbrt(ratio) : D == 2 ? std::sqrt(ratio) : ratio);
    hi = std::clamp(hi, options_.h_min_factor * h0, options_.h_max_factor * h0);
  }
  // Row i's own entries only (the other rows' sums do not read them): end of the step.
  p_.planar_density[i] = eta_new;
  p_.smoothing_length[i] = hi;
  p_.position[i] = x_end[i];
  // The shared constitutive update's inputs: row i's slot in its material's batch.
  MaterialPoints& pts = batches_[p_.material[i]];
  const std::size_t slot = p_.slot[i];
  // The density: eta / (2 pi r), whose hoop rate is v_r / r; with the smoothed hoop rate it
  // follows that rate instead, d ln rho = d ln eta - L_tt dt.
  const double rho = smoothed_hoop ? p_.density[i] * (eta_new / scratch_eta_[i]) * std::exp(-dt * L[2][2])
                                   : eta_new / geometric_weight(x_end[i]);
  pts.density_previous[slot] = p_.density[i];
  pts.density[slot] = rho;
  pts.strain_rate[slot] = d;
  pts.spin[slot] = p_.spin[i];
  pts.artificial_viscosity[slot] = 0.0;  // SPH viscosity is pairwise: its heating is added below
  pts.characteristic_length[slot] = hi;
  pts.specific_energy[slot] += p_.heating[i];
  p_.heating[i] = 0.0;
  p_.density[i] = rho;
  return !(eta_new < p_.mass[i] * kernel_.value(0.0, hi));
}

template <int D>
void SphSystem<D>::update_material_batches(const MaterialContext& ctx) {
  // The shared constitutive update, one batch per material.
  for (std::size_t mat = 0; mat < batches_.size(); ++mat) {
    auto& pts = batches_[mat];
    const auto& members = batch_particles_[mat];
    if (members.empty()) continue;
    try {
      materials_[mat]->update(pts, ctx);
    } catch (const NumericalError& error) {
      // The material names its batch slot: name the particle instead (its id, as output and gauges do).
      if (error.kind() != EntityKind::material_point || error.id() < 0 ||
          static_cast<std::size_t>(error.id()) >= members.size())
        throw;
      const std::size_t i = members[static_cast<std::size_t>(error.id())];
      throw NumericalError(
          EntityKind::particle, static_cast<std::int64_t>(p_.id[i]) + 1, error.quantity(),
          fmt::format("{} (planar density {:.6g}, {:.3g} of its initial value)", error.detail(),
                      p_.planar_density[i], p_.planar_density[i] / p_.reference_planar_density[i]));
    }
  }
  gather_material_state();
}

// The class itself is instantiated in sph_system.cpp; these are its members defined here.
template void SphSystem<2>::compute_correction();
template void SphSystem<3>::compute_correction();
template void SphSystem<2>::fill_hoop_shares();
template void SphSystem<3>::fill_hoop_shares();
template void SphSystem<2>::update_state(double, double);
template void SphSystem<3>::update_state(double, double);

}  // namespace camouflet::sph
