#include "model/detonation_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "materials/jwl_eos.hpp"

namespace camouflet {

namespace {

using Point = std::array<double, 3>;

Point node(const FemMesh& mesh, std::int64_t n) {
  Point p{};
  for (int i = 0; i < mesh.dimension; ++i)
    p[static_cast<std::size_t>(i)] = mesh.coordinates[static_cast<std::size_t>(n * mesh.dimension + i)];
  return p;
}

double cross2(const Point& a, const Point& b, const Point& x) {
  return (b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0]);
}

// Inside a counter-clockwise quad (convex or not too distorted), boundary included.
bool inside_quad(const std::array<Point, 4>& q, const Point& x) {
  double size = 0.0;
  for (int a = 0; a < 4; ++a)
    size = std::max({size, std::abs(q[static_cast<std::size_t>(a)][0] - q[0][0]),
                     std::abs(q[static_cast<std::size_t>(a)][1] - q[0][1])});
  const double tol = -1e-9 * size * size;
  for (std::size_t a = 0; a < 4; ++a)
    if (cross2(q[a], q[(a + 1) % 4], x) < tol) return false;
  return true;
}

double det3(const Point& a, const Point& b, const Point& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}
Point minus(const Point& a, const Point& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// Inside a tetrahedron by barycentric coordinates, boundary included.
bool inside_tet(const Point& p0, const Point& p1, const Point& p2, const Point& p3, const Point& x) {
  const Point e1 = minus(p1, p0), e2 = minus(p2, p0), e3 = minus(p3, p0), r = minus(x, p0);
  const double v = det3(e1, e2, e3);
  if (v == 0.0) return false;
  const double l1 = det3(r, e2, e3) / v, l2 = det3(e1, r, e3) / v, l3 = det3(e1, e2, r) / v;
  const double tol = -1e-9;
  return l1 >= tol && l2 >= tol && l3 >= tol && 1.0 - l1 - l2 - l3 >= tol;
}

// Hex8 split into six tetrahedra around its diagonal 0-6.
bool inside_hex(const std::array<Point, 8>& h, const Point& x) {
  static constexpr int tets[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
  for (const auto& t : tets)
    if (inside_tet(h[0], h[static_cast<std::size_t>(t[0])], h[static_cast<std::size_t>(t[1])], h[6], x))
      return true;
  return false;
}

bool in_explosive_element(const Model& model, const std::vector<bool>& explosive_part, const Point& x) {
  const FemMesh& mesh = model.mesh;
  const std::size_t npe = static_cast<std::size_t>(mesh.nodes_per_element);
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    if (!explosive_part[static_cast<std::size_t>(mesh.element_part[e])]) continue;
    const std::int64_t* conn = &mesh.connectivity[e * npe];
    if (mesh.dimension == 2 && npe == 4) {
      if (inside_quad({node(mesh, conn[0]), node(mesh, conn[1]), node(mesh, conn[2]), node(mesh, conn[3])},
                      x))
        return true;
    } else if (mesh.dimension == 3 && npe == 8) {
      std::array<Point, 8> h;
      for (std::size_t a = 0; a < 8; ++a) h[a] = node(mesh, conn[a]);
      if (inside_hex(h, x)) return true;
    }
  }
  return false;
}

bool near_explosive_particle(const Model& model, const std::vector<bool>& explosive_part, const Point& x) {
  const ParticleSet& ps = model.particles;
  const int d = model.dimension();
  for (std::size_t p = 0; p < ps.count(); ++p) {
    if (!explosive_part[static_cast<std::size_t>(ps.particle_part[p])]) continue;
    double r2 = 0.0;
    for (int i = 0; i < d; ++i) {
      const double dx = ps.coordinates[p * static_cast<std::size_t>(d) + static_cast<std::size_t>(i)] -
                        x[static_cast<std::size_t>(i)];
      r2 += dx * dx;
    }
    if (r2 <= ps.spacing[p] * ps.spacing[p]) return true;
  }
  return false;
}

}  // namespace

bool is_explosive(const Material& material) {
  return dynamic_cast<const JwlEos*>(&material.eos()) != nullptr;
}

void check_detonation_points(const Model& model) {
  std::vector<bool> explosive_part(model.parts.size(), false);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < model.parts.size(); ++i) {
    const int m = model.parts[i].material;
    if (m >= 0 && static_cast<std::size_t>(m) < model.materials.size() &&
        is_explosive(*model.materials[static_cast<std::size_t>(m)].material)) {
      explosive_part[i] = true;
      names.push_back(model.parts[i].name);
    }
  }
  for (std::size_t k = 0; k < model.detonations.size(); ++k) {
    const Point& x = model.detonations[k].position;
    if (in_explosive_element(model, explosive_part, x) || near_explosive_particle(model, explosive_part, x))
      continue;
    const SourceLocation where =
        k < model.detonation_where.size() ? model.detonation_where[k] : model.run.where;
    throw InputError(
        where, names.empty()
                   ? fmt::format("detonation point ({:g}, {:g}, {:g}) m given, but no part is an explosive "
                                 "(a material with a JWL equation of state)",
                                 x[0], x[1], x[2])
                   : fmt::format("detonation point ({:g}, {:g}, {:g}) m lies in no explosive part (explosive "
                                 "parts: {})",
                                 x[0], x[1], x[2], fmt::join(names, ", ")));
  }
}

}  // namespace camouflet
