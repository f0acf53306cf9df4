// Rows of the pair-symmetric SPH loops on SIMD lanes (pair_lanes.hpp): the
// momentum row of force_pass() and the kinematics row of update_state(),
// without the kernel correction (sph_forces.cpp and sph_kinematics.cpp keep the scalar loops for it).
// The equations and the pair-once bookkeeping are those of those scalar loops; each
// lane repeats the scalar operations in order, so that only the order of the
// additions into a particle's sums differs from the scalar loops.
#include "sph/pair_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "sph/pair_terms.hpp"
#include "sph/sph_system.hpp"

namespace camouflet::sph {

namespace {

// The neighbours j[0..width) of one group; lanes past the end repeat i (finite data, masked out).
inline LaneMask fill_group(const std::uint32_t* list, std::size_t width, std::uint32_t i, std::uint32_t j[]) {
  LaneMask valid;
  for (int l = 0; l < pair_lanes; ++l) {
    const bool in = static_cast<std::size_t>(l) < width;
    j[l] = in ? list[l] : i;
    valid[l] = in ? -1 : 0;
  }
  return valid;
}

// One group of up to pair_lanes pairs (i, j_l) of a row, as both rows begin it: the neighbours
// (lanes past the list's end repeat i and are masked out), the first `lines` 64-byte lines of
// their records (pair_point.hpp), the separation x_i - x_j, its square, the pair smoothing
// length, the lanes inside the support and the relative velocity v_i - v_j.
template <int D, int lines>
struct PairGroup {
  std::size_t width;
  std::uint32_t j[pair_lanes];
  Lanes fj[8 * lines];  // the neighbours' records, field by field
  Lanes dx[D];
  Lanes dv[D];
  Lanes r2;
  Lanes hij;
  LaneMask inside;

