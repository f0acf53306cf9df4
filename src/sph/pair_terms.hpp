#pragma once
// The SPH pair terms, written once for one pair (T = double, M = bool: the
// scalar rows of sph_forces.cpp, sph_kinematics.cpp and sph_motion.cpp) and for
// a group of pairs on SIMD lanes (T = Lanes, M = LaneMask: pair_lanes.cpp). A
// term takes the two points' values, an i-side value as a plain double beside
// the lanes of the neighbours (it broadcasts), and gives the pair's share; the
// rows gather the values and add the shares into their sums. A lane does one
// pair's operations in the order the scalar row does (the sph layer is built
// with -ffp-contract=off), so a term has the same bits either way; only the
// order in which a row adds its terms up differs. The equations are those of
// sph_system.hpp; `inside` marks the pairs within the kernel's support.
#include <array>
#include <cmath>

#include "core/sym_tensor.hpp"
#include "sph/pair_lanes.hpp"

namespace camouflet::sph {

// The components xx yy zz xy yz zx of a tensor, the order the pair terms read.
inline std::array<double, 6> components(const SymTensor& s) { return {s.xx, s.yy, s.zz, s.xy, s.yz, s.zx}; }

// s . g, s given by its components xx yy zz xy yz zx (the order of core/sym_tensor_vec.hpp's apply).
template <int D, class S, class T>
inline void apply_components(const S s[6], const T g[D], T out[D]) {
  if constexpr (D == 2) {
    out[0] = s[0] * g[0] + s[3] * g[1];
    out[1] = s[3] * g[0] + s[1] * g[1];
  } else {
    out[0] = s[0] * g[0] + s[3] * g[1] + s[5] * g[2];
    out[1] = s[3] * g[0] + s[1] * g[1] + s[4] * g[2];
    out[2] = s[5] * g[0] + s[4] * g[1] + s[2] * g[2];
  }
}

// The artificial viscosity of Monaghan (1992), eq. (4.2): for a pair inside the support whose
// points approach (v_ij . x_ij < 0),
//   mu = h_ij v_ij . x_ij / (r^2 + 0.01 h_ij^2),  Pi_ij = (-alpha c_mean mu + beta mu^2) / eta_mean,
// and the pair's dissipative term Pi_ij grad W; mu and the term are zero otherwise.
template <int D, class T, class M>
struct ViscousPair {
  M approaching;
  T mu;
  T dissipation[D];
};

template <int D, class T, class M, class Ti, class A>
inline ViscousPair<D, T, M> viscous_pair(M inside, const T dx[D], const T dv[D], const T grad[D], T r2, T hij,
                                         Ti c_i, T c_j, Ti eta_i, T eta_j, A alpha, A beta) {
  const T zero{};
  T vr = zero;
  for (int a = 0; a < D; ++a) vr += dv[a] * dx[a];
  ViscousPair<D, T, M> out;
  out.approaching = inside & (vr < 0.0);
  out.mu = out.approaching ? hij * vr / (r2 + 0.01 * hij * hij) : zero;
  const T c_mean = 0.5 * (c_i + c_j);
  const T pi_ij = (-alpha * c_mean * out.mu + beta * out.mu * out.mu) / (0.5 * (eta_i + eta_j));
  for (int a = 0; a < D; ++a) out.dissipation[a] = out.approaching ? grad[a] * pi_ij : zero;
  return out;
}

// 1 / |r| of a point at radius r (r-z; an image across the axis stands at r < 0), 0 on the axis.
inline double inverse_ring_radius(double r) { return r != 0.0 ? 1.0 / std::abs(r) : 0.0; }
inline Lanes inverse_ring_radius(Lanes r) {
  const Lanes a = abs_of(r);
  const Lanes one = Lanes{} + 1.0;
  return a != 0.0 ? one / (a != 0.0 ? a : one) : Lanes{};
}

// r-z: the hoop shares of a pair (SphSystem::force_pass(), "The hoop terms of the artificial
// viscosity and stress"), for i and for j; inv_r = 1 / |r| (inverse_ring_radius), 0 on the axis.
template <class T>
struct HoopShares {
  T i, j;
};

// The artificial stress's: (m_j / |r_j|) (r_j - r_i) f^n dW/dr_i for i and its mirror for j, with
// dx_r = r_i - r_j and grad_r = dW/dr_i (the pair's gradient, radial); the row multiplies each
// sum by -R_tt of its particle.
template <class T, class Ti>
inline HoopShares<T> tensile_hoop_shares(T dx_r, T grad_r, T fn, T m_j, Ti m_i, T inv_r_j, Ti inv_r_i) {
  const T term = -(dx_r * grad_r) * fn;
  return {term * m_j * inv_r_j, term * (m_i * inv_r_i)};
}

// The artificial viscosity's. The pair's viscous term m_j Pi_ij grad W, Pi_ij = K_ij / eta_mean,
// weighs its neighbours by ring mass; its planar (Cartesian) form (m_j / w_j) K_ij / rho_mean
// grad W, w = 2 pi |r|, rho = eta / w, gives no force in a uniform compression. The shares are
// the planar form's radial term minus the ring form's: i gets -d_r m_j (eta_mean / (w_j rho_mean)
// - 1), j gets +d_r m_i (eta_mean / (w_i rho_mean) - 1), with d_r = Pi_ij dW/dr_i the pair's
// viscous term (radial). eta_mean / (w rho_mean) does not change when 1 / w is scaled: 1 / |r|
// stands for 1 / w.
template <class T, class Ti>
inline HoopShares<T> viscous_hoop_shares(T d_r, T m_j, Ti m_i, T eta_j, Ti eta_i, T inv_r_j, Ti inv_r_i) {
  const T ratio = (eta_i + eta_j) / (eta_i * inv_r_i + eta_j * inv_r_j);
  const T zero{};
  HoopShares<T> out;
  out.i = inv_r_j != 0.0 ? -d_r * m_j * (ratio * inv_r_j - 1.0) : zero;
  out.j = inv_r_j != 0.0 ? d_r * m_i * (ratio * inv_r_i - 1.0) : zero;
  return out;
}

// The artificial-stress pair weight f^n, f = W(r) / W(dp) (artificial_stress.hpp); a small
// integer n (4 by default) is taken by repeated products, which std::pow would not give bit for bit.
template <class T>
inline T tensile_weight(T f, double power, int integer_power) {
  if (integer_power == 0) return pow_of(f, power);
  T fn = f;
  for (int k = 1; k < integer_power; ++k) fn *= f;
  return fn;
}

// The artificial stress's part of the pair's dissipative term where the pair `has` one:
// d -= f^n (R_i + R_j) . grad W, with r_sum the components of R_i + R_j.
template <int D, class T, class M>
inline void subtract_tensile_pair(M has, const T r_sum[6], const T grad[D], T fn, T dissipation[D]) {
  T tension[D];
  apply_components<D>(r_sum, grad, tension);
  for (int a = 0; a < D; ++a) dissipation[a] = has ? dissipation[a] - tension[a] * fn : dissipation[a];
}

// The momentum pair term per unit mass product: S_pair . grad W - d, with S = sigma / rho paired
// as S_i / eta_j + S_j / eta_i (volume form) or S_i / eta_i + S_j / eta_j (density form); zero
// outside the support. s_i, s_j: the components of the stress terms.
template <int D, class T, class M, class Ti>
inline void momentum_pair(M inside, bool volume_form, const Ti s_i[6], const T s_j[6], Ti inv_eta_i, T inv_eta_j,
                          const T grad[D], const T dissipation[D], T force[D]) {
  T pair[6];
  for (int c = 0; c < 6; ++c)
    pair[c] = volume_form ? s_i[c] * inv_eta_j + s_j[c] * inv_eta_i : s_i[c] * inv_eta_i + s_j[c] * inv_eta_j;
  apply_components<D>(pair, grad, force);
  for (int a = 0; a < D; ++a) force[a] = inside ? force[a] - dissipation[a] : T{};
}

// Continuity and velocity gradient: the pair's rate v_ij . grad W (grad_rate: the gradient the
// continuity pairs with, the momentum sum's), its shares weight_i rate for i and weight_j rate
// for j, and the weighted velocity differences whose outer products with each point's gradient
// the rows subtract from L_i and L_j.
template <int D, class T>
struct KinematicPair {
  T rate_i, rate_j;
  T weighted_dv_i[D], weighted_dv_j[D];
};

template <int D, class T, class W>
inline KinematicPair<D, T> kinematic_pair(const T dv[D], const T grad_rate[D], W weight_i, W weight_j) {
  KinematicPair<D, T> out;
  T rate{};
  for (int a = 0; a < D; ++a) rate += dv[a] * grad_rate[a];
  out.rate_i = weight_i * rate;
  out.rate_j = weight_j * rate;
  for (int a = 0; a < D; ++a) {
    out.weighted_dv_i[a] = weight_i * dv[a];
    out.weighted_dv_j[a] = weight_j * dv[a];
  }
  return out;
}

}  // namespace camouflet::sph
