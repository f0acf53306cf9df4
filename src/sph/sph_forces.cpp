// The particle forces of one cycle (equations in sph_system.hpp): the pair
// sums of the momentum and energy equations, the active-pair lists and row
// blocks they run over, and the per-particle factors they read.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/sym_tensor_vec.hpp"
#include "sph/artificial_stress.hpp"
#include "sph/pair_terms.hpp"
#include "sph/sph_system.hpp"

namespace camouflet::sph {

template <int D>
void SphSystem<D>::compute_accelerations() {
  // Re-sort by cell every sort_interval list rebuilds: here, at the start of
  // the force stage, no other stage holds per-particle arrays of its own.
  if (options_.sort_interval > 0 && search_.builds() - builds_at_sort_ >= options_.sort_interval)
    sort_by_cell();
  const std::size_t n = p_.real;
  if (options_.artificial_stress && D == 3) {
    // In blocks, so that the eigen-solves run on SIMD lanes (artificial_stress_lanes.cpp).
    constexpr std::size_t block = 256;
#pragma omp parallel for schedule(dynamic, 4)  // eigen-solves vary in cost: balance them
    for (std::size_t b = 0; b < n; b += block) {
      const std::size_t count = std::min(block, n - b);
      double scale[block];
      for (std::size_t k = 0; k < count; ++k) {
        const double eta = p_.planar_density[b + k];
        scale[k] = geometric_weight(p_.position[b + k]) / (eta * eta);
      }
      artificial_stress_3d({p_.stress.data() + b, count}, {scale, count}, options_.artificial_stress_epsilon,
                           {p_.tensile_term.data() + b, count});
    }
  } else if (options_.artificial_stress) {
    const bool axisymmetric = mode_ == GeometryMode::axisymmetric;
    const double epsilon = options_.artificial_stress_epsilon;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double eta = p_.planar_density[i];
      const double scale = geometric_weight(p_.position[i]) / (eta * eta);
      p_.tensile_term[i] = artificial_stress<D>(p_.stress[i], epsilon, scale);
      // r-z: the hoop direction is principal; its R enters the hoop term of force_pass().
      if (axisymmetric && p_.stress[i].zz > 0.0) p_.tensile_term[i].zz = -epsilon * p_.stress[i].zz * scale;
    }
  }
  prepare_neighbours();
  if (options_.kernel_correction && !correction_current_) compute_correction();
  force_pass(true);
}

template <int D>
void SphSystem<D>::size_point_factors() {
  const std::size_t total = p_.position.size();
  factors_.sum_density.resize(total);
  factors_.inverse_density.resize(total);
  factors_.volume.resize(total);
  if (mode_ == GeometryMode::axisymmetric) factors_.inverse_radius.resize(total);
  factors_.has_tensile.resize(total);
  // The SIMD pair loops (no kernel correction) read the packed records, filled in the same pass.
  if (!options_.kernel_correction) factors_.packed.resize(total);
}

