// The particle sums of one cycle (equations in sph_system.hpp): forces,
// position update with optional XSPH, and the kinematics that feed the shared
// material update.
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/sym_tensor_vec.hpp"
#include "sph/artificial_stress.hpp"
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
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double eta = p_.planar_density[i];
      p_.tensile_term[i] = artificial_stress<D>(p_.stress[i], options_.artificial_stress_epsilon,
                                                geometric_weight(p_.position[i]) / (eta * eta));
    }
  }
  prepare_neighbours();
  if (options_.kernel_correction && !correction_current_) compute_correction();
  force_pass(true);
}

template <int D>
void SphSystem<D>::size_point_factors() {
  const std::size_t total = p_.position.size();
  sum_density_.resize(total);
  inverse_density_.resize(total);
  point_volume_.resize(total);
  has_tensile_.resize(total);
  // The SIMD pair loops (no kernel correction) read the packed records, filled in the same pass.
  if (!options_.kernel_correction) pair_points_.resize(total);
}

template <int D>
void SphSystem<D>::fill_point_factors() {
  const std::size_t total = p_.position.size();
  const bool tensile = options_.artificial_stress;
  const bool pack = !options_.kernel_correction;
  using P = PairPoint<D>;
#pragma omp for schedule(static)
  for (std::size_t k = 0; k < total; ++k) {
    const double eta_q = quadrature_density(k);
    sum_density_[k] = eta_q;
    inverse_density_[k] = 1.0 / eta_q;
    point_volume_[k] = p_.mass[k] / eta_q;
    const SymTensor& r = p_.tensile_term[k];
    has_tensile_[k] =
        tensile && (r.xx != 0.0 || r.yy != 0.0 || r.zz != 0.0 || r.xy != 0.0 || r.yz != 0.0 || r.zx != 0.0);
    if (!pack) continue;
    double* f = pair_points_[k].f;
    for (int a = 0; a < D; ++a) {
      f[P::x + a] = p_.position[k][a];
      f[P::v + a] = p_.velocity[k][a];
    }
    f[P::h] = p_.smoothing_length[k];
    f[P::m] = p_.mass[k];
    const SymTensor& s = p_.stress_term[k];
    const double components[6] = {s.xx, s.yy, s.zz, s.xy, s.yz, s.zx};
    for (int c = 0; c < 6; ++c) f[P::stress + c] = components[c];
    f[P::eta] = eta_q;  // eta_q: the pair weights (quadrature_density)
    f[P::c] = p_.wave_speed[k];
  }
}

namespace {

// f^n with n a small integer by repeated products (n = 4 by default), else std::pow.
inline double tensile_weight(double f, double power, int integer_power) {
  if (integer_power == 0) return std::pow(f, power);
  double fn = f;
  for (int k = 1; k < integer_power; ++k) fn *= f;
  return fn;
}

}  // namespace

