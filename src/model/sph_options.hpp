#pragma once
// The numerical settings of the SPH package ([sph] of a case), with the
// defaults of the literature: a record of the model, read once by the case
// reader (sph::read_sph_options) and used by the SPH package. It sits here,
// below the packages, so that the model carries it typed; the namespace says
// whose settings they are.

namespace camouflet::sph {

// The smoothing kernel (sph/kernel.hpp).
enum class KernelKind { cubic_spline, wendland_c2 };

struct SphOptions {
  KernelKind kernel = KernelKind::cubic_spline;
  // Initial smoothing length h0 = smoothing_factor x particle spacing. 1.2 puts
  // ~2.4 spacings inside the support 2h: ~20 neighbours in 2-D, ~60 in 3-D
  // (Monaghan 2005, Rep. Prog. Phys. 68, section 2.3 suggests h ~ 1.2-1.5 dx).
  double smoothing_factor = 1.2;
  // Variable smoothing length h = h0 (rho0 / rho)^(1/d) (Monaghan 2005, eq. 2.19
  // in its SPH-summation form), kept within [h_min_factor, h_max_factor] x h0.
  bool variable_smoothing_length = true;
  double h_min_factor = 0.25;
  double h_max_factor = 4.0;
  // Monaghan artificial viscosity (Monaghan 1992, eq. 4.2): Pi_ij = (-alpha c mu + beta mu^2) / rho_ij.
  double viscosity_alpha = 1.0;
  double viscosity_beta = 2.0;
  // Time-dependent viscosity (Morris & Monaghan 1997, J. Comput. Phys. 136, 41-50, "A switch
  // to reduce SPH viscosity"): each particle carries its own alpha_i, relaxing to
  // viscosity_alpha_min over tau = h / (viscosity_switch_decay c) and driven up towards
  // viscosity_alpha by compression, d alpha/dt = -(alpha - alpha_min)/tau + max(-div v, 0)
  // (alpha_max - alpha) (the (alpha_max - alpha) factor of Rosswog et al. 2000, MNRAS 317,
  // 333). A pair uses alpha_ij = (alpha_i + alpha_j)/2 and beta_ij = beta alpha_ij / alpha_max.
  // Off by default: alpha = viscosity_alpha everywhere.
  bool viscosity_switch = false;
  // r-z only: the viscosity's hoop term (sph_forces.cpp, "The hoop terms of the artificial
  // viscosity and stress"): the radial viscous force in the planar (Cartesian) weights, so that a
  // uniform compression gives no force next to the axis (without it: ~q/r towards the axis).
  // Off by default: on, the r-z Sedov blast's shock runs 11 % further along the equator than
  // along the axis (0.505 against 0.455 m; 0.485 m in both without), docs/theory/sph.md.
  bool viscosity_hoop = false;
  // r-z only, volume form only: the stress's hoop term with the ring sum's own weights,
  // -(2 pi / eta_i) sum_j V_j (r_j - r_i) dW/dr_i sigma_tt,j, and its energy conjugate, the hoop
  // strain rate (2 pi rho_i / eta_i) sum_j V_j (r_j - r_i) dW/dr_i v_r,j, in place of the point
  // values -sigma_tt / (rho r) and v_r / r; the density then follows that hoop rate instead of
  // eta / (2 pi r) (docs/theory/sph.md, "The hoop term smoothed as the ring sum is"). Off by default.
  bool smoothed_hoop = false;
  // r-z, with smoothed_hoop: the band next to the axis, in smoothing lengths, in which the point
  // hoop term hands over to the smoothed one. Each particle has the share beta = min(1, r / (width
  // h)); a pair's smoothed terms carry min(beta_i, beta_j), and the part 1 - S_beta / S of the
  // particle's smoothed weight sum S that the shares took away goes to the point term
  // -sigma_tt / (rho r) and the point rate v_r / r, with the same weight in both (conjugate). The
  // ring sums hold no self term, so without the band a particle's own hoop compression never
  // reaches its own force and nothing holds it off the axis (tests/sph/test_smoothed_hoop_band.cpp).
  // 0: no band.
  double smoothed_hoop_width = 0.0;
  double viscosity_alpha_min = 0.1;
  double viscosity_switch_decay = 0.2;
  // Artificial stress against the tensile instability (Gray, Monaghan & Swift
  // 2001, CMAME 190, eqs. 3.1-3.3; Monaghan 2000, JCP 159): R = -eps sigma'/rho^2
  // on tensile principal stresses, weighted by (W(r)/W(dp))^n. Its pair work
  // is booked in the internal energy (kick()), so the energy balance closes.
  // On by default: without it an elastic plate in tension clumps and its
  // vibration is destroyed within a period (tests/sph/test_tensile_stability.cpp);
  // its price is a softening of tensile stress by ~eps/2 (docs/theory/sph.md).
  bool artificial_stress = true;
  double artificial_stress_epsilon = 0.3;
  double artificial_stress_power = 4.0;
  // Artificial thermal conductivity (Price 2008, J. Comput. Phys. 227, 10040,
  // eqs. 28 and 30): du_i/dt = sum_j m_j alpha_u v_sig (u_i - u_j) / rho_ij dW/dr,
  // v_sig = sqrt(|p_i - p_j| / rho_ij), between particles of one EOS type
  // (their specific energies share a reference). It spreads a spike of
  // specific energy that the particles cannot resolve (a point blast's few
  // hot particles keep most of its energy without it: docs/theory/sph.md,
  // "Sedov"). Pairwise antisymmetric, so energy is conserved exactly.
  // 0 = off (default); Price recommends alpha_u ~ 1.
  double conductivity = 0.0;
  // Momentum/continuity pair (sph_system.hpp): true = volume form (Colagrossi &
  // Landrini 2003), robust at density jumps; false = classic density form
  // sigma_i/rho_i^2 + sigma_j/rho_j^2 (Monaghan 1992). In r-z only the volume
  // form gives the images across the axis their signed ring weight (the first
  // particle columns then feel the right stress divergence); the density form
  // keeps |r| there (its r_j weight multiplies sigma_i, which the images cannot
  // carry), and the solver warns (docs/theory/sph.md, "The first columns").
  bool volume_form = true;
  // XSPH velocity smoothing for the position update (Monaghan 1989); 0 = off.
  double xsph = 0.0;
  // Kernel-gradient correction of the velocity gradient (Randles & Libersky
  // 1996, CMAME 139; Bonet & Lok 1999): exact for linear velocity fields.
  bool kernel_correction = false;
  // Neighbour-list skin as a fraction of the smallest initial smoothing length.
  double skin_factor = 0.3;
  // Re-sort the particles in memory by neighbour-search cell after this many
  // list rebuilds (0 = never), so that the neighbour sums read memory nearly
  // in order. Results change only by round-off (the order of the sums); ids
  // in output, gauges and checkpoints are unaffected, but code that keeps
  // per-particle arrays by memory index across steps must map them through
  // ParticleArrays::id. Off by default: fills are generated in cell order
  // already, and the gain appears only after heavy mixing (docs/theory/sph.md).
  int sort_interval = 0;
};

}  // namespace camouflet::sph
