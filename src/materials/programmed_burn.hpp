#pragma once
// Programmed burn of a high explosive (issue 4): each point is lit when the
// detonation front, running at the detonation velocity D in straight lines
// from the detonation points, reaches it, and its burn fraction then ramps
// from 0 to 1 while the front crosses a few point sizes.
//
// Lighting time: t_l = min_k (t_k + |x - x_k| / D).
// Burn fraction: F = min(1, max(0, (t - t_l) D / (n_burn L))), L the point's
// characteristic length (element size or smoothing length).
// This is the LS-DYNA programmed-burn factor F1 = 2 (t - t_l) D A_max / (3 V)
// (LS-DYNA Theory Manual, *MAT_HIGH_EXPLOSIVE_BURN), which for a square or
// cubic cell (A_max / V = 1 / L) is n_burn = 1.5. We default to n_burn = 3
// (key `burn_width_factor`): in the 1-D TNT column of
// tests/fem/test_detonation_column.cpp (0.1 m, 100-400 cells) n_burn = 1.5
// stalls on the finest mesh (the time step collapses: more than 100 cycles
// per cell) and peaks at 1.05 P_CJ on 200 cells; n_burn = 2 peaks at 1.06
// P_CJ on 400 cells; n_burn = 3 peaks at 0.90-1.02 P_CJ with the front within
// 0.25 % of D on all three meshes. The energy balance holds within 0.06 % for
// all of them. LS-DYNA's volumetric (beta) burn is not used: the front
// position alone lights the explosive.
#include <array>
#include <vector>

#include "materials/material.hpp"

namespace camouflet {

inline constexpr double default_burn_width_factor = 3.0;

// s; +infinity when there is no detonation point (the point never burns).
double lighting_time(const std::array<double, 3>& position, const std::vector<DetonationPoint>& detonations,
                     double detonation_velocity);

// Burn fraction F in [0, 1] at `time` (s). A point of zero size burns at once when lit.
double burn_fraction(double time, double lighting_time, double detonation_velocity, double burn_width_factor,
                     double characteristic_length);

}  // namespace camouflet