  PairGroup(const PairPoint<D>* points, const double* fi, std::span<const std::uint32_t> list, std::size_t e0,
            std::size_t i) {
    using P = PairPoint<D>;
    width = std::min<std::size_t>(pair_lanes, list.size() - e0);
    const LaneMask valid = fill_group(list.data() + e0, width, static_cast<std::uint32_t>(i), j);
    load_lines(points, j, lines, fj);
    for (int a = 0; a < D; ++a) dx[a] = fi[P::x + a] - fj[P::x + a];
    r2 = Lanes{};
    for (int a = 0; a < D; ++a) r2 += dx[a] * dx[a];
    hij = 0.5 * (fi[P::h] + fj[P::h]);
    inside = valid & (r2 < support_factor * support_factor * hij * hij);
    for (int a = 0; a < D; ++a) dv[a] = fi[P::v + a] - fj[P::v + a];
  }
};

// (AVX-512VL: the 256-bit masked and blended stores of scatter_force_sums.)
#if defined(__AVX512F__) && defined(__AVX512VL__)
// The j sides of a group of pair-once rows in 3-D, added to the partners' sums (j < n) as the
// scalar loops of the rows do, lane by lane: each lane's values are gathered into one register
// by an 8 x 8 transpose rather than inserted value by value, and added with whole-register
// loads and stores. x - y is computed as x + (-y), which IEEE arithmetic rounds alike: the
// sums keep their bits.
template <class Sum>
inline void scatter_kinematic_sums(const Lanes& rate_j, const Lanes weighted_dv_j[3], const Lanes grad[3],
                                   const std::uint32_t* j, std::size_t width, std::size_t n, Sum* own) {
  static_assert(offsetof(Sum, L) == sizeof(double) && sizeof(Sum::L) == 9 * sizeof(double),
                "rate and L[3][3] are ten contiguous doubles");
  Lanes minus_L[9];  // -(weight_j v_ij)_a grad_b, row by row
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) minus_L[3 * a + b] = -(weighted_dv_j[a] * grad[b]);
  __m512d columns[8], rows[8];
  columns[0] = reinterpret_cast<__m512d>(rate_j);
  for (int c = 1; c < 8; ++c) columns[c] = reinterpret_cast<__m512d>(minus_L[c - 1]);
  transpose_8x8(columns, rows);
  // The last two (L_zy, L_zz) lane by lane in pairs: tail[2 l], tail[2 l + 1].
  alignas(64) double tail[16];
  const __m512i first = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
  const __m512i second = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
  const __m512d zy = reinterpret_cast<__m512d>(minus_L[7]), zz = reinterpret_cast<__m512d>(minus_L[8]);
  _mm512_store_pd(tail, _mm512_permutex2var_pd(zy, first, zz));
  _mm512_store_pd(tail + 8, _mm512_permutex2var_pd(zy, second, zz));
  for (std::size_t l = 0; l < width; ++l) {
    if (j[l] >= n) continue;  // ghosts and coupling points have no sums of their own
    double* sums = &own[j[l]].rate;
    _mm512_storeu_pd(sums, _mm512_add_pd(_mm512_loadu_pd(sums), rows[l]));
    _mm_storeu_pd(sums + 8, _mm_add_pd(_mm_loadu_pd(sums + 8), _mm_load_pd(tail + 2 * l)));
  }
}

// The force row's j sides in 3-D: the acceleration (-= reaction), the compression rate (the
// larger of it and -mu, as std::max: the sum unless it is less than -mu), the count, and the
// pair's dissipative term stored per entry (every lane, ghosts included).
template <class Sum>
inline void scatter_force_sums(const Lanes reaction[3], const Lanes& mu, const Lanes dissipation[3],
                               LaneMask inside, const std::uint32_t* j, std::size_t width, std::size_t n,
                               Sum* own, Vec<3>* out) {
  static_assert(offsetof(Sum, compression_rate) == 3 * sizeof(double), "acceleration, then compression_rate");
  static_assert(sizeof(Vec<3>) == 3 * sizeof(double));
  __m512d columns[8], rows[8];
  for (int a = 0; a < 3; ++a) columns[a] = reinterpret_cast<__m512d>(-reaction[a]);
  columns[3] = reinterpret_cast<__m512d>(-mu);
  for (int a = 0; a < 3; ++a) columns[4 + a] = reinterpret_cast<__m512d>(dissipation[a]);
  columns[7] = _mm512_setzero_pd();
  transpose_8x8(columns, rows);
  for (std::size_t l = 0; l < width; ++l) {
    _mm256_mask_storeu_pd(out[l].c.data(), 0x7, _mm512_extractf64x4_pd(rows[l], 1));
    if (j[l] >= n) continue;
    Sum& other = own[j[l]];
    double* sums = other.acceleration.c.data();
    const __m256d old = _mm256_loadu_pd(sums), mine = _mm512_castpd512_pd256(rows[l]);
    // maxpd(a, b) is a > b ? a : b: with a = -mu, b = the sum, std::max(sum, -mu)'s choice.
    _mm256_storeu_pd(sums, _mm256_blend_pd(_mm256_add_pd(old, mine), _mm256_max_pd(mine, old), 0x8));
    other.count += inside[l] ? 1 : 0;
  }
}
#endif
}  // namespace

