#pragma once
// What the SPH pair loops read of each point besides the particle arrays: the
// packed record of the SIMD loops (pair_lanes.hpp) and the pair weights, one
// entry per particle, ghost and coupling point, refreshed before each pass
// (SphSystem::fill_point_factors).
#include <vector>

namespace camouflet::sph {

// What the pair loops read of one point (particle, ghost or coupling point),
// refreshed before each pass: position, h, velocity and mass in the first 64
// bytes (all that the kinematics need besides eta), S = sigma / rho, eta and
// the wave speed in the second. The kinematics pass refreshes only the first
// line and eta; S and the wave speed are written for the force pass.
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

template <int D>
struct PointFactors {
  std::vector<double> sum_density;         // eta_q (SphSystem::quadrature_density)
  std::vector<double> inverse_density;     // 1 / eta_q
  std::vector<double> volume;              // m / eta_q, m^3 (m^2 per radian x 2 pi in r-z)
  std::vector<double> inverse_radius;      // r-z: 1 / |r|, 1/m (inverse_ring_radius), for the scalar force row
  std::vector<unsigned char> has_tensile;  // the artificial stress R is not zero
  std::vector<PairPoint<D>> packed;        // the SIMD loops' records (kernel correction off)
};

}  // namespace camouflet::sph