template <int D>
void SphSystem<D>::refresh_active_pairs() {
  const std::size_t n = p_.real, total = p_.position.size();
  const auto& x = p_.position;
  const auto& h = p_.smoothing_length;
  if (active_builds_ == search_.builds() && active_x_.size() == total) {
    // Same criterion as NeighbourSearch::needs_rebuild, against the extraction.
    double d2_max = 0.0, dh_max = 0.0;
#pragma omp parallel for schedule(static) reduction(max : d2_max, dh_max)
    for (std::size_t k = 0; k < total; ++k) {
      const Vec<D> d = x[k] - active_x_[k];
      d2_max = std::max(d2_max, dot(d, d));
      dh_max = std::max(dh_max, h[k] - active_h_[k]);
    }
    if (2.0 * std::sqrt(d2_max) + support_factor * dh_max <= active_margin_) return;
  }
  active_builds_ = search_.builds();
  ++active_extractions_;
  active_x_.assign(x.begin(), x.end());
  active_h_.assign(h.begin(), h.end());
  active_offset_.assign(n + 1, 0);
  // The cell lists hold every pair within 2 h_ij + (their skin - the part of it used):
  // the thin skin can be no wider than that.
  const double skin = std::max(0.0, std::min(active_skin_, search_.skin() - search_.skin_used(x, h)));
  active_margin_ = skin;
  auto inside = [&](std::size_t i, std::uint32_t j) {
    const Vec<D> dx = x[i] - x[j];
    const double reach = support_factor * pair_smoothing_length(h[i], h[j]) + skin;
    return dot(dx, dx) < reach * reach;
  };
  // One pass over the cell lists: each block of particles collects its entries
  // in a buffer of its own, then the buffers are copied into place.
  constexpr std::size_t block = 256;
  const std::size_t n_blocks = (n + block - 1) / block;
  std::vector<std::vector<std::uint32_t>> found(n_blocks);
#pragma omp parallel for schedule(dynamic, 4)
  for (std::size_t b = 0; b < n_blocks; ++b) {
    std::vector<std::uint32_t>& buffer = found[b];
    const std::size_t end = std::min(n, (b + 1) * block);
    std::size_t candidates = 0;
    for (std::size_t i = b * block; i < end; ++i) candidates += search_.neighbours(i).size();
    buffer.reserve(candidates);
    for (std::size_t i = b * block; i < end; ++i) {
      const std::size_t start = buffer.size();
      for (const std::uint32_t j : search_.neighbours(i))
        if (inside(i, j)) buffer.push_back(j);
      active_offset_[i + 1] = buffer.size() - start;
    }
  }
  for (std::size_t i = 0; i < n; ++i) active_offset_[i + 1] += active_offset_[i];
  active_.resize(active_offset_[n]);
  active_upper_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n_blocks; ++b) {
    std::copy(found[b].begin(), found[b].end(),
              active_.begin() + static_cast<std::ptrdiff_t>(active_offset_[b * block]));
    const std::size_t end = std::min(n, (b + 1) * block);
    for (std::size_t i = b * block; i < end; ++i) {
      const auto first = active_.begin() + static_cast<std::ptrdiff_t>(active_offset_[i]);
      const auto last = active_.begin() + static_cast<std::ptrdiff_t>(active_offset_[i + 1]);
      active_upper_[i] = static_cast<std::size_t>(
          std::upper_bound(first, last, static_cast<std::uint32_t>(i)) - active_.begin());
    }
  }
  upper_index_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    upper_index_[i + 1] = upper_index_[i] + (active_offset_[i + 1] - active_upper_[i]);
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
  if (row_blocks_extraction_ == active_extractions_ &&
      row_blocks_.count() == std::min(blocks, std::max<std::size_t>(p_.real, 1)))
    return;
  const std::size_t n = p_.real;
  constexpr std::size_t row_cost = 4;  // pair entries
  // One past the largest particle among row i's j > i entries (ghosts and coupling points, j >= n,
  // sort after the particles in the list and have no sums).
  auto reach = [&](std::size_t i) {
    const auto list = active_upper_neighbours(i);
    std::size_t e = list.size();
    while (e > 0 && list[e - 1] >= n) --e;
    return e > 0 ? std::max<std::size_t>(i + 1, list[e - 1] + 1) : i + 1;
  };
  row_blocks_.build(blocks, n, upper_index_.data(), row_cost, reach);
  row_blocks_extraction_ = active_extractions_;
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
  pair_dissipation_.resize(upper_index_[n]);
  prepare_row_blocks();
  const RowBlocks& blocks = row_blocks_;
  const std::size_t n_blocks = blocks.count();
  force_sums_.prepare(blocks, n);
  const bool tensile = options_.artificial_stress;
  const bool volume_form = options_.volume_form;
  const bool switched = options_.viscosity_switch;
  const double power = options_.artificial_stress_power;
  const auto& x = p_.position;
  const auto& v = p_.velocity;
  const auto& m = p_.mass;
  const auto& eta = sum_density_;  // eta_q: the pair weights (quadrature_density)
  const auto& h = p_.smoothing_length;
  const auto& inv_eta = inverse_density_;
  const PairViscosity fixed = pair_viscosity(options_, 0.0, 0.0);
  // One parallel region: the point factors (barrier), the rows, their sums (docs/performance.md,
  // "Fewer parallel regions").
