#include "coupling/sliding_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "coupling/face_projection.hpp"

namespace camouflet {

using contact_geometry::project_triangle;
using contact_geometry::quad_normal;

template <int D>
SlidingContact<D>::SlidingContact(const Model& model) {
  for (const Contact& c : model.contacts) {
    if (c.sph_part < 0 || static_cast<std::size_t>(c.sph_part) >= model.parts.size() ||
        model.parts[static_cast<std::size_t>(c.sph_part)].kind != PartKind::sph)
      throw InputError(c.where, "part: a sliding interface needs an SPH part on its particle side");
    const auto set = model.mesh.face_sets.find(c.face_set);
    if (set == model.mesh.face_sets.end())
      throw InputError(c.where,
                       fmt::format("set: unknown face set '{}' for a sliding interface", c.face_set));
    if (!(c.friction >= 0.0)) throw InputError(c.where, "friction: must be >= 0");
    if (!(c.penalty_scale > 0.0 && c.penalty_scale < 4.0))
      throw InputError(c.where, "penalty_scale: must lie in (0, 4) for a stable contact spring");
    contacts_.push_back({c.sph_part, set->second, c.friction, c.penalty_scale});
  }
}

template <int D>
double SlidingContact<D>::apply(sph::SphSystem<D>& particles, const double* x, const double* v, double* f,
                                double dt) {
  constexpr int F = D == 2 ? 2 : 4;
  auto& p = particles.particles();
  smallest_gap_ = std::numeric_limits<double>::infinity();
  double power = 0.0;
  if (!(dt > 0.0)) return 0.0;
  auto node = [&](std::int64_t n) {
    Vec<D> out;
    for (int i = 0; i < D; ++i) out[i] = x[n * D + i];
    return out;
  };
  for (const Surface& s : contacts_) {
    for (std::size_t i = 0; i < p.real; ++i) {
      if (p.part[i] != s.part) continue;
      const double radius = 0.5 * p.spacing[i];
      // The face this particle presses on most: its nodes, weights and normal.
      double best_depth = 0.0, best_gap = 0.0;
      std::array<std::int64_t, 3> nodes{};
      std::array<double, 3> weight{};
      int count = 0;
      Vec<D> normal{};
      for (std::size_t k = 0; k + F - 1 < s.faces.size(); k += F) {
        const std::int64_t* q = &s.faces[k];
        if constexpr (D == 2) {
          const Vec<2> a = node(q[0]), b = node(q[1]);
          const Vec<2> ab = b - a;
          const double length = std::sqrt(dot(ab, ab));
          if (!(length > 0.0)) continue;
          const Vec<2> t = ab * (1.0 / length);
          const Vec<2> n{{t[1], -t[0]}};  // outward for counter-clockwise faces
          const Vec<2> ap = p.position[i] - a;
          const double xi = dot(ap, t) / length, g = dot(ap, n);
          if (xi < 0.0 || xi > 1.0 || g >= radius || g < -radius) continue;
          if (radius - g > best_depth) {
            best_depth = radius - g, best_gap = g, count = 2, normal = n;
            nodes = {q[0], q[1], 0};
            weight = {1.0 - xi, xi, 0.0};
          }
        } else {
          const Vec<3> c0 = node(q[0]), c1 = node(q[1]), c2 = node(q[2]), c3 = node(q[3]);
          Vec<3> n;
          if (!quad_normal(c0, c1, c2, c3, n)) continue;
          const std::array<std::array<int, 3>, 2> triangles{{{0, 1, 2}, {0, 2, 3}}};
          for (const auto& tri : triangles) {
            std::array<double, 3> w{};
            double g = 0.0;
            const Vec<3> corner[4] = {c0, c1, c2, c3};
            if (!project_triangle(p.position[i], corner[tri[0]], corner[tri[1]], corner[tri[2]], n, w, g))
              continue;
            if (g >= radius || g < -radius || radius - g <= best_depth) continue;
            best_depth = radius - g, best_gap = g, count = 3, normal = n;
            nodes = {q[tri[0]], q[tri[1]], q[tri[2]]};
            weight = w;
          }
        }
      }
      if (count == 0) continue;
      smallest_gap_ = std::min(smallest_gap_, best_gap);
      const double m = p.mass[i];
      const double fn = s.penalty_scale * m / (dt * dt) * best_depth;
      Vec<D> v_face{};
      for (int a = 0; a < count; ++a)
        for (int d = 0; d < D; ++d)
          v_face[d] += weight[static_cast<std::size_t>(a)] * v[nodes[static_cast<std::size_t>(a)] * D + d];
      const Vec<D> v_rel = p.velocity[i] - v_face;
      const Vec<D> v_t = v_rel - normal * dot(v_rel, normal);
      const double vt = std::sqrt(dot(v_t, v_t));
      Vec<D> force = normal * fn;
      if (s.friction > 0.0 && vt > 0.0) force -= v_t * (std::min(s.friction * fn, m * vt / dt) / vt);
      p.acceleration[i] += force * (1.0 / m);
      for (int a = 0; a < count; ++a)
        for (int d = 0; d < D; ++d)
          f[nodes[static_cast<std::size_t>(a)] * D + d] -= weight[static_cast<std::size_t>(a)] * force[d];
      power += dot(force, v_rel);
    }
  }
  if (!std::isfinite(smallest_gap_)) smallest_gap_ = 0.0;
  return power;
}

template class SlidingContact<2>;
template class SlidingContact<3>;

}  // namespace camouflet
