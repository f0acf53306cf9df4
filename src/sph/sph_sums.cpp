// The particle sums of one cycle (equations in sph_system.hpp): forces,
// position update with optional XSPH, and the kinematics that feed the shared
// material update.
#include <fmt/format.h>

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
  const bool axisymmetric = mode_ == GeometryMode::axisymmetric;
  if (options_.artificial_stress) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double eta = p_.planar_density[i];
      p_.tensile_term[i] = artificial_stress<D>(p_.stress[i], options_.artificial_stress_epsilon,
                                                geometric_weight(p_.position[i]) / (eta * eta));
    }
  }
  prepare_neighbours();
  if (options_.kernel_correction && !correction_current_) compute_correction();

  const bool tensile = options_.artificial_stress;
  const bool volume_form = options_.volume_form;
  const double power = options_.artificial_stress_power;
  const double factor = options_.smoothing_factor;
  const auto& x = p_.position;
  const auto& v = p_.velocity;
  const auto& m = p_.mass;
  const auto& eta = p_.planar_density;
  const auto& h = p_.smoothing_length;
#pragma omp parallel for schedule(dynamic, 128)
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> acc{};
    double mu_max = 0.0;
    int count = 0;
    for (const std::uint32_t j : search_.neighbours(i)) {
      const Vec<D> dx = x[i] - x[j];
      const double r2 = dot(dx, dx);
      const double hij = pair_smoothing_length(h[i], h[j]);
      if (r2 >= support_factor * support_factor * hij * hij) continue;
      ++count;
      const double r = std::sqrt(r2);
      const Vec<D> grad = pair_gradient(i, j, dx * kernel_.gradient_factor(r, hij));
      const Vec<D> dv = v[i] - v[j];
      const double vr = dot(dv, dx);
      double pi_ij = 0.0;
      if (vr < 0.0) {  // approaching pair: Monaghan 1992, eq. (4.2)
        const double mu = hij * vr / (r2 + 0.01 * hij * hij);
        const double c_mean = 0.5 * (p_.wave_speed[i] + p_.wave_speed[j]);
        const PairViscosity q = pair_viscosity(options_, p_.viscosity_alpha[i], p_.viscosity_alpha[j]);
        pi_ij = (-q.alpha * c_mean * mu + q.beta * mu * mu) / (0.5 * (eta[i] + eta[j]));
        mu_max = std::max(mu_max, -mu);
      }
      // S = sigma / rho: volume form (S_i / eta_j + S_j / eta_i), density form (S_i / eta_i + S_j / eta_j).
      SymTensor pair = volume_form ? p_.stress_term[i] * (1.0 / eta[j]) + p_.stress_term[j] * (1.0 / eta[i])
                                   : p_.stress_term[i] * (1.0 / eta[i]) + p_.stress_term[j] * (1.0 / eta[j]);
      if (tensile) {
        const double dp = hij / factor;  // current particle spacing
        const double f = kernel_.value(r, hij) / kernel_.value(dp, hij);
        pair += (p_.tensile_term[i] + p_.tensile_term[j]) * std::pow(f, power);
      }
      acc += (apply<D>(pair, grad) - grad * pi_ij) * m[j];
    }
    if (axisymmetric && x[i][0] > 0.0)  // hoop stress: -sigma_tt / (rho r) e_r
      acc[0] -= p_.stress[i].zz / (p_.density[i] * x[i][0]);
    p_.acceleration[i] = acc;
    p_.compression_rate[i] = mu_max;
    p_.neighbour_count[i] = count;
  }
}