#pragma omp parallel
  {
    fill_point_factors();
    // Blocks handed out one at a time (prepare_row_blocks()); rows are added up after the barrier.
#pragma omp for schedule(dynamic, 1)
    for (std::size_t k = 0; k < n_blocks; ++k) {
      ForceSum* const own = force_sums_.zeroed(blocks, k);
      for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i) {
        if (!options_.kernel_correction) {  // SIMD lanes (pair_lanes.cpp), the same sums
          force_row_lanes(i, own);
          continue;
        }
        Vec<D> acc{};
        double mu_max = 0.0;
        int count = 0;
        const std::size_t base = upper_index_[i];
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
          const Vec<D> dv = v[i] - v[j];
          const double vr = dot(dv, dx);
          Vec<D> dissipation{};
          double mu = 0.0;
          if (vr < 0.0) {  // approaching pair: Monaghan 1992, eq. (4.2)
            mu = hij * vr / (r2 + 0.01 * hij * hij);
            const double c_mean = 0.5 * (p_.wave_speed[i] + p_.wave_speed[j]);
            const PairViscosity q =
                switched ? pair_viscosity(options_, p_.viscosity_alpha[i], p_.viscosity_alpha[j]) : fixed;
            const double pi_ij = (-q.alpha * c_mean * mu + q.beta * mu * mu) / (0.5 * (eta[i] + eta[j]));
            mu_max = std::max(mu_max, -mu);
            dissipation = grad * pi_ij;
          }
          if (tensile && (has_tensile_[i] | has_tensile_[j])) {
            const double fn = tensile_weight(w.shape * tensile_shape_inverse_, power, tensile_power_integer_);
            dissipation -= apply<D>(p_.tensile_term[i] + p_.tensile_term[j], grad) * fn;
          }
          pair_dissipation_[base + e] = dissipation;
          // S = sigma / rho: volume form (S_i / eta_j + S_j / eta_i), density form (S_i / eta_i + S_j /
          // eta_j).
          const SymTensor pair = volume_form
                                     ? p_.stress_term[i] * inv_eta[j] + p_.stress_term[j] * inv_eta[i]
                                     : p_.stress_term[i] * inv_eta[i] + p_.stress_term[j] * inv_eta[j];
          const Vec<D> force = apply<D>(pair, grad) - dissipation;
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
      }
    }
    if (write_rates) {
      auto add = [](ForceSum& total, const ForceSum& part) {
        total.acceleration += part.acceleration;
        total.compression_rate = std::max(total.compression_rate, part.compression_rate);
        total.count += part.count;
      };
#pragma omp for schedule(dynamic, 1)
      for (std::size_t k = 0; k < n_blocks; ++k) {
        for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i) {
          ForceSum total = force_sums_.total(blocks, k, i, add);
          if (axisymmetric && x[i][0] > 0.0)  // hoop stress: -sigma_tt / (rho r) e_r
            total.acceleration[0] -= p_.stress[i].zz / (p_.density[i] * x[i][0]);
          p_.acceleration[i] = total.acceleration;
          p_.compression_rate[i] = total.compression_rate;
          p_.neighbour_count[i] = total.count;
        }
      }
    }
  }
  pair_dissipation_current_ = true;
  pair_dissipation_extraction_ = active_extractions_;
}

template <int D>
void SphSystem<D>::kick(double dt) {
  const std::size_t n = p_.real;
  const std::size_t total = p_.velocity.size();
  velocity_old_.resize(total);  // particles and ghosts, v(n-1/2)
  heat_points_.resize(total);
  // v(n+1/2) = v(n-1/2) + a dt, and the heating record of each particle (below) in the same pass.
  const auto kick_particles = [&] {
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < total; ++k) {
      velocity_old_[k] = p_.velocity[k];
      if (k < n) {
        p_.velocity[k] += p_.acceleration[k] * dt;
        heat_points_[k] = {velocity_old_[k] + p_.velocity[k], p_.mass[k]};
      }
    }
  };
  // The ghosts and coupling points after refresh_ghosts(): their records too.
  const auto refresh_other_points = [&] {
    refresh_ghosts();
    for (std::size_t k = n; k < total; ++k) heat_points_[k] = {velocity_old_[k] + p_.velocity[k], p_.mass[k]};
  };
  // After a restart between the force stage and the kick the pair terms are not stored:
  // the force pass at the same x(n), v(n-1/2) gives them again, bit for bit.
  const bool stored = pair_dissipation_current_ && pair_dissipation_extraction_ == active_extractions_;
  if (!stored) {
#pragma omp parallel
    kick_particles();
    refresh_other_points();
    std::vector<Vec<D>> v_new(p_.velocity);
    p_.velocity = velocity_old_;
    force_pass(false);
    p_.velocity = std::move(v_new);
  }

  // Viscous heating of this impulse: the kinetic energy the viscous pair forces
  // (evaluated with v(n-1/2) at x(n)) take out over the kick is
  // 1/2 sum_ij m_i m_j Pi_ij vbar_ij . grad W dt with vbar the mean of the old
  // and new velocities; each particle gets its half (Monaghan 1992, eq. 4.6)
  // with that same mean velocity, so the exchange is exact.
  // The artificial stress is a pair force T_ij . grad W with T_ij = f^n (R_i + R_j)
  // that no constitutive law books: its work is booked the same way, as
  // de_i = -1/2 sum_j m_j vbar_ij . T_ij . grad W dt, so that kinetic +
  // internal energy stays conserved (it is reversible over a tension cycle;
  // docs/theory/sph.md). Both are the stored d_ij of force_pass(): the pair
  // gives de_i = 1/2 m_j d_ij . vbar_ij dt and de_j = 1/2 m_i d_ij . vbar_ij dt.
  const auto& d = pair_dissipation_;
  // The blocks of the force pass that stored d (the same extraction; thread_sums.hpp).
  const RowBlocks& blocks = row_blocks_;
  const std::size_t n_blocks = blocks.count();
  heat_sums_.prepare(blocks, n);
  const HeatPoint* const hp = heat_points_.data();
  // One parallel region: the kick with the particles' heating records (v(n-1/2) + v(n+1/2) and m
  // in one 32-byte record, 3-D: one line per neighbour), the ghosts' (one thread), the heating
  // rows, their sums (docs/performance.md, "Fewer parallel regions").