template <int D>
void SphSystem<D>::force_row_lanes(std::size_t i, ForceSum* own) {
  using P = PairPoint<D>;
  const std::size_t n = p_.real;
  const PairPoint<D>* points = factors_.packed.data();
  const double* fi = points[i].f;
  const auto list = active_upper_neighbours(i);
  Vec<D>* dissipation_out = pair_dissipation_.data() + active_.upper_index()[i];
  const bool volume_form = options_.volume_form;
  const bool tensile = options_.artificial_stress;
  const bool switched = options_.viscosity_switch && options_.viscosity_alpha > 0.0;
  const double alpha_fixed = options_.viscosity_alpha, beta_fixed = options_.viscosity_beta;
  const double mi = fi[P::m], eta_i = fi[P::eta], ci = fi[P::c];
  const double inv_eta_i = 1.0 / eta_i;
  const bool tensile_i = tensile && factors_.has_tensile[i];
  const bool axisymmetric = mode_ == GeometryMode::axisymmetric;
  const bool viscosity_hoop = axisymmetric && options_.viscosity_hoop;
  const double inverse_ring_radius_i = inverse_ring_radius(fi[P::x]);
  const Lanes zero{};
  Lanes acc[D] = {}, mu_max{}, count{}, hoop_weight{}, viscous_hoop{};
  for (std::size_t e0 = 0; e0 < list.size(); e0 += pair_lanes) {
    const PairGroup<D, 2> g(points, fi, list, e0, i);
    const Lanes inv_h = 1.0 / g.hij;
    const Lanes r = sqrt_lanes(g.r2);
    const auto w = kernel_.pair_terms(r, inv_h);
    Lanes grad[D];
    for (int a = 0; a < D; ++a) grad[a] = g.dx[a] * w.gradient_factor;
    const Lanes eta_j = g.fj[P::eta];
    ViscousPair<D, Lanes, LaneMask> viscous;
    if (switched) {
      Lanes alpha_j;
      for (int l = 0; l < pair_lanes; ++l) alpha_j[l] = p_.viscosity_alpha[g.j[l]];
      const PairViscosity<Lanes> q = switched_pair_viscosity(options_, p_.viscosity_alpha[i], alpha_j);
      viscous = viscous_pair<D>(g.inside, g.dx, g.dv, grad, g.r2, g.hij, ci, g.fj[P::c], eta_i, eta_j, q.alpha, q.beta);
    } else {
      viscous = viscous_pair<D>(g.inside, g.dx, g.dv, grad, g.r2, g.hij, ci, g.fj[P::c], eta_i, eta_j, alpha_fixed,
                                beta_fixed);
    }
    const Lanes& mu = viscous.mu;
    mu_max = max_lanes(mu_max, -mu);
    Lanes* dissipation = viscous.dissipation;
    Lanes hoop_weight_j{}, viscous_hoop_j{};
    if (viscosity_hoop) {  // the viscosity's hoop shares (force_pass()), before the artificial stress joins d
      const auto shares = viscous_hoop_shares(dissipation[0], g.fj[P::m], mi, eta_j, eta_i,
                                              inverse_ring_radius(g.fj[P::x]), inverse_ring_radius_i);
      viscous_hoop += shares.i;
      viscous_hoop_j = shares.j;
    }
    if (tensile) {
      LaneMask has;
      for (int l = 0; l < pair_lanes; ++l) has[l] = (tensile_i || factors_.has_tensile[g.j[l]]) ? -1 : 0;
      has &= g.inside;
      if (any_of(has)) {
        Lanes fn = tensile_weight(w.shape * tensile_shape_inverse_, options_.artificial_stress_power,
                                  tensile_power_integer_);
        if (axisymmetric) {
          // The artificial stress's hoop weight, then an image's ring sign on the pair's R term
          // (force_pass(), "The hoop terms of the artificial viscosity and stress").
          const auto shares = tensile_hoop_shares(g.dx[0], grad[0], has ? fn : zero, g.fj[P::m], mi,
                                                  inverse_ring_radius(g.fj[P::x]), inverse_ring_radius_i);
          hoop_weight += shares.i;
          hoop_weight_j = shares.j;
          for (int l = 0; l < pair_lanes; ++l) fn[l] *= ring_sign(g.j[l]);
        }
        const auto ri = components(p_.tensile_term[i]);
        Lanes rij[6];
        for (int l = 0; l < pair_lanes; ++l) {
          const auto rj = components(p_.tensile_term[g.j[l]]);
          for (int c = 0; c < 6; ++c) rij[c][l] = ri[static_cast<std::size_t>(c)] + rj[static_cast<std::size_t>(c)];
        }
        subtract_tensile_pair<D>(has, rij, grad, fn, dissipation);
      }
    }
    const Lanes inv_eta_j = 1.0 / eta_j;
    Lanes force[D];
    momentum_pair<D>(g.inside, volume_form, fi + P::stress, g.fj + P::stress, inv_eta_i, inv_eta_j, grad,
                     dissipation, force);
    const Lanes mj = g.fj[P::m];
    Lanes reaction[D];
    for (int a = 0; a < D; ++a) {
      acc[a] += force[a] * mj;
      reaction[a] = force[a] * mi;
    }
    count += g.inside ? Lanes{} + 1.0 : zero;
#if defined(__AVX512F__) && defined(__AVX512VL__)
    if constexpr (D == 3) {
      // The same values as the loop below, moved by one transpose (transpose_8x8); 3-D has no hoop terms.
      scatter_force_sums(reaction, mu, dissipation, g.inside, g.j, g.width, n, own, dissipation_out + e0);
      continue;
    }
#endif
    for (std::size_t l = 0; l < g.width; ++l) {
      Vec<D>& out = dissipation_out[e0 + l];
      for (int a = 0; a < D; ++a) out[a] = dissipation[a][l];
      if (g.j[l] < n) {
        ForceSum& other = own[g.j[l]];
        for (int a = 0; a < D; ++a) other.acceleration[a] -= reaction[a][l];
        other.compression_rate = std::max(other.compression_rate, -mu[l]);
        other.count += g.inside[l] ? 1 : 0;
        if (axisymmetric) {
          other.tensile_hoop_weight += hoop_weight_j[l];
          other.viscous_hoop += viscous_hoop_j[l];
        }
      }
    }
  }
  ForceSum& mine = own[i];
  for (int a = 0; a < D; ++a) mine.acceleration[a] += sum_lanes(acc[a]);
  mine.compression_rate = std::max(mine.compression_rate, max_of_lanes(mu_max));
  mine.count += static_cast<int>(sum_lanes(count));
  mine.tensile_hoop_weight += sum_lanes(hoop_weight);
  mine.viscous_hoop += sum_lanes(viscous_hoop);
}