template <int D>
void SphSystem<D>::kick(double dt) {
  const std::size_t n = p_.real;
  velocity_old_.assign(p_.velocity.begin(), p_.velocity.end());  // particles and ghosts, v(n-1/2)
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) p_.velocity[i] += p_.acceleration[i] * dt;
  refresh_ghosts();

  // Viscous heating of this impulse: the kinetic energy the viscous pair forces
  // (evaluated with v(n-1/2) at x(n)) take out over the kick is
  // 1/2 sum_ij m_i m_j Pi_ij vbar_ij . grad W dt with vbar the mean of the old
  // and new velocities; each particle gets its half (Monaghan 1992, eq. 4.6)
  // with that same mean velocity, so the exchange is exact.
  const auto& x = p_.position;
  const auto& m = p_.mass;
  const auto& eta = p_.planar_density;
  const auto& h = p_.smoothing_length;
  const auto& v_old = velocity_old_;
  const auto& v_new = p_.velocity;
  // The artificial stress is a pair force T_ij . grad W with T_ij = f^n (R_i + R_j)
  // that no constitutive law books: its work is booked the same way, as
  // de_i = -1/2 sum_j m_j vbar_ij . T_ij . grad W dt, so that kinetic +
  // internal energy stays conserved (it is reversible over a tension cycle;
  // docs/theory/sph.md).
  const bool tensile = options_.artificial_stress;
  const double power = options_.artificial_stress_power, factor = options_.smoothing_factor;
  // Artificial conductivity (SphOptions::conductivity): specific energy,
  // pressure, density and EOS family of every point, ghosts as their sources;
  // coupling points (FEM) take no part.
  const double alpha_u = options_.conductivity;
  const bool conduct = alpha_u > 0.0;
  std::vector<double> u, pressure, rho;
  std::vector<int> family;
  const std::size_t mirrored = n + ghosts_.size();
  if (conduct) {
    u.resize(mirrored);
    pressure.resize(mirrored);
    rho.resize(mirrored);
    family.resize(mirrored);
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
  }
#pragma omp parallel for schedule(dynamic, 128)
  for (std::size_t i = 0; i < n; ++i) {
    double heat = 0.0;
    for (const std::uint32_t j : search_.neighbours(i)) {
      const Vec<D> dx = x[i] - x[j];
      const double r2 = dot(dx, dx);
      const double hij = pair_smoothing_length(h[i], h[j]);
      if (r2 >= support_factor * support_factor * hij * hij) continue;
      const Vec<D> dv = v_old[i] - v_old[j];
      const double vr = dot(dv, dx);
      if (vr >= 0.0 && !tensile && !conduct) continue;
      const double r = std::sqrt(r2);
      if (conduct && j < mirrored && family[j] == family[i] && u[i] != u[j]) {
        // Price (2008), eqs. 28 and 30, with the planar density of the SPH
        // sums (eta, ring mass in r-z) and dW/dr < 0: heat flows from i to j
        // when u_i > u_j, and m_i du_i = -m_j du_j pair by pair.
        const double rho_ij = 0.5 * (rho[i] + rho[j]);
        const double v_sig = std::sqrt(std::abs(pressure[i] - pressure[j]) / rho_ij);
        heat +=
            m[j] * alpha_u * v_sig * (u[i] - u[j]) / (0.5 * (eta[i] + eta[j])) * kernel_.derivative(r, hij);
      }
      if (vr >= 0.0 && !tensile) continue;
      const Vec<D> grad = pair_gradient(i, j, dx * kernel_.gradient_factor(r, hij));
      const Vec<D> mean_dv = (dv + (v_new[i] - v_new[j])) * 0.5;
      if (vr < 0.0) {
        const double mu = hij * vr / (r2 + 0.01 * hij * hij);
        const double c_mean = 0.5 * (p_.wave_speed[i] + p_.wave_speed[j]);
        const PairViscosity q = pair_viscosity(options_, p_.viscosity_alpha[i], p_.viscosity_alpha[j]);
        const double pi_ij = (-q.alpha * c_mean * mu + q.beta * mu * mu) / (0.5 * (eta[i] + eta[j]));
        heat += 0.5 * m[j] * pi_ij * dot(mean_dv, grad);
      }
      if (tensile) {
        const SymTensor& ri = p_.tensile_term[i];
        const SymTensor& rj = p_.tensile_term[j];
        if (ri.xx == 0.0 && ri.yy == 0.0 && ri.xy == 0.0 && rj.xx == 0.0 && rj.yy == 0.0 && rj.xy == 0.0 &&
            ri.zz == 0.0 && rj.zz == 0.0)
          continue;
        const double f = kernel_.value(r, hij) / kernel_.value(hij / factor, hij);
        heat -= 0.5 * m[j] * std::pow(f, power) * dot(mean_dv, apply<D>(ri + rj, grad));
      }
    }
    p_.heating[i] += heat * dt;
  }
}