#pragma omp parallel
  {
    if (stored) {
      kick_particles();
#pragma omp single
      refresh_other_points();
    }
#pragma omp for schedule(dynamic, 1)
    for (std::size_t k = 0; k < n_blocks; ++k) {
      double* const own = heat_sums_.zeroed(blocks, k);
      for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i) {
        const Vec<D> sum_i = hp[i].velocity_sum;
        const double mi = hp[i].mass;
        double heat = 0.0;
        const std::size_t base = upper_index_[i];
        const auto list = active_upper_neighbours(i);
        for (std::size_t e = 0; e < list.size(); ++e) {
          const std::uint32_t j = list[e];
          const double work = dot(d[base + e], sum_i - hp[j].velocity_sum);  // 2 d_ij . vbar_ij
          heat += work * hp[j].mass;
          if (j < n) own[j] += work * mi;
        }
        own[i] += heat;
      }
    }
    auto add = [](double& total, double part) { total += part; };
#pragma omp for schedule(dynamic, 1)
    for (std::size_t k = 0; k < n_blocks; ++k)
      for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i)
        p_.heating[i] += 0.25 * heat_sums_.total(blocks, k, i, add) * dt;
  }
  book_axis_image_work(dt);
  if (options_.conductivity > 0.0) conduct_heat(dt);
}

// The images across the axis carry their ring weight signed (refresh_ghosts), so that the
// momentum sum of the first particle columns is accurate. The conservative pairing would give
// them |r|: with it the term of pair (i, image of j) and the one of pair (j, image of i) balance
// each other's work exactly; with the signed weight they do not, and the energy balance of a
// blast centred on the axis lost ~5 % (long_sedov.cpp). The difference of the two forces on i,
// dF_i = 2 m_i m_g (S_g / eta_i + f^n R_g) . grad W (S_g, R_g as stored, signed), is the only
// part of the sums that no internal energy balances: its work dF_i . vbar_i dt is taken from
// the particle's internal energy, the same centring as the viscous heating above. It vanishes
// with the spacing (particles within 2 h of the axis, ring masses ~ r).
template <int D>
void SphSystem<D>::book_axis_image_work(double dt) {
  if (mode_ != GeometryMode::axisymmetric || !options_.volume_form) return;
  const std::size_t n = p_.real, images_end = n + ghosts_.size();
  const auto& x = p_.position;
  const auto& h = p_.smoothing_length;
  const auto& m = p_.mass;
  const auto& eta = sum_density_;
  const bool tensile = options_.artificial_stress;
  const double power = options_.artificial_stress_power;
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    const auto list = active_upper_neighbours(i);  // every image j >= n > i is in the upper part
    if (list.empty() || list.back() < n) continue;
    const Vec<D> v_mean = (velocity_old_[i] + p_.velocity[i]) * 0.5;
    double work = 0.0;  // J/kg per s
    for (const std::uint32_t j : list) {
      if (j < n || j >= images_end || image_sign_[j - n] > 0) continue;
      const Vec<D> dx = x[i] - x[j];
      const double r2 = dot(dx, dx);
      const double hij = pair_smoothing_length(h[i], h[j]);
      if (r2 >= support_factor * support_factor * hij * hij) continue;
      const auto w = kernel_.pair_terms(std::sqrt(r2), 1.0 / hij);
      const Vec<D> grad = pair_gradient(i, j, dx * w.gradient_factor);
      SymTensor term = p_.stress_term[j] * (1.0 / eta[i]);
      if (tensile && (has_tensile_[i] | has_tensile_[j]))
        term += p_.tensile_term[j] *
                tensile_weight(w.shape * tensile_shape_inverse_, power, tensile_power_integer_);
      work += 2.0 * m[j] * dot(apply<D>(term, grad), v_mean);
    }
    p_.heating[i] -= work * dt;
  }
}

