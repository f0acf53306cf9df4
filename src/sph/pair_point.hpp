#pragma once
// The packed per-point record of the SPH pair loops (pair_lanes.hpp): one
// record per particle, ghost and coupling point, refreshed before each pass.

namespace camouflet::sph {

// What the pair loops read of one point (particle, ghost or coupling point),
// refreshed before each pass: position, h, velocity and mass in the first 64
// bytes (all that the kinematics need besides eta), S = sigma / rho, eta and
// the wave speed in the second.
template <int D>
struct alignas(64) PairPoint {
  static constexpr int x = 0;               // m, D entries
  static constexpr int h = D;               // m
  static constexpr int v = D + 1;           // m/s, D entries
  static constexpr int m = 2 * D + 1;       // kg
  static constexpr int stress = 2 * D + 2;  // S, m^2/s^2: xx yy zz xy yz zx
  static constexpr int eta = 2 * D + 8;     // planar density
  static constexpr int c = 2 * D + 9;       // m/s, wave speed
  double f[2 * D + 10];
};

}  // namespace camouflet::sph