template <int D>
void SphSystem<D>::kinematics_row_lanes(std::size_t i, KinematicSum* own) {
  using P = PairPoint<D>;
  const std::size_t n = p_.real;
  const PairPoint<D>* points = factors_.packed.data();
  const double* fi = points[i].f;
  const auto list = active_upper_neighbours(i);
  const bool volume_form = options_.volume_form;
  const double mi = fi[P::m], eta_i = fi[P::eta];
  const double inv_eta_i = 1.0 / eta_i, volume_i = mi / eta_i;
  const Lanes zero{};
  Lanes rate_sum{}, L_sum[D][D] = {};
  for (std::size_t e0 = 0; e0 < list.size(); e0 += pair_lanes) {
    // The first line of the neighbours' records: x, h, v, m (eta, in the second, per lane below).
    const PairGroup<D, 1> g(points, fi, list, e0, i);
    const Lanes gradient_factor = kernel_.pair_terms(sqrt_lanes(g.r2), 1.0 / g.hij).gradient_factor;
    Lanes grad[D];
    for (int a = 0; a < D; ++a) grad[a] = g.inside ? g.dx[a] * gradient_factor : zero;
    const Lanes mj = g.fj[P::m], eta_j = gather(points, g.j, P::eta);
    // Volume form V_j for i and V_i for g.j; density form m_j / eta_i and m_i / eta_j.
    const Lanes weight_i = volume_form ? mj / eta_j : mj * inv_eta_i;
    const Lanes weight_j = volume_form ? Lanes{} + volume_i : mi * (1.0 / eta_j);
    const KinematicPair<D, Lanes> k = kinematic_pair<D>(g.dv, grad, weight_i, weight_j);
    rate_sum += k.rate_i;
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) L_sum[a][b] -= k.weighted_dv_i[a] * grad[b];
#if defined(__AVX512F__) && defined(__AVX512VL__)
    if constexpr (D == 3) {
      scatter_kinematic_sums(k.rate_j, k.weighted_dv_j, grad, g.j, g.width, n, own);
      continue;
    }
#endif
    for (std::size_t l = 0; l < g.width; ++l) {
      if (g.j[l] >= n) continue;  // ghosts and coupling points have no sums of their own
      KinematicSum& other = own[g.j[l]];
      other.rate += k.rate_j[l];
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) other.L[a][b] -= k.weighted_dv_j[a][l] * grad[b][l];
    }
  }
  KinematicSum& mine = own[i];
  mine.rate += sum_lanes(rate_sum);
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) mine.L[a][b] += sum_lanes(L_sum[a][b]);
}

template void SphSystem<2>::force_row_lanes(std::size_t, ForceSum*);
template void SphSystem<3>::force_row_lanes(std::size_t, ForceSum*);
template void SphSystem<2>::kinematics_row_lanes(std::size_t, KinematicSum*);
template void SphSystem<3>::kinematics_row_lanes(std::size_t, KinematicSum*);

}  // namespace camouflet::sph