template <int D>
void SphSystem<D>::fill_point_factors(FactorPass pass) {
  const std::size_t total = p_.position.size();
  const bool forces = pass == FactorPass::forces;
  const bool tensile = options_.artificial_stress;
  const bool pack = !options_.kernel_correction;
  // The arrays are read by the scalar rows (kernel correction; r-z with the smoothed hoop term)
  // and, after the force pass, by the kick's axis-image work (r-z); has_tensile by the force rows
  // and that work. The kinematics rows on lanes read the first line of the packed record and eta.
  const bool axisymmetric = mode_ == GeometryMode::axisymmetric;
  const bool arrays = options_.kernel_correction || axisymmetric;
  using P = PairPoint<D>;
#pragma omp for schedule(static)
  for (std::size_t k = 0; k < total; ++k) {
    const double eta_q = quadrature_density(k);
    if (arrays) {
      factors_.sum_density[k] = eta_q;
      factors_.inverse_density[k] = 1.0 / eta_q;
      factors_.volume[k] = p_.mass[k] / eta_q;
    }
    // The scalar force row's hoop shares read 1 / |r| of both points of every pair.
    if (forces && axisymmetric) factors_.inverse_radius[k] = inverse_ring_radius(p_.position[k][0]);
    if (forces) {
      const SymTensor& r = p_.tensile_term[k];
      factors_.has_tensile[k] =
          tensile && (r.xx != 0.0 || r.yy != 0.0 || r.zz != 0.0 || r.xy != 0.0 || r.yz != 0.0 || r.zx != 0.0);
    }
    if (!pack) continue;
    double* f = factors_.packed[k].f;
    for (int a = 0; a < D; ++a) {
      f[P::x + a] = p_.position[k][a];
      f[P::v + a] = p_.velocity[k][a];
    }
    f[P::h] = p_.smoothing_length[k];
    f[P::m] = p_.mass[k];
    f[P::eta] = eta_q;  // eta_q: the pair weights (quadrature_density)
    if (!forces) continue;
    const SymTensor& s = p_.stress_term[k];
    const double components[6] = {s.xx, s.yy, s.zz, s.xy, s.yz, s.zx};
    for (int c = 0; c < 6; ++c) f[P::stress + c] = components[c];
    f[P::c] = p_.wave_speed[k];
  }
}

namespace {
// Row blocks per thread of the pair-once loops: more balance the load, but each block's window
// reaches ~2 h of rows past its end, zeroed and added up once more (docs/performance.md).
constexpr int blocks_per_thread = 4;
}  // namespace

template <int D>
void SphSystem<D>::prepare_row_blocks() {
  // Blocks of about equal cost (the j > i entries plus a per-row share for the row's own work: its
  // packed record, the finishing of its sums), several per thread, handed out dynamically: a thread
  // that falls behind (a busy core, a costlier part of the body) is relieved by the others, and
  // the sums do not depend on which thread runs a block. One thread: one block, the serial loop.
  const int threads = std::max(1, omp_get_max_threads());
  const std::size_t blocks = threads == 1 ? 1 : static_cast<std::size_t>(blocks_per_thread * threads);
  if (row_blocks_extraction_ == active_.extractions() &&
      row_blocks_.count() == std::min(blocks, std::max<std::size_t>(p_.real, 1)))
    return;
  const std::size_t n = p_.real;
  constexpr std::size_t row_cost = 4;  // pair entries
  // One past the largest particle among row i's j > i entries (the lists are in cell order, not
  // sorted; ghosts and coupling points, j >= n, have no sums).
  auto reach = [&](std::size_t i) {
    std::size_t end = i + 1;
    for (const std::uint32_t j : active_upper_neighbours(i))
      if (j < n) end = std::max<std::size_t>(end, j + 1);
    return end;
  };
  row_blocks_.build(blocks, n, active_.upper_index().data(), row_cost, reach);
  row_blocks_extraction_ = active_.extractions();
}