template <int D>
void SphSystem<D>::drift(double dt) {
  const std::size_t n = p_.real;
  correction_current_ = false;
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
      const double f = kernel_.gradient_factor(std::sqrt(r2), hij) * p_.mass[j] / p_.planar_density[j];
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
  std::vector<double> eta_new(n), h_new(n);

  // The rates are evaluated at the mid-step positions x(n+1/2) = x(n+1) - v dt/2
  // with v(n+1/2): second-order in time, and the p dV work then matches the
  // kinetic energy the forces exchange far better than at x(n+1).
  std::vector<Vec<D>> x_end(p_.position.begin(), p_.position.begin() + static_cast<std::ptrdiff_t>(n));
  for (std::size_t i = 0; i < n; ++i) p_.position[i] -= p_.velocity[i] * (0.5 * dt);
  refresh_ghosts();
  const bool corrected = options_.kernel_correction;
  if (corrected) compute_correction();
#pragma omp parallel for schedule(dynamic, 128)
  for (std::size_t i = 0; i < n; ++i) {
    double eta_rate = 0.0;
    double L[3][3] = {};
    for (const std::uint32_t j : search_.neighbours(i)) {
      const Vec<D> dx = x[i] - x[j];
      const double r2 = dot(dx, dx);
      const double hij = pair_smoothing_length(h[i], h[j]);
      if (r2 >= support_factor * support_factor * hij * hij) continue;
      const Vec<D> grad = dx * kernel_.gradient_factor(std::sqrt(r2), hij);
      const Vec<D> dv = v[i] - v[j];
      // Volume form: weights V_j = m_j / eta_j (times eta_i for the rate); density form: m_j / eta_i.
      const double weight = options_.volume_form ? m[j] / eta[j] : m[j] / eta[i];
      if (corrected) {
        // Continuity with the pair gradient of the momentum sum (conjugate);
        // L with particle i's own correction, exact for linear fields.
        eta_rate += weight * dot(dv, pair_gradient(i, j, grad));
        const Vec<D> own = apply<D>(p_.correction[i], grad);
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) L[a][b] -= weight * dv[a] * own[b];
      } else {
        eta_rate += weight * dot(dv, grad);
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) L[a][b] -= weight * dv[a] * grad[b];
      }
    }
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
    eta_new[i] = eta[i] * std::exp(dt * eta_rate);
    double hi = h[i];
    if (options_.variable_smoothing_length) {
      const double h0 = p_.reference_smoothing_length[i];
      hi = h0 * std::pow(p_.reference_planar_density[i] / eta_new[i], 1.0 / D);
      hi = std::clamp(hi, options_.h_min_factor * h0, options_.h_max_factor * h0);
    }
    h_new[i] = hi;
  }

  for (std::size_t i = 0; i < n; ++i) {
    p_.planar_density[i] = eta_new[i];
    p_.smoothing_length[i] = h_new[i];
    p_.position[i] = x_end[i];
  }
  refresh_ghosts();
  correction_current_ = false;

  // The shared constitutive update, one batch per material.
  const MaterialContext ctx{dt, time};
  for (std::size_t mat = 0; mat < batches_.size(); ++mat) {
    auto& pts = batches_[mat];
    const auto& members = batch_particles_[mat];
    if (members.empty()) continue;
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < members.size(); ++k) {
      const std::size_t i = members[k];
      const double rho = p_.planar_density[i] / geometric_weight(x[i]);
      pts.density_previous[k] = p_.density[i];
      pts.density[k] = rho;
      pts.strain_rate[k] = p_.strain_rate[i];
      pts.spin[k] = p_.spin[i];
      pts.artificial_viscosity[k] = 0.0;  // SPH viscosity is pairwise: its heating is added below
      pts.characteristic_length[k] = p_.smoothing_length[i];
      pts.specific_energy[k] += p_.heating[i];
      p_.heating[i] = 0.0;
      p_.density[i] = rho;
    }
    materials_[mat]->update(pts, ctx);
  }
  gather_material_state();
}

// The class itself is instantiated in sph_system.cpp; these are its members defined here.
template void SphSystem<2>::compute_correction();
template void SphSystem<3>::compute_correction();
template void SphSystem<2>::compute_accelerations();
template void SphSystem<3>::compute_accelerations();
template void SphSystem<2>::kick(double);
template void SphSystem<3>::kick(double);
template void SphSystem<2>::drift(double);
template void SphSystem<3>::drift(double);
template void SphSystem<2>::update_state(double, double);
template void SphSystem<3>::update_state(double, double);

}  // namespace camouflet::sph