// Artificial conductivity (SphOptions::conductivity; Price 2008, eqs. 28 and
// 30): between particles of one EOS family, ghosts as their sources; coupling
// points (FEM) take no part. With the planar density of the SPH sums (eta,
// ring mass in r-z) and dW/dr < 0, heat flows from i to j when u_i > u_j, and
// m_i du_i = -m_j du_j pair by pair. A gather over the full neighbour list:
// it is off by default and not on the hot path of the cycle.
template <int D>
void SphSystem<D>::conduct_heat(double dt) {
  const std::size_t n = p_.real;
  const std::size_t mirrored = n + ghosts_.size();
  const auto& x = p_.position;
  const auto& m = p_.mass;
  const auto& eta = p_.planar_density;
  const auto& h = p_.smoothing_length;
  const double alpha_u = options_.conductivity;
  std::vector<double> u(mirrored), pressure(mirrored), rho(mirrored);
  std::vector<int> family(mirrored);
  for (std::size_t i = 0; i < n; ++i) {
    u[i] = batches_[p_.material[i]].specific_energy[p_.slot[i]];
    pressure[i] = p_.pressure[i];
    rho[i] = p_.density[i];
    family[i] = eos_family_[p_.material[i]];
  }
  for (std::size_t g = 0; g < ghosts_.size(); ++g) {
    const std::size_t s = ghosts_[g].source;
    u[n + g] = u[s], pressure[n + g] = pressure[s], rho[n + g] = rho[s], family[n + g] = family[s];
  }
#pragma omp parallel for schedule(dynamic, 128)
  for (std::size_t i = 0; i < n; ++i) {
    double heat = 0.0;
    for (const std::uint32_t j : search_.neighbours(i)) {
      if (j >= mirrored || family[j] != family[i] || u[i] == u[j]) continue;
      const Vec<D> dx = x[i] - x[j];
      const double r2 = dot(dx, dx);
      const double hij = pair_smoothing_length(h[i], h[j]);
      if (r2 >= support_factor * support_factor * hij * hij) continue;
      const double r = std::sqrt(r2);
      const double rho_ij = 0.5 * (rho[i] + rho[j]);
      const double v_sig = std::sqrt(std::abs(pressure[i] - pressure[j]) / rho_ij);
      heat += m[j] * alpha_u * v_sig * (u[i] - u[j]) / (0.5 * (eta[i] + eta[j])) * kernel_.derivative(r, hij);
    }
    p_.heating[i] += heat * dt;
  }
}

