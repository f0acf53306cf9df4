#pragma once
// Programmed burn of a high explosive: each point is lit when the
// detonation front, running at the detonation velocity D in straight lines
// from the detonation points, reaches it; its burn fraction is the larger of
// a time ramp while the front crosses a few point sizes and the volumetric
// ("beta") fraction of its compression.
//
// Lighting time: t_l = min_k (t_k + |x - x_k| / D).
// Burn fraction: F = max(F_t, F_v) with
//   F_t = min(1, max(0, (t - t_l) D / (n_burn L))), L the point's
//         characteristic length (element size or smoothing length): the
//         LS-DYNA programmed-burn factor F1 = 2 (t - t_l) D A_max / (3 V)
//         (LS-DYNA Theory Manual, *MAT_HIGH_EXPLOSIVE_BURN), which for a
//         square or cubic cell (A_max / V = 1 / L) is n_burn = 1.5, our default
//         (key `burn_width_factor`);
//   F_v = (1 - V) / (1 - V_CJ), V = rho0 / rho (volume_burn_fraction below).
// The time ramp alone lets the front crush the pressureless cell ahead of it:
// the overshoot then grows with travel and the step collapses at fine cells
// (docs/theory/explosive-and-steel.md, "Burn under refinement").
#include <array>
#include <vector>

#include "materials/material.hpp"

namespace camouflet {

inline constexpr double default_burn_width_factor = 1.5;

// s; +infinity when there is no detonation point (the point never burns).
double lighting_time(const std::array<double, 3>& position, const std::vector<DetonationPoint>& detonations,
                     double detonation_velocity);

// Burn fraction F in [0, 1] at `time` (s). A point of zero size burns at once when lit.
double burn_fraction(double time, double lighting_time, double detonation_velocity, double burn_width_factor,
                     double characteristic_length);

// Volumetric ("beta") burn fraction of explosive compressed to the relative
// volume V = rho0 / rho: F_v = (1 - V) / (1 - V_CJ), in [0, 1] (Wilkins 1964,
// "Calculation of elastic-plastic flow", sec. on detonation; the beta burn of
// LS-DYNA's *MAT_HIGH_EXPLOSIVE_BURN, F = max(F1, F2) with F2 = beta). A cell
// that the shock ahead of the programmed front crushes then burns and
// pushes back instead of collapsing at zero pressure.
double volume_burn_fraction(double relative_volume, double cj_relative_volume);

}  // namespace camouflet
