#include "model/isoparametric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camouflet {

namespace {
constexpr std::array<std::array<double, 3>, 8> corners{
    {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};

int npe_of(int dim) {
  return dim == 3 ? 8 : 4;
}

// Jacobian J_ij = dx_i/dxi_j.
void jacobian(int dim, std::span<const double> nodes, const Natural& xi, double j[3][3]) {
  double dn[8][3];
  shape_derivatives(dim, xi, dn);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) j[i][k] = (i == k && i >= dim) ? 1.0 : 0.0;
  for (int a = 0; a < npe_of(dim); ++a)
    for (int i = 0; i < dim; ++i)
      for (int k = 0; k < dim; ++k) j[i][k] += nodes[static_cast<std::size_t>(a * dim + i)] * dn[a][k];
}

double det3(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
}  // namespace

Natural corner_natural(int dim, int a) {
  Natural c = corners[static_cast<std::size_t>(a)];
  if (dim == 2) c[2] = 0.0;
  return c;
}

void shape_functions(int dim, const Natural& xi, double* n) {
  for (int a = 0; a < npe_of(dim); ++a) {
    const auto& c = corners[static_cast<std::size_t>(a)];
    double v = 0.25 * (1.0 + c[0] * xi[0]) * (1.0 + c[1] * xi[1]);
    if (dim == 3) v *= 0.5 * (1.0 + c[2] * xi[2]);
    n[a] = v;
  }
}

void shape_derivatives(int dim, const Natural& xi, double (*dn)[3]) {
  for (int a = 0; a < npe_of(dim); ++a) {
    const auto& c = corners[static_cast<std::size_t>(a)];
    const double f0 = 1.0 + c[0] * xi[0], f1 = 1.0 + c[1] * xi[1];
    if (dim == 2) {
      dn[a][0] = 0.25 * c[0] * f1;
      dn[a][1] = 0.25 * c[1] * f0;
      dn[a][2] = 0.0;
    } else {
      const double f2 = 1.0 + c[2] * xi[2];
      dn[a][0] = 0.125 * c[0] * f1 * f2;
      dn[a][1] = 0.125 * c[1] * f0 * f2;
      dn[a][2] = 0.125 * c[2] * f0 * f1;
    }
  }
}

double jacobian_determinant(int dim, std::span<const double> nodes, const Natural& xi) {
  double j[3][3];
  jacobian(dim, nodes, xi, j);
  return det3(j);
}

std::optional<Natural> inverse_map(int dim, std::span<const double> nodes, std::span<const double> x) {
  const int npe = npe_of(dim);
  // Element size, to make the convergence test scale-free.
  double size = 0.0;
  for (int i = 0; i < dim; ++i) {
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (int a = 0; a < npe; ++a) {
      lo = std::min(lo, nodes[static_cast<std::size_t>(a * dim + i)]);
      hi = std::max(hi, nodes[static_cast<std::size_t>(a * dim + i)]);
    }
    size = std::max(size, hi - lo);
  }
  if (!(size > 0.0)) return std::nullopt;
  Natural xi{0.0, 0.0, 0.0};
  double n[8];
  for (int iter = 0; iter < 50; ++iter) {
    shape_functions(dim, xi, n);
    double r[3] = {0, 0, 0};
    for (int i = 0; i < dim; ++i) {
      double xm = 0.0;
      for (int a = 0; a < npe; ++a) xm += n[a] * nodes[static_cast<std::size_t>(a * dim + i)];
      r[i] = x[static_cast<std::size_t>(i)] - xm;
    }
    const double rnorm = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (rnorm <= 1e-13 * size) return xi;
    double j[3][3];
    jacobian(dim, nodes, xi, j);
    const double d = det3(j);
    if (!(std::abs(d) > 0.0) || !std::isfinite(d)) return std::nullopt;
    // Cramer's rule for J dxi = r.
    double dxi[3];
    for (int k = 0; k < 3; ++k) {
      double m[3][3];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) m[a][b] = (b == k) ? r[a] : j[a][b];
      dxi[k] = det3(m) / d;
    }
    for (int k = 0; k < dim; ++k) xi[static_cast<std::size_t>(k)] += dxi[k];
    // Far outside the element the bilinear map may fold; such a point is not in it.
    for (int k = 0; k < dim; ++k)
      if (!std::isfinite(xi[static_cast<std::size_t>(k)]) || std::abs(xi[static_cast<std::size_t>(k)]) > 1e3)
        return std::nullopt;
  }
  return std::nullopt;
}

void gather_element(int dim, std::span<const double> coordinates, std::span<const std::int64_t> connectivity,
                    std::int64_t e, double* out) {
  const int npe = npe_of(dim);
  for (int a = 0; a < npe; ++a) {
    const auto node = connectivity[static_cast<std::size_t>(e * npe + a)];
    for (int i = 0; i < dim; ++i) out[a * dim + i] = coordinates[static_cast<std::size_t>(node * dim + i)];
  }
}

bool element_centre_in_box(int dim, std::span<const double> coordinates, std::span<const std::int64_t> connectivity,
                           std::int64_t e, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  const int npe = npe_of(dim);
  double x[8 * 3];
  gather_element(dim, coordinates, connectivity, e, x);
  for (int i = 0; i < dim; ++i) {
    double c = 0.0;
    for (int a = 0; a < npe; ++a) c += x[a * dim + i] / npe;
    if (!(c >= lo[static_cast<std::size_t>(i)] && c <= hi[static_cast<std::size_t>(i)])) return false;
  }
  return true;
}

std::optional<ElementLocation> locate_in_element(int dim, std::span<const double> coordinates,
                                                 std::span<const std::int64_t> connectivity, std::int64_t e,
                                                 std::span<const double> x, double tol) {
  const int npe = npe_of(dim);
  double nodes[24];
  gather_element(dim, coordinates, connectivity, e, nodes);
  // Bounding-box rejection first: most elements a search tries are far away.
  for (int i = 0; i < dim; ++i) {
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (int a = 0; a < npe; ++a) {
      lo = std::min(lo, nodes[a * dim + i]);
      hi = std::max(hi, nodes[a * dim + i]);
    }
    const double slack = tol * (hi - lo);
    if (x[static_cast<std::size_t>(i)] < lo - slack || x[static_cast<std::size_t>(i)] > hi + slack)
      return std::nullopt;
  }
  const auto xi = inverse_map(dim, std::span<const double>(nodes, static_cast<std::size_t>(npe * dim)), x);
  if (!xi) return std::nullopt;
  for (int k = 0; k < dim; ++k)
    if (!(std::abs((*xi)[static_cast<std::size_t>(k)]) <= 1.0 + tol)) return std::nullopt;
  return ElementLocation{e, *xi};
}

std::optional<ElementLocation> locate_point(int dim, std::span<const double> coordinates,
                                            std::span<const std::int64_t> connectivity,
                                            std::span<const double> x, double tol) {
  const auto n_elements =
      static_cast<std::int64_t>(connectivity.size() / static_cast<std::size_t>(npe_of(dim)));
  for (std::int64_t e = 0; e < n_elements; ++e)
    if (auto found = locate_in_element(dim, coordinates, connectivity, e, x, tol)) return found;
  return std::nullopt;
}

}  // namespace camouflet