template <int D>
void SphSystem<D>::drift(double dt) {
  const std::size_t n = p_.real;
  correction_current_ = false;
  pair_dissipation_current_ = false;
  // The XSPH shift exists only when asked for: no allocation in the default cycle.
  std::vector<Vec<D>> shift;
  if (options_.xsph > 0.0) {
    shift.resize(n);
    // XSPH (Monaghan 1989): move with the velocity smoothed over neighbours.
    prepare_neighbours();
    const auto& x = p_.position;
    const auto& v = p_.velocity;
#pragma omp parallel for schedule(dynamic, 128)
    for (std::size_t i = 0; i < n; ++i) {
      Vec<D> s{};
      for (const std::uint32_t j : search_.neighbours(i)) {
        const Vec<D> dx = x[i] - x[j];
        const double hij = pair_smoothing_length(p_.smoothing_length[i], p_.smoothing_length[j]);
        const double w = kernel_.value(std::sqrt(dot(dx, dx)), hij);
        if (w == 0.0) continue;
        s += (v[j] - v[i]) *
             (options_.xsph * p_.mass[j] * w / (0.5 * (p_.planar_density[i] + p_.planar_density[j])));
      }
      shift[i] = s;
    }
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<D> dx = (shift.empty() ? p_.velocity[i] : p_.velocity[i] + shift[i]) * dt;
    p_.position[i] += dx;
    p_.displacement[i] += dx;
  }
  if (mode_ == GeometryMode::axisymmetric)
    for (std::size_t i = 0; i < n; ++i)
      if (!(p_.position[i][0] > 0.0))
        throw NumericalError(EntityKind::particle, static_cast<std::int64_t>(p_.id[i]) + 1, "radius",
                             fmt::format("particle crossed the axis (r = {:.6g} m)", p_.position[i][0]));
}

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
void SphSystem<D>::update_state(double dt, double time) {
  const std::size_t n = p_.real;
  const bool axisymmetric = mode_ == GeometryMode::axisymmetric;
  prepare_neighbours();
  const auto& x = p_.position;
  const auto& v = p_.velocity;
  const auto& m = p_.mass;
  const auto& eta = p_.planar_density;
  const auto& h = p_.smoothing_length;
  // Scratch kept between steps (no allocation in the cycle): every entry is written before it is read.
  auto& x_end = scratch_x_;
  x_end.resize(n);
  auto& eta_start = scratch_eta_;
  eta_start.resize(n);

  // The rates are evaluated at the mid-step positions x(n+1/2) = x(n+1) - v dt/2
  // with v(n+1/2), and with the pair weights (m_j / eta_j) at mid-step too:
  // eta(n+1/2) predicted from the last step's rate of eta (the trace of the
  // strain rate it produced, without the hoop term). Weights at eta(n) would
  // make the p dV work lag the kinetic energy the forces exchange by a
  // first-order term, which in a fast expansion (a detonation's products)
  // creates energy in proportion to the time step.
  const int planar_axes = axisymmetric ? 2 : D;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    x_end[i] = p_.position[i];
    p_.position[i] -= p_.velocity[i] * (0.5 * dt);
    eta_start[i] = p_.planar_density[i];
    const SymTensor& d_last = p_.strain_rate[i];
    const double rate_last = -(d_last.xx + d_last.yy + (planar_axes == 3 ? d_last.zz : 0.0));
    p_.planar_density[i] *= std::exp(0.5 * dt * rate_last);
  }
  refresh_ghosts();
  const bool corrected = options_.kernel_correction;
  if (corrected) compute_correction();
  refresh_active_pairs();
  size_point_factors();
  const bool volume_form = options_.volume_form;
  const auto& volume = point_volume_;
  const auto& inv_eta = inverse_density_;
  // Pair-symmetric like force_pass(): v_ji (x) grad_j W_ji = v_ij (x) grad_i W_ij, so each
  // pair of particles is evaluated once and adds to both with its own weight
  // (volume form V_j for i and V_i for j; density form m_j / eta_i and m_i / eta_j).
  prepare_row_blocks();
  const RowBlocks& blocks = row_blocks_;
  const std::size_t n_blocks = blocks.count();
  kinematic_sums_.prepare(blocks, n);
  std::size_t limited = 0;
  const MaterialContext ctx{dt, time};
  // One parallel region from the point factors to the material batches (docs/performance.md,
  // "Fewer parallel regions"): the point factors (barrier), the rows (barrier), then
  // each row's sums, its end-of-step eta, h and x and its material point's inputs in one pass.
