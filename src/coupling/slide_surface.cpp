#include "coupling/slide_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "coupling/face_projection.hpp"

namespace camouflet {

using contact_geometry::project_triangle;
using contact_geometry::quad_normal;

namespace {

// A foot on a face's seam, within this fraction of the face outside it, still counts: a node
// that sits on the ridge between two faces must meet one of them.
constexpr double seam_tolerance = 1e-3;

std::vector<std::int64_t> unique_nodes(const std::vector<std::int64_t>& faces) {
  std::vector<std::int64_t> nodes = faces;
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace

template <int D>
SlideSurfaces<D>::SlideSurfaces(const Model& model) {
  for (const SlideSurface& s : model.slide_surfaces) {
    if (!(s.friction >= 0.0)) throw InputError(s.where, "friction: must be >= 0");
    if (!(s.penalty_scale > 0.0 && s.penalty_scale < 2.0 * (1.0 - model.run.cfl * model.run.cfl)))
      throw InputError(s.where,
                       fmt::format("penalty_scale: must lie in (0, 2 (1 - cfl^2)) = (0, {:.3g}) for a "
                                   "stable contact at cfl {}",
                                   2.0 * (1.0 - model.run.cfl * model.run.cfl), model.run.cfl));
    if (s.faces_a.empty() || s.faces_a.size() != s.faces_b.size() ||
        s.faces_a.size() != F * s.elements_a.size() || s.faces_b.size() != F * s.elements_b.size())
      throw InputError(s.where, "parts: the slide surface has no faces between its two sides");
    Surface surface;
    surface.a = {s.faces_a, s.elements_a, unique_nodes(s.faces_a)};
    surface.b = {s.faces_b, s.elements_b, unique_nodes(s.faces_b)};
    surface.friction = s.friction;
    surface.penalty_scale = s.penalty_scale;
    surfaces_.push_back(std::move(surface));
  }
}

template <int D>
void SlideSurfaces<D>::apply(const double* x, const double* v, const double* m,
                             const std::vector<char>& eroded, double* f, double dt_stable) {
  pairs_ = 0;
  deepest_ = 0.0;
  contacts_.clear();
  if (!(dt_stable > 0.0)) return;
  for (const Surface& s : surfaces_) {
    pass(s, s.b, s.a, x, v, m, eroded, f, dt_stable);
    pass(s, s.a, s.b, x, v, m, eroded, f, dt_stable);
  }
}

template <int D>
Vec<D> SlideSurfaces<D>::relative_velocity(const Pair& pair, const double* v) const {
  Vec<D> rel;
  for (int d = 0; d < D; ++d) rel[d] = v[pair.node * D + d];
  for (int a = 0; a < pair.count; ++a)
    for (int d = 0; d < D; ++d)
      rel[d] -= pair.weight[static_cast<std::size_t>(a)] * v[pair.on[static_cast<std::size_t>(a)] * D + d];
  return rel;
}

template <int D>
void SlideSurfaces<D>::apply_friction(double* v, const double* m, double dt) {
  if (!(dt > 0.0)) return;
  for (Pair& pair : contacts_) {
    if (!(pair.friction > 0.0)) continue;
    const Vec<D> v_rel = relative_velocity(pair, v);
    const Vec<D> v_t = v_rel - pair.normal * dot(v_rel, pair.normal);
    const double vt = std::sqrt(dot(v_t, v_t));
    if (!(vt > 0.0)) continue;
    const double fn = dot(pair.force, pair.normal);
    const double impulse = std::min(pair.friction * fn * dt, pair.m_eff * vt);
    const Vec<D> j = v_t * (-impulse / vt);  // on the node; -w_a j on the face nodes
    for (int d = 0; d < D; ++d) v[pair.node * D + d] += j[d] / m[pair.node];
    for (int a = 0; a < pair.count; ++a) {
      const std::int64_t n = pair.on[static_cast<std::size_t>(a)];
      for (int d = 0; d < D; ++d) v[n * D + d] -= pair.weight[static_cast<std::size_t>(a)] * j[d] / m[n];
    }
    pair.force += j * (1.0 / dt);  // booked with the spring's force in settle()
  }
}

template <int D>
double SlideSurfaces<D>::settle(const double* v, double dt) const {
  double work = 0.0;
  for (const Pair& pair : contacts_)
    work += 0.5 * (dot(pair.force, pair.v_rel_before) + dot(pair.force, relative_velocity(pair, v))) * dt;
  return work;
}

template <int D>
void SlideSurfaces<D>::pass(const Surface& s, const Side& nodes, const Side& faces, const double* x,
                            const double* v, const double* m, const std::vector<char>& eroded, double* f,
                            double dt_stable) {
  auto point = [&](std::int64_t n) {
    Vec<D> p;
    for (int i = 0; i < D; ++i) p[i] = x[n * D + i];
    return p;
  };
  auto live = [&](std::int64_t e) {
    return static_cast<std::size_t>(e) >= eroded.size() || !eroded[static_cast<std::size_t>(e)];
  };
  const std::size_t face_count = faces.elements.size();

  // Bucket search: each face's box, grown by its capture depth (half its size), into the cells of
  // a grid as coarse as the largest grown box, so that a node looks in its own cell only.
  std::vector<std::array<double, 2 * D>> box(face_count);
  std::vector<double> capture(face_count, 0.0);
  double cell = 0.0;
  for (std::size_t k = 0; k < face_count; ++k) {
    auto& b = box[k];
    for (int i = 0; i < D; ++i) b[i] = std::numeric_limits<double>::infinity(), b[D + i] = -b[i];
    for (int a = 0; a < F; ++a) {
      const Vec<D> p = point(faces.faces[k * F + a]);
      for (int i = 0; i < D; ++i) b[i] = std::min(b[i], p[i]), b[D + i] = std::max(b[D + i], p[i]);
    }
    double size = 0.0;
    for (int i = 0; i < D; ++i) size = std::max(size, b[D + i] - b[i]);
    capture[k] = 0.5 * size;
    for (int i = 0; i < D; ++i) b[i] -= capture[k], b[D + i] += capture[k];
    for (int i = 0; i < D; ++i) cell = std::max(cell, b[D + i] - b[i]);
  }
  if (!(cell > 0.0) || !std::isfinite(cell)) return;
  auto cell_of = [&](double c) { return static_cast<std::int64_t>(std::floor(c / cell)); };
  auto key = [&](const std::array<std::int64_t, 3>& c) {
    // 21 bits a coordinate: a grid of 2 million cells a side, far beyond any model here.
    return ((c[0] & 0x1fffff) << 42) | ((c[1] & 0x1fffff) << 21) | (c[2] & 0x1fffff);
  };
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> grid;
  for (std::size_t k = 0; k < face_count; ++k) {
    if (!live(faces.elements[k])) continue;
    std::array<std::int64_t, 3> lo{}, hi{};
    for (int i = 0; i < D; ++i) lo[i] = cell_of(box[k][i]), hi[i] = cell_of(box[k][D + i]);
    std::array<std::int64_t, 3> c{};
    for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0])
      for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
        for (c[2] = lo[2]; c[2] <= hi[2]; ++c[2]) grid[key(c)].push_back(static_cast<std::uint32_t>(k));
  }

