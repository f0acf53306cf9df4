// The particle motion of one cycle: the kick (velocity and internal energy
// from the forces), the work of the axis images and the artificial heat
// conduction booked with it, and the drift of the positions (optional XSPH).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/sym_tensor_vec.hpp"
#include "sph/artificial_stress.hpp"
#include "sph/pair_terms.hpp"
#include "sph/sph_system.hpp"

namespace camouflet::sph {

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
  const bool stored = pair_dissipation_current_ && pair_dissipation_extraction_ == active_.extractions();
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
    for_each_row_block(blocks, heat_sums_, [&](std::size_t i, double* own) {
      const Vec<D> sum_i = hp[i].velocity_sum;
      const double mi = hp[i].mass;
      double heat = 0.0;
      const std::size_t base = active_.upper_index()[i];
      const auto list = active_upper_neighbours(i);
      for (std::size_t e = 0; e < list.size(); ++e) {
        const std::uint32_t j = list[e];
        const double work = dot(d[base + e], sum_i - hp[j].velocity_sum);  // 2 d_ij . vbar_ij
        heat += work * hp[j].mass;
        if (j < n) own[j] += work * mi;
      }
      own[i] += heat;
    });
    auto add = [](double& total, double part) { total += part; };
    for_each_row_total(blocks, heat_sums_, add,
                       [&](std::size_t i, double total) { p_.heating[i] += 0.25 * total * dt; });
  }
  book_axis_image_work(dt);
  if (options_.conductivity > 0.0) conduct_heat(dt);
}

// The images across the axis carry their ring weight signed (refresh_ghosts), so that the
// momentum sum of the first particle columns is accurate. The conservative pairing would give
// them |r|: with it the term of pair (i, image of j) and the one of pair (j, image of i) balance
// each other's work exactly; with the signed weight they do not, and the energy balance of a
// blast centred on the axis lost ~5 % (long_sedov.cpp). The difference of the two forces on i,
// dF_i = 2 m_g (S_g / eta_i - f^n R_i) . grad W per unit mass (S_g as stored, signed; the
// artificial stress's ring weight sits on R_i's half of its pair), is part of the sums that no
// internal energy balances: its work dF_i . vbar_i dt is taken from the particle's internal
// energy, the same centring as the viscous heating above. It vanishes with the spacing
// (particles within 2 h of the axis, ring masses ~ r). So is the work of the hoop terms of the
// artificial viscosity and stress (force_pass()), which have no pair partner.
template <int D>
void SphSystem<D>::book_axis_image_work(double dt) {
  // (The density form keeps |r| on its images, image_sign_ > 0: only the hoop terms' work.)
  if (mode_ != GeometryMode::axisymmetric) return;
  const std::size_t n = p_.real, images_end = n + ghosts_.size();
  const auto& x = p_.position;
  const auto& h = p_.smoothing_length;
  const auto& m = p_.mass;
  const auto& eta = factors_.sum_density;
  const bool tensile = options_.artificial_stress;
  const double power = options_.artificial_stress_power;
  const bool hoop = pair_hoop_.size() == n;
  const bool smoothed = options_.smoothed_hoop && image_hoop_.size() == n;
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    const auto list = active_upper_neighbours(i);  // every image j >= n > i is in the upper part
    const bool images = !list.empty() && list.back() >= n;
    if (!images && !(hoop && pair_hoop_[i] != 0.0)) continue;
    const Vec<D> v_mean = (velocity_old_[i] + p_.velocity[i]) * 0.5;
    // The hoop terms of the artificial viscosity and stress have no pair partner: their work too.
    double work = hoop ? pair_hoop_[i] * v_mean[0] : 0.0;  // J/kg per s
    // The smoothed hoop term ([sph] smoothed_hoop): the images' part of the force on i and the
    // images' part of j's hoop rate, with mirrored v_r, do the same work where the conservative
    // pairing would have them cancel: twice the force's work is taken back.
    if (smoothed) work += 2.0 * image_hoop_[i] * v_mean[0];
    for (const std::uint32_t j : list) {
      if (!images) break;
      if (j < n || j >= images_end || image_sign_[j - n] > 0) continue;
      const Vec<D> dx = x[i] - x[j];
      const double r2 = dot(dx, dx);
      const double hij = pair_smoothing_length(h[i], h[j]);
      if (r2 >= support_factor * support_factor * hij * hij) continue;
      const auto w = kernel_.pair_terms(std::sqrt(r2), 1.0 / hij);
      const Vec<D> grad = pair_gradient(i, j, dx * w.gradient_factor);
      SymTensor term = p_.stress_term[j] * (1.0 / eta[i]);
      // The artificial stress's pair term is m_j f^n (R_i + R_j): its ring weight is on R_i's
      // half (R_j ~ sigma_j / (w_j rho_j^2) cancels m_j's w_j), so an image's sign falls on R_i,
      // and the difference from the conservative |r| term is -2 m_g f^n R_i.
      if (tensile && (factors_.has_tensile[i] | factors_.has_tensile[j]))
        term -= p_.tensile_term[i] *
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

// The class itself is instantiated in sph_system.cpp; these are its members defined here.
template void SphSystem<2>::kick(double);
template void SphSystem<3>::kick(double);
template void SphSystem<2>::drift(double);
template void SphSystem<3>::drift(double);

}  // namespace camouflet::sph