#pragma omp parallel reduction(+ : limited)
  {
    fill_point_factors();
    // Blocks handed out one at a time, as in force_pass().
#pragma omp for schedule(dynamic, 1)
    for (std::size_t k = 0; k < n_blocks; ++k) {
      KinematicSum* const own = kinematic_sums_.zeroed(blocks, k);
      for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i) {
        if (!corrected) {  // SIMD lanes (pair_lanes.cpp), the same sums
          kinematics_row_lanes(i, own);
          continue;
        }
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
          const bool both = j < n;
          if (corrected) {
            // Continuity with the pair gradient of the momentum sum (conjugate);
            // L with each particle's own correction, exact for linear fields.
            const double rate = dot(dv, pair_gradient(i, j, grad));
            const Vec<D> b_grad_i = apply<D>(p_.correction[i], grad);
            mine.rate += weight_i * rate;
            for (int a = 0; a < D; ++a)
              for (int b = 0; b < D; ++b) mine.L[a][b] -= weight_i * dv[a] * b_grad_i[b];
            if (both) {
              const Vec<D> b_grad_j = apply<D>(p_.correction[j], grad);
              own[j].rate += weight_j * rate;
              for (int a = 0; a < D; ++a)
                for (int b = 0; b < D; ++b) own[j].L[a][b] -= weight_j * dv[a] * b_grad_j[b];
            }
          } else {
            const double rate = dot(dv, grad);
            mine.rate += weight_i * rate;
            for (int a = 0; a < D; ++a)
              for (int b = 0; b < D; ++b) mine.L[a][b] -= weight_i * dv[a] * grad[b];
            if (both) {
              own[j].rate += weight_j * rate;
              for (int a = 0; a < D; ++a)
                for (int b = 0; b < D; ++b) own[j].L[a][b] -= weight_j * dv[a] * grad[b];
            }
          }
        }
        own[i].rate += mine.rate;
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) own[i].L[a][b] += mine.L[a][b];
      }
    }
    auto add = [](KinematicSum& total, const KinematicSum& part) {
      total.rate += part.rate;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) total.L[a][b] += part.L[a][b];
    };
#pragma omp for schedule(dynamic, 1)
    for (std::size_t k = 0; k < n_blocks; ++k)
      for (std::size_t i = blocks.begin(k); i < blocks.end(k); ++i) {
        const KinematicSum total = kinematic_sums_.total(blocks, k, i, add);
        const double eta_rate = total.rate;
        double L[3][3] = {};
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) L[a][b] = total.L[a][b];
        // L = -sum_j weight_j v_ij (x) grad W: the velocity gradient whose work
        // matches the momentum sum (energy-consistent).
        if (axisymmetric) L[2][2] = v[i][0] / x[i][0];  // hoop strain rate v_r / r
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
        const double eta_new = eta_start[i] * std::exp(dt * eta_rate);
        double hi = h[i];
        if (options_.variable_smoothing_length) {
          const double h0 = p_.reference_smoothing_length[i];
          hi = h0 * std::pow(p_.reference_planar_density[i] / eta_new, 1.0 / D);
          hi = std::clamp(hi, options_.h_min_factor * h0, options_.h_max_factor * h0);
        }
        // Row i's own entries only (the other rows' sums do not read them): end of the step.
        p_.planar_density[i] = eta_new;
        p_.smoothing_length[i] = hi;
        p_.position[i] = x_end[i];
        if (eta_new < m[i] * kernel_.value(0.0, hi)) ++limited;
        // The shared constitutive update's inputs: row i's slot in its material's batch.
        MaterialPoints& pts = batches_[p_.material[i]];
        const std::size_t slot = p_.slot[i];
        const double rho = eta_new / geometric_weight(x_end[i]);
        pts.density_previous[slot] = p_.density[i];
        pts.density[slot] = rho;
        pts.strain_rate[slot] = d;
        pts.spin[slot] = p_.spin[i];
        pts.artificial_viscosity[slot] = 0.0;  // SPH viscosity is pairwise: its heating is added below
        pts.characteristic_length[slot] = hi;
        pts.specific_energy[slot] += p_.heating[i];
        p_.heating[i] = 0.0;
        p_.density[i] = rho;
      }
  }
  refresh_ghosts();
  volume_limited_ = limited;
  correction_current_ = false;
  pair_dissipation_current_ = false;

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
template void SphSystem<2>::refresh_active_pairs();
template void SphSystem<3>::refresh_active_pairs();
template void SphSystem<2>::prepare_row_blocks();
template void SphSystem<3>::prepare_row_blocks();
template void SphSystem<2>::force_pass(bool);
template void SphSystem<3>::force_pass(bool);
template void SphSystem<2>::size_point_factors();
template void SphSystem<3>::size_point_factors();
template void SphSystem<2>::fill_point_factors();
template void SphSystem<3>::fill_point_factors();
template void SphSystem<2>::compute_accelerations();
template void SphSystem<3>::compute_accelerations();
template void SphSystem<2>::kick(double);
template void SphSystem<3>::kick(double);
template void SphSystem<2>::drift(double);
template void SphSystem<3>::drift(double);
template void SphSystem<2>::update_state(double, double);
template void SphSystem<3>::update_state(double, double);

}  // namespace camouflet::sph
