#pragma once
// Isoparametric geometry of the 4-node quadrilateral and the 8-node
// hexahedron, used outside the element kernels: locating Lagrangian gauges in
// the initial mesh (output/), checking elements for inversion before the first
// cycle (case/). Node order (also the FemMesh convention):
//   quad4: (-1,-1) (1,-1) (1,1) (-1,1)                    counter-clockwise
//   hex8:  the quad4 order at zeta = -1, then at zeta = +1 (right-handed)
#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace camouflet {

using Natural = std::array<double, 3>;  // (xi, eta, zeta); zeta unused in 2-D

// Natural coordinates of corner `a` (0-based) of a quad4 (dim 2) or hex8 (dim 3).
Natural corner_natural(int dim, int a);

// Shape functions N_a(xi) (4 or 8 values) and their derivatives dN_a/dxi_j.
void shape_functions(int dim, const Natural& xi, double* n);
void shape_derivatives(int dim, const Natural& xi, double (*dn)[3]);

// Jacobian determinant det(dx/dxi) at xi; `nodes` holds npe * dim coordinates.
double jacobian_determinant(int dim, std::span<const double> nodes, const Natural& xi);

// Inverse isoparametric map by Newton's method (exact in one step for
// parallelograms and parallelepipeds; a few steps for distorted elements).
// Returns nothing when Newton does not converge.
std::optional<Natural> inverse_map(int dim, std::span<const double> nodes, std::span<const double> x);

struct ElementLocation {
  std::int64_t element = -1;  // 0-based
  Natural xi{};
};

// Element e's natural coordinates of x when its closure contains x (tolerance `tol` in natural
// coordinates), else nothing.
std::optional<ElementLocation> locate_in_element(int dim, std::span<const double> coordinates,
                                                 std::span<const std::int64_t> connectivity, std::int64_t e,
                                                 std::span<const double> x, double tol = 1e-8);

// The element whose closure contains x (tolerance `tol` in natural
// coordinates), searching every element; nothing when x lies outside the mesh.
std::optional<ElementLocation> locate_point(int dim, std::span<const double> coordinates,
                                            std::span<const std::int64_t> connectivity,
                                            std::span<const double> x, double tol = 1e-8);

// Gathers the coordinates (npe * dim) of element e from flat arrays.
void gather_element(int dim, std::span<const double> coordinates, std::span<const std::int64_t> connectivity,
                    std::int64_t e, double* out);

// Whether element e's centre (the mean of its nodes) lies in the box [lo, hi] (member gauges).
bool element_centre_in_box(int dim, std::span<const double> coordinates, std::span<const std::int64_t> connectivity,
                           std::int64_t e, const std::array<double, 3>& lo, const std::array<double, 3>& hi);

}  // namespace camouflet