template <int D>
void SphSystem<D>::force_pass(bool write_rates) {
  // The momentum sum of sph_system.hpp, pair-symmetric: each pair of
  // particles is evaluated once (j > i) and gives m_j F_ij to i and -m_i F_ij
  // to j, with the pair force per unit mass product
  //   F_ij = (S_i / eta_j + S_j / eta_i) . grad W - d_ij     (volume form)
  //   F_ij = (S_i / eta_i + S_j / eta_j) . grad W - d_ij     (density form)
  //   d_ij = Pi_ij grad W - f^n (R_i + R_j) . grad W,
  // antisymmetric in (i, j) because grad_j W_ji = -grad_i W_ij. Pairs with
  // ghosts and coupling points count for i only. d_ij is stored per pair for
  // the viscous and artificial-stress heating of kick().
  const std::size_t n = p_.real;
  const bool axisymmetric = mode_ == GeometryMode::axisymmetric;
  refresh_active_pairs();
  size_point_factors();
  if (axisymmetric && pair_hoop_.size() != n) pair_hoop_.assign(n, 0.0);
  const bool smoothed_hoop = axisymmetric && options_.smoothed_hoop;
  if (smoothed_hoop && image_hoop_.size() != n) image_hoop_.assign(n, 0.0);
  const std::size_t coupling_begin = external_begin_;  // coupling points take no part in the smoothed hoop term
  if (smoothed_hoop) {
    hoop_sigma_.resize(coupling_begin);
    for (std::size_t k = 0; k < n; ++k) hoop_sigma_[k] = p_.stress[k].zz;
    for (std::size_t g = 0; g < ghosts_.size(); ++g) hoop_sigma_[n + g] = hoop_sigma_[ghosts_[g].source];
    fill_hoop_shares();
  }
  const auto& volume = factors_.volume;
  pair_dissipation_.resize(active_.upper_index()[n]);
  prepare_row_blocks();
  const RowBlocks& blocks = row_blocks_;
  force_sums_.prepare(blocks, n);
  const bool tensile = options_.artificial_stress;
  const bool volume_form = options_.volume_form;
  const bool switched = options_.viscosity_switch;
  const double power = options_.artificial_stress_power;
  const auto& x = p_.position;
  const auto& v = p_.velocity;
  const auto& m = p_.mass;
  const auto& eta = factors_.sum_density;  // eta_q: the pair weights (quadrature_density)
  const auto& h = p_.smoothing_length;
  const auto& inv_eta = factors_.inverse_density;
  const auto& inv_r = factors_.inverse_radius;  // r-z: 1 / |r| (inverse_ring_radius)
  const PairViscosity<> fixed = pair_viscosity(options_, 0.0, 0.0);
  // One parallel region: the point factors (barrier), the rows, their sums (docs/performance.md,
  // "Fewer parallel regions").
#pragma omp parallel
  {
    fill_point_factors(FactorPass::forces);
    // Blocks handed out one at a time (prepare_row_blocks()); rows are added up after the barrier.
    for_each_row_block(blocks, force_sums_, [&](std::size_t i, ForceSum* own) {
      if (!options_.kernel_correction && !smoothed_hoop) {  // SIMD lanes (pair_lanes.cpp), the same sums
        force_row_lanes(i, own);
        return;
      }
      Vec<D> acc{};
      double mu_max = 0.0, hoop_weight = 0.0, viscous_hoop = 0.0, hoop_stress = 0.0, image_hoop_stress = 0.0,
             hoop_norm = 0.0, hoop_full = 0.0;
      int count = 0;
      const std::size_t base = active_.upper_index()[i];
      const auto list = active_upper_neighbours(i);
      for (std::size_t e = 0; e < list.size(); ++e) {
        const std::uint32_t j = list[e];
        const Vec<D> dx = x[i] - x[j];
        const double r2 = dot(dx, dx);
        const double hij = pair_smoothing_length(h[i], h[j]);
        if (r2 >= support_factor * support_factor * hij * hij) {
          pair_dissipation_[base + e] = Vec<D>{};
          continue;
        }
        const double inv_h = 1.0 / hij;
        const double r = std::sqrt(r2);
        const auto w = kernel_.pair_terms(r, inv_h);
        const Vec<D> grad = pair_gradient(i, j, dx * w.gradient_factor);
        // The pair terms on one pair (pair_terms.hpp), the source the SIMD rows run too.
        double dx_a[D], dv_a[D], grad_a[D];
        for (int a = 0; a < D; ++a) dx_a[a] = dx[a], dv_a[a] = v[i][a] - v[j][a], grad_a[a] = grad[a];
        const PairViscosity<> q =
            switched ? pair_viscosity(options_, p_.viscosity_alpha[i], p_.viscosity_alpha[j]) : fixed;
        ViscousPair<D, double, bool> viscous = viscous_pair<D>(true, dx_a, dv_a, grad_a, r2, hij, p_.wave_speed[i],
                                                               p_.wave_speed[j], eta[i], eta[j], q.alpha, q.beta);
        const double mu = viscous.mu;
        if (viscous.approaching) mu_max = std::max(mu_max, -mu);
        if (axisymmetric && options_.viscosity_hoop) {  // as force_row_lanes: the viscosity's hoop shares
          const auto shares = viscous_hoop_shares(viscous.dissipation[0], m[j], m[i], eta[j], eta[i],
                                                  inv_r[j], inv_r[i]);
          viscous_hoop += shares.i;
          if (j < n) own[j].viscous_hoop += shares.j;
        }
        if (tensile && (factors_.has_tensile[i] | factors_.has_tensile[j])) {
          double fn = tensile_weight(w.shape * tensile_shape_inverse_, power, tensile_power_integer_);
          if (axisymmetric) {  // as force_row_lanes: the hoop weight, then the ring sign of an image
            const auto shares = tensile_hoop_shares(dx[0], grad_a[0], fn, m[j], m[i], inv_r[j], inv_r[i]);
            hoop_weight += shares.i;
            if (j < n) own[j].tensile_hoop_weight += shares.j;
            fn *= ring_sign(j);
          }
          const auto r_sum = components(p_.tensile_term[i] + p_.tensile_term[j]);
          subtract_tensile_pair<D>(true, r_sum.data(), grad_a, fn, viscous.dissipation);
        }
        if (smoothed_hoop && j < coupling_begin) {
          // The hoop term with the ring sum's weights V_j (r_j - r_i) dW/dr_i min(beta_i, beta_j)
          // (symmetric in i, j).
          const double full = (x[j][0] - x[i][0]) * grad_a[0];
          const double share = std::min(hoop_share_[i], hoop_share_[j]);
          const double weight = full * share;
          const double term = volume[j] * weight * hoop_sigma_[j];
          hoop_stress += term;
          hoop_norm += volume[j] * weight;
          hoop_full += volume[j] * full;
          if (j < n) {
            own[j].hoop_stress += volume[i] * weight * hoop_sigma_[i];
            own[j].hoop_norm += volume[i] * weight;
            own[j].hoop_full += volume[i] * full;
          } else if (ring_sign(j) < 0.0) {
            image_hoop_stress += term;
          }
        }
        Vec<D>& dissipation = pair_dissipation_[base + e];
        for (int a = 0; a < D; ++a) dissipation[a] = viscous.dissipation[a];
        const auto s_i = components(p_.stress_term[i]), s_j = components(p_.stress_term[j]);
        double force_a[D];
        momentum_pair<D>(true, volume_form, s_i.data(), s_j.data(), inv_eta[i], inv_eta[j], grad_a,
                         viscous.dissipation, force_a);
        Vec<D> force;
        for (int a = 0; a < D; ++a) force[a] = force_a[a];
        acc += force * m[j];
        ++count;
        if (j < n) {
          ForceSum& other = own[j];
          other.acceleration -= force * m[i];
          other.compression_rate = std::max(other.compression_rate, -mu);
          ++other.count;
        }
      }
      ForceSum& mine = own[i];
      mine.acceleration += acc;
      mine.compression_rate = std::max(mine.compression_rate, mu_max);
      mine.count += count;
      mine.tensile_hoop_weight += hoop_weight;
      mine.viscous_hoop += viscous_hoop;
      mine.hoop_stress += hoop_stress;
      mine.image_hoop_stress += image_hoop_stress;
      mine.hoop_norm += hoop_norm;
      mine.hoop_full += hoop_full;
    });
    auto add = [](ForceSum& total, const ForceSum& part) {
      total.acceleration += part.acceleration;
      total.compression_rate = std::max(total.compression_rate, part.compression_rate);
      total.count += part.count;
      total.tensile_hoop_weight += part.tensile_hoop_weight;
      total.viscous_hoop += part.viscous_hoop;
      total.hoop_stress += part.hoop_stress;
      total.image_hoop_stress += part.image_hoop_stress;
      total.hoop_norm += part.hoop_norm;
      total.hoop_full += part.hoop_full;
    };
    // The totals: the accelerations (write_rates), and in r-z the hoop terms of the artificial
    // viscosity and stress, which the kick books also after a restart (force_pass(false)).
    if (write_rates || axisymmetric)
      for_each_row_total(blocks, force_sums_, add, [&](std::size_t i, ForceSum total) {
        if (axisymmetric) {
          // The hoop terms of the artificial viscosity and stress. Their pair sums carry the ring
          // mass m_j ~ r_j, so that a uniform viscous pressure or artificial stress gives a
          // radial force of order q / r that no hoop term balanced, as -sigma_tt / (rho r)
          // balances the stress's (docs/theory/sph.md, "The hoop terms ...").
          // Artificial stress m_j f^n (R_i + R_j): the ring weight sits on R_i's half (R_j ~
          // 1 / (r_j rho_j^2) cancels m_j's r_j), signed for an image. With
          // m_j = (m_j / |r_j|) (r_i + (r_j - r_i)) that half holds the 1/r term
          // R_i sum_j (m_j / |r_j|) (r_j - r_i) f^n grad W; the hoop term is -R_tt,i times its
          // radial weight sum, so that an R even in r and theta gives no radial force.
          // Viscosity ([sph] viscosity_hoop): the planar form's radial term minus the ring form's
          // (pair_terms.hpp, viscous_hoop_shares).
          pair_hoop_[i] = total.viscous_hoop;
          if (tensile) pair_hoop_[i] -= p_.tensile_term[i].zz * total.tensile_hoop_weight;
          total.acceleration[0] += pair_hoop_[i];
        }
        // The smoothed hoop term -(2 pi / eta_i) sum_j V_j (r_j - r_i) dW/dr_i sigma_tt,j; its images'
        // part is booked by the kick (book_axis_image_work), also after a restart.
        const double hoop_scale = smoothed_hoop ? -2.0 * std::numbers::pi / p_.planar_density[i] : 0.0;
        if (smoothed_hoop) image_hoop_[i] = hoop_scale * total.image_hoop_stress;
        if (!write_rates) return;
        if (smoothed_hoop) {
          total.acceleration[0] += hoop_scale * total.hoop_stress;
          // The point term -sigma_tt / (rho r) takes the part of the weight the shares beta took
          // from the smoothed sum.
          const double r = x[i][0];
          const double point = hoop_point_share(total.hoop_norm, total.hoop_full);
          if (r > 0.0 && point > 0.0) total.acceleration[0] -= point * p_.stress[i].zz / (p_.density[i] * r);
        } else if (axisymmetric && x[i][0] > 0.0) {  // hoop stress: -sigma_tt / (rho r) e_r
          total.acceleration[0] -= p_.stress[i].zz / (p_.density[i] * x[i][0]);
        }
        p_.acceleration[i] = total.acceleration;
        p_.compression_rate[i] = total.compression_rate;
        p_.neighbour_count[i] = total.count;
      });
  }
  pair_dissipation_current_ = true;
  pair_dissipation_extraction_ = active_.extractions();
}

// The class itself is instantiated in sph_system.cpp; these are its members defined here.
template void SphSystem<2>::prepare_row_blocks();
template void SphSystem<3>::prepare_row_blocks();
template void SphSystem<2>::force_pass(bool);
template void SphSystem<3>::force_pass(bool);
template void SphSystem<2>::size_point_factors();
template void SphSystem<3>::size_point_factors();
template void SphSystem<2>::fill_point_factors(FactorPass);
template void SphSystem<3>::fill_point_factors(FactorPass);
template void SphSystem<2>::compute_accelerations();
template void SphSystem<3>::compute_accelerations();

}  // namespace camouflet::sph
