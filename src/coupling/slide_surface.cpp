#include "coupling/slide_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "coupling/face_projection.hpp"

namespace camouflet {

using contact_geometry::closest_on_segment;
using contact_geometry::closest_on_triangle;

namespace {

std::vector<std::int64_t> unique_nodes(const std::vector<std::int64_t>& faces) {
  std::vector<std::int64_t> nodes = faces;
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// A node within this fraction of a face's size beyond the rim of the other side's surface still
// meets it: where the parts were joined, the two sides' rims coincide.
constexpr double seam_tolerance = 1e-3;

// The rim of a side's surface: its edges that bound one face only (sorted node pairs; in 2-D the
// faces' end points that end one face only, as pairs (node, node)), and every node on the rim.
template <int F>
void find_rim(const std::vector<std::int64_t>& faces,
              std::vector<std::pair<std::int64_t, std::int64_t>>& edges, std::vector<std::int64_t>& nodes) {
  std::vector<std::pair<std::int64_t, std::int64_t>> all;
  for (std::size_t k = 0; k + F <= faces.size(); k += F)
    for (int a = 0; a < (F == 2 ? 2 : F); ++a) {
      if constexpr (F == 2) {
        all.emplace_back(faces[k + static_cast<std::size_t>(a)], faces[k + static_cast<std::size_t>(a)]);
      } else {
        const std::int64_t i = faces[k + static_cast<std::size_t>(a)],
                           j = faces[k + static_cast<std::size_t>((a + 1) % F)];
        all.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
  std::sort(all.begin(), all.end());
  edges.clear();
  nodes.clear();
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    while (j < all.size() && all[j] == all[i]) ++j;
    if (j - i == 1) {
      edges.push_back(all[i]);
      nodes.push_back(all[i].first);
      nodes.push_back(all[i].second);
    }
    i = j;
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
}

Vec<3> cross(const Vec<3>& a, const Vec<3>& b) {
  return Vec<3>{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
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
    surface.a = {s.faces_a, s.elements_a, unique_nodes(s.faces_a), {}, {}, {}, {}};
    surface.b = {s.faces_b, s.elements_b, unique_nodes(s.faces_b), {}, {}, {}, {}};
    find_rim<F>(surface.a.faces, surface.a.rim_edges, surface.a.rim_nodes);
    find_rim<F>(surface.b.faces, surface.b.rim_edges, surface.b.rim_nodes);
    index_pieces(surface.a);
    index_pieces(surface.b);
    surface.friction = s.friction;
    surface.penalty_scale = s.penalty_scale;
    surfaces_.push_back(std::move(surface));
  }
}

template <int D>
std::array<std::int64_t, 3> SlideSurfaces<D>::piece_nodes(const Side& faces, std::size_t k, int piece) {
  const std::int64_t* q = &faces.faces[k * F];
  if constexpr (D == 2) {
    return {q[0], q[1], -1};
  } else {
    return piece == 0 ? std::array<std::int64_t, 3>{q[0], q[1], q[2]}
                      : std::array<std::int64_t, 3>{q[0], q[2], q[3]};
  }
}

template <int D>
void SlideSurfaces<D>::index_pieces(Side& side) {
  constexpr int pieces = D == 2 ? 1 : 2;
  constexpr int corners = D == 2 ? 2 : 3;
  const std::size_t face_count = side.elements.size();
  auto index_of = [&](std::int64_t node) {
    return static_cast<std::size_t>(std::lower_bound(side.nodes.begin(), side.nodes.end(), node) -
                                    side.nodes.begin());
  };
  side.piece_start.assign(side.nodes.size() + 1, 0);
  for (std::size_t k = 0; k < face_count; ++k)
    for (int piece = 0; piece < pieces; ++piece) {
      const auto on = piece_nodes(side, k, piece);
      for (int a = 0; a < corners; ++a) ++side.piece_start[index_of(on[static_cast<std::size_t>(a)]) + 1];
    }
  for (std::size_t i = 0; i < side.nodes.size(); ++i) side.piece_start[i + 1] += side.piece_start[i];
  side.piece_list.assign(side.piece_start.back(), 0);
  std::vector<std::size_t> next(side.piece_start.begin(), side.piece_start.end() - 1);
  for (std::size_t k = 0; k < face_count; ++k)
    for (int piece = 0; piece < pieces; ++piece) {
      const auto on = piece_nodes(side, k, piece);
      for (int a = 0; a < corners; ++a)
        side.piece_list[next[index_of(on[static_cast<std::size_t>(a)])]++] =
            k * 2 + static_cast<std::size_t>(piece);
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
template <class Point>
bool SlideSurfaces<D>::closest_foot(const Side& faces, std::size_t k, int piece, const Vec<D>& p,
                                    const Point& point, Foot& foot) {
  const std::int64_t* q = &faces.faces[k * F];
  foot.face = k;
  if constexpr (D == 2) {
    const Vec<2> a = point(q[0]), b = point(q[1]);
    const Vec<2> ab = b - a;
    const double length = std::sqrt(dot(ab, ab));
    if (!(length > 0.0)) return false;
    foot.normal = Vec<2>{{ab[1] / length, -ab[0] / length}};  // outward of a counter-clockwise element
    const double t = closest_on_segment<2>(p, a, b);
    foot.count = 2;
    foot.on = {q[0], q[1], 0};
    foot.weight = {1.0 - t, t, 0.0};
    foot.interior = t > 0.0 && t < 1.0;
    const Vec<2> c = a + ab * t;
    foot.distance2 = dot(p - c, p - c);
  } else {
    // The quad as the triangles (0, 1, 2) and (0, 2, 3), each with its own outward normal.
    constexpr int triangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
    const int* tri = triangles[piece];
    const Vec<3> a = point(q[tri[0]]), b = point(q[tri[1]]), c = point(q[tri[2]]);
    const Vec<3> ab = b - a, ac = c - a;
    const Vec<3> n = cross(ab, ac);
    const double area2 = std::sqrt(dot(n, n));
    if (!(area2 > 0.0)) return false;
    foot.normal = n * (1.0 / area2);
    foot.interior = closest_on_triangle(p, a, b, c, foot.weight);
    foot.count = 3;
    foot.on = {q[tri[0]], q[tri[1]], q[tri[2]]};
    const Vec<3> f = a * foot.weight[0] + b * foot.weight[1] + c * foot.weight[2];
    foot.distance2 = dot(p - f, p - f);
  }
  return true;
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
  constexpr int pieces = D == 2 ? 1 : 2;  // a segment; a quad's two triangles

  // Bucket search: each face's box, grown by its capture depth (half its size), into every cell of
  // a grid it overlaps, so that a node looks in its own cell only. The cell is the median grown
  // box of the live faces: one face stretched far (or eroded, out of the search) must not make
  // the cell, and with it every node's list, as large as itself,
  std::vector<std::array<double, 2 * D>> box(face_count);
  std::vector<double> capture(face_count, 0.0), extents;
  extents.reserve(face_count);
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
    if (live(faces.elements[k])) extents.push_back(2.0 * size);
  }
  if (extents.empty()) return;
  std::nth_element(extents.begin(), extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2),
                   extents.end());
  // ... nor so fine that the largest face spans more than 16 cells a side.
  const double cell =
      std::max(extents[extents.size() / 2], *std::max_element(extents.begin(), extents.end()) / 16.0);
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
    // The closest point of the other side's surface. The distance to it is continuous however
    // the node moves, across the seams, ridges and valleys of the faces alike, and so is the
    // spring's potential k d^2 / 2: a node that took the nearest face it projects onto met a
    // depth that jumped where its foot left one face for the next, and each jump gave the spring
    // energy (the 3-D box under a blast).
    Foot best;
    for (const std::uint32_t k : found->second)
      for (int piece = 0; piece < pieces; ++piece) {
        Foot foot;
        if (closest_foot(faces, k, piece, p, point, foot) && foot.distance2 < best.distance2) best = foot;
      }
    if (best.count == 0) continue;
    const double distance = std::sqrt(best.distance2);
    if (!(distance > 0.0) || distance > capture[best.face]) continue;
    auto place = [&](const Foot& foot) {
      Vec<D> q{};
      for (int a = 0; a < foot.count; ++a)
        q = q + point(foot.on[static_cast<std::size_t>(a)]) * foot.weight[static_cast<std::size_t>(a)];
      return q;
    };
    const Vec<D> foot_point = place(best);
    double gap = dot(p - foot_point, best.normal);  // the signed distance when the foot is inside
    Vec<D> normal = best.normal;
    if (!best.interior) {
      // On an edge or corner: the node is inside the other side's body when behind the
      // pseudonormal there (Baerentzen and Aanaes 2005, IEEE TVCG 11: the sum of the normals of
      // the pieces that share an edge, their sum weighted by the angle each makes at a corner;
      // outside a convex edge a node lies in front of both faces, inside a valley behind both),
      // and is pushed towards the point. The pieces are those the surface's topology puts there,
      // not those whose own closest point happens to coincide with this one: a face whose foot
      // fell a hair inside it, beside the edge, dropped out of such a tie, and the node just
      // below the box's bottom edge, in the plane of its wall, was judged behind the wall alone
      // and pushed out by its whole distance, 1.8 mm in one step (coarse3d, 33.6 ms).
      std::array<std::int64_t, 3> carrier{};
      int carriers = 0;
      for (int a = 0; a < best.count; ++a)
        if (best.weight[static_cast<std::size_t>(a)] > 0.0)
          carrier[static_cast<std::size_t>(carriers++)] = best.on[static_cast<std::size_t>(a)];
      Vec<D> behind{};
      std::array<Vec<D>, D> basis{};  // the directions the normals span, orthonormal
      int span = 0;
      const std::size_t at = static_cast<std::size_t>(
          std::lower_bound(faces.nodes.begin(), faces.nodes.end(), carrier[0]) - faces.nodes.begin());
      for (std::size_t j = faces.piece_start[at]; j < faces.piece_start[at + 1]; ++j) {
        const std::size_t k = faces.piece_list[j] / 2;
        const int piece = static_cast<int>(faces.piece_list[j] % 2);
        if (!live(faces.elements[k])) continue;
        const std::array<std::int64_t, 3> on = piece_nodes(faces, k, piece);
        const auto on_end = on.begin() + (D == 2 ? 2 : 3);
        if (carriers == 2 && std::find(on.begin(), on_end, carrier[1]) == on_end)
          continue;  // an edge's pieces hold both its nodes
        Foot foot;
        if (!closest_foot(faces, k, piece, p, point, foot)) continue;
        double weight = 1.0;
        if constexpr (D == 3) {
          if (carriers == 1) {  // the piece's angle at the corner
            const int c = on[0] == carrier[0] ? 0 : (on[1] == carrier[0] ? 1 : 2);
            const Vec<3> o = point(on[static_cast<std::size_t>(c)]);
            const Vec<3> e1 = point(on[static_cast<std::size_t>((c + 1) % 3)]) - o,
                         e2 = point(on[static_cast<std::size_t>((c + 2) % 3)]) - o;
            const Vec<3> n = cross(e1, e2);
            weight = std::atan2(std::sqrt(dot(n, n)), dot(e1, e2));
          }
        }
        behind = behind + foot.normal * weight;
        Vec<D> rest = foot.normal;
        for (int i = 0; i < span; ++i)
          rest = rest - basis[static_cast<std::size_t>(i)] * dot(rest, basis[static_cast<std::size_t>(i)]);
        // A normal within about 10 degrees of the span adds no direction of its own: a bent
        // surface's rim stays a rim.
        const double length = std::sqrt(dot(rest, rest));
        if (span < D && length > 0.2) basis[static_cast<std::size_t>(span++)] = rest * (1.0 / length);
      }
      gap = dot(p - foot_point, behind) < 0.0 ? -distance : distance;
      normal = (foot_point - p) * (1.0 / distance);
      // On the rim of the other side's surface (an edge or corner bounding one face only) a node
      // may lie beside the surface rather than against it: then the way from the point to the
      // node leaves the span of the normals there (for a plain rim, the face's normal; at the end
      // of a valley, the valley's two). Within 1e-3 of a face size it still counts: where the
      // parts were joined, the two sides' rims coincide.
      const bool rim =
          (carriers == 1 && std::binary_search(faces.rim_nodes.begin(), faces.rim_nodes.end(), carrier[0])) ||
          (carriers == 2 &&
           std::binary_search(faces.rim_edges.begin(), faces.rim_edges.end(),
                              std::pair{std::min(carrier[0], carrier[1]), std::max(carrier[0], carrier[1])}));
      if (rim) {
        // Within it the depth and the push are those along the span: a node a hair beside the
        // rim is not pushed sideways.
        Vec<D> along{};
        for (int i = 0; i < span; ++i)
          along = along + basis[static_cast<std::size_t>(i)] *
                              dot(p - foot_point, basis[static_cast<std::size_t>(i)]);
        const Vec<D> beside = (p - foot_point) - along;
        if (dot(beside, beside) > std::pow(seam_tolerance * 2.0 * capture[best.face], 2)) continue;
        const double depth = std::sqrt(dot(along, along));
        if (!(depth > 0.0)) continue;
        gap = dot(along, behind) < 0.0 ? -depth : depth;
        normal = along * (-1.0 / depth);
      }
    }
    if (!(gap < 0.0)) continue;
    const int count = best.count;
    const std::array<std::int64_t, 3>& on = best.on;
    const std::array<double, 3>& weight = best.weight;
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