  // A node takes part while one of its own faces is live.
  std::vector<char> node_live;
  {
    std::unordered_map<std::int64_t, char> alive;
    for (std::size_t k = 0; k < nodes.elements.size(); ++k)
      if (live(nodes.elements[k]))
        for (int a = 0; a < F; ++a) alive[nodes.faces[k * F + a]] = 1;
    node_live.resize(nodes.nodes.size());
    for (std::size_t i = 0; i < nodes.nodes.size(); ++i) node_live[i] = alive.count(nodes.nodes[i]) ? 1 : 0;
  }

  for (std::size_t i = 0; i < nodes.nodes.size(); ++i) {
    if (!node_live[i]) continue;
    const std::int64_t node = nodes.nodes[i];
    if (!(m[node] > 0.0)) continue;
    const Vec<D> p = point(node);
    std::array<std::int64_t, 3> c{};
    for (int d = 0; d < D; ++d) c[d] = cell_of(p[d]);
    const auto found = grid.find(key(c));
    if (found == grid.end()) continue;
    // The nearest face the node projects onto, within its capture depth.
    double best = std::numeric_limits<double>::infinity(), gap = 0.0;
    std::array<std::int64_t, 3> on{};
    std::array<double, 3> weight{};
    int count = 0;
    Vec<D> normal{};
    for (const std::uint32_t k : found->second) {
      const std::int64_t* q = &faces.faces[static_cast<std::size_t>(k) * F];
      if constexpr (D == 2) {
        const Vec<2> a = point(q[0]), b = point(q[1]);
        const Vec<2> ab = b - a;
        const double length = std::sqrt(dot(ab, ab));
        if (!(length > 0.0)) continue;
        const Vec<2> t = ab * (1.0 / length);
        const Vec<2> n{{t[1], -t[0]}};  // outward of a counter-clockwise element
        const Vec<2> ap = p - a;
        const double xi = dot(ap, t) / length, g = dot(ap, n);
        if (xi < -seam_tolerance || xi > 1.0 + seam_tolerance || std::abs(g) > capture[k]) continue;
        if (std::abs(g) < best) {
          const double w = std::clamp(xi, 0.0, 1.0);
          best = std::abs(g), gap = g, count = 2, normal = n, on = {q[0], q[1], 0},
          weight = {1.0 - w, w, 0.0};
        }
      } else {
        const Vec<3> corner[4] = {point(q[0]), point(q[1]), point(q[2]), point(q[3])};
        Vec<3> n;
        if (!quad_normal(corner[0], corner[1], corner[2], corner[3], n)) continue;
        constexpr int triangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
        for (const auto& tri : triangles) {
          std::array<double, 3> w{};
          double g = 0.0;
          if (!project_triangle(p, corner[tri[0]], corner[tri[1]], corner[tri[2]], n, w, g, seam_tolerance))
            continue;
          if (std::abs(g) > capture[k] || !(std::abs(g) < best)) continue;
          double sum = 0.0;
          for (double& wa : w) wa = std::max(wa, 0.0), sum += wa;
          for (double& wa : w) wa /= sum;
          best = std::abs(g), gap = g, count = 3, normal = n, weight = w;
          on = {q[tri[0]], q[tri[1]], q[tri[2]]};
        }
      }
    }
    if (count == 0 || !(gap < 0.0)) continue;
    // The pair's mass along the normal, the spring and the friction.
    double inverse = 1.0 / m[node];
    for (int a = 0; a < count; ++a) {
      const double w = weight[static_cast<std::size_t>(a)];
      if (w > 0.0) inverse += w * w / m[on[static_cast<std::size_t>(a)]];
    }
    const double m_eff = 1.0 / inverse;
    const double fn = s.penalty_scale * m_eff / (dt_stable * dt_stable) * (-gap);
    Pair pair{node, count, on, weight, normal, m_eff, s.friction, normal * fn, {}};
    pair.v_rel_before = relative_velocity(pair, v);
    const Vec<D> force = pair.force;
    for (int d = 0; d < D; ++d) f[node * D + d] += force[d];
    for (int a = 0; a < count; ++a)
      for (int d = 0; d < D; ++d)
        f[on[static_cast<std::size_t>(a)] * D + d] -= weight[static_cast<std::size_t>(a)] * force[d];
    contacts_.push_back(pair);
    ++pairs_;
    deepest_ = std::max(deepest_, -gap);
  }
}

template class SlideSurfaces<2>;
template class SlideSurfaces<3>;

}  // namespace camouflet
