#pragma once
// Artificial stress against the SPH tensile instability: Monaghan 2000 (JCP
// 159, 290) and Gray, Monaghan & Swift 2001 (CMAME 190, 6641), eqs. (3.1)-(3.3).
//
// In the principal frame of the stress, each tensile principal component gets
//     R'_aa = -epsilon sigma'_aa / rho^2     (sigma'_aa > 0, tension)
//     R'_aa = 0                               (compression)
// and R = Q R' Q^T is rotated back. The pair term m_j (R_i + R_j) f_ij^n . grad W
// with f_ij = W(r_ij) / W(dp), dp the particle spacing, adds a short-range
// repulsion that only acts where particles are in tension and would clump.
// Gray et al. recommend epsilon = 0.3 and n = 4 (their section 3). The pair
// term itself is in pair_terms.hpp (tensile_weight, subtract_tensile_pair).
//
// Here `scale` stands for 1 / rho^2 (or w / eta^2 in the planar form used for
// axisymmetry, sph/sph_system.hpp). In 2-D only the in-plane 2x2 block enters
// the pair terms; in r-z the hoop component (a principal direction there) is
// set by the force stage and enters the artificial stress's hoop term
// (SphSystem::force_pass, docs/theory/sph.md).
#include <cmath>
#include <span>

#include "core/sym_tensor.hpp"

namespace camouflet::sph {

template <int D>
SymTensor artificial_stress(const SymTensor& sigma, double epsilon, double scale);

// Eigen-decomposition of a symmetric 3x3 tensor by cyclic Jacobi rotations:
// values[k] with unit eigenvector vectors[.][k] (column k).
void symmetric_eigen(const SymTensor& a, double values[3], double vectors[3][3]);

// artificial_stress<3>(sigma[k], epsilon, scale[k]) -> out[k] for every k, bit
// for bit, with the eigen-decompositions run on SIMD lanes (artificial_stress_lanes.cpp).
void artificial_stress_3d(std::span<const SymTensor> sigma, std::span<const double> scale, double epsilon,
                          std::span<SymTensor> out);

// The two halves of artificial_stress<3> around the eigen-decomposition:
// true when sigma certainly has no tensile principal stress (R = 0), and R
// from the principal stresses values[k] with directions q[.][k].
bool no_tension(const SymTensor& sigma);
SymTensor rotate_tensile_part(const double values[3], const double q[3][3], double epsilon, double scale);

}  // namespace camouflet::sph
