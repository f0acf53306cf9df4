#include "mesh/block_generator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"

namespace camouflet {

std::vector<double> graded_coordinates(double origin, double length, int cells, double grading) {
  if (cells < 1) throw InputError({}, "a block needs at least one cell per direction");
  if (!(grading > 0.0)) throw InputError({}, "block grading must be positive");
  // Geometric progression h_i = h_0 r^i with r^(n-1) = grading, sum h_i = length.
  const double r = cells > 1 ? std::pow(grading, 1.0 / (cells - 1)) : 1.0;
  std::vector<double> widths(static_cast<std::size_t>(cells));
  double w = 1.0, total = 0.0;
  for (auto& h : widths) {
    h = w;
    total += w;
    w *= r;
  }
  std::vector<double> x(static_cast<std::size_t>(cells) + 1);
  x[0] = origin;
  double sum = 0.0;
  for (int i = 0; i < cells; ++i) {
    sum += widths[static_cast<std::size_t>(i)];
    x[static_cast<std::size_t>(i) + 1] = origin + length * sum / total;
  }
  x.back() = origin + length;  // exact end, so adjacent blocks meet bit for bit
  return x;
}

namespace {

// Finds existing nodes that coincide with new ones. Only nodes inside the
// block's bounding box (grown by the tolerance) can, so only those are indexed.
class NodeMatcher {
 public:
  NodeMatcher(const FemMesh& mesh, const std::array<double, 3>& lo, const std::array<double, 3>& hi,
              double tolerance)
      : mesh_(mesh), d_(mesh.dimension), tol_(tolerance) {
    const std::size_t n = mesh.node_count();
    for (std::size_t i = 0; i < n; ++i) {
      bool inside = true;
      for (int k = 0; k < d_; ++k) {
        const double x = coord(i, k);
        inside = inside && x >= lo[static_cast<std::size_t>(k)] - tol_ &&
                 x <= hi[static_cast<std::size_t>(k)] + tol_;
      }
      if (inside) candidates_.push_back(static_cast<std::int64_t>(i));
    }
    std::sort(candidates_.begin(), candidates_.end(),
              [this](std::int64_t a, std::int64_t b) { return coord(a, 0) < coord(b, 0); });
  }

  // Index of an existing node at p, or -1.
  std::int64_t find(const std::array<double, 3>& p) const {
    auto first = std::lower_bound(candidates_.begin(), candidates_.end(), p[0] - tol_,
                                  [this](std::int64_t a, double x) { return coord(a, 0) < x; });
    for (auto it = first; it != candidates_.end() && coord(*it, 0) <= p[0] + tol_; ++it) {
      bool same = true;
      for (int k = 1; k < d_; ++k)
        same = same && std::abs(coord(*it, k) - p[static_cast<std::size_t>(k)]) <= tol_;
      if (same) return *it;
    }
    return -1;
  }

 private:
  double coord(std::int64_t i, int k) const {
    return mesh_.coordinates[static_cast<std::size_t>(i) * static_cast<std::size_t>(d_) +
                             static_cast<std::size_t>(k)];
  }
  const FemMesh& mesh_;
  int d_;
  double tol_;
  std::vector<std::int64_t> candidates_;
};

void append_unique(std::vector<std::int64_t>& set, const std::vector<std::int64_t>& nodes) {
  for (auto n : nodes)
    if (std::find(set.begin(), set.end(), n) == set.end()) set.push_back(n);
}

}  // namespace

void add_block(FemMesh& mesh, const BlockSpec& spec) {
  const int d = mesh.dimension;
  if (d != 2 && d != 3) throw std::invalid_argument("mesh dimension must be 2 or 3");
  if (mesh.node_count() == 0 && mesh.connectivity.empty()) mesh.nodes_per_element = d == 2 ? 4 : 8;
  const int nz = d == 3 ? spec.cells[2] : 0;

  std::array<std::vector<double>, 3> axis;
  double extent = 0.0;
  std::array<double, 3> lo{}, hi{};
  for (int k = 0; k < d; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    if (!(spec.size[ku] > 0.0)) throw InputError({}, "block '" + spec.name + "' needs a positive size");
    axis[ku] = graded_coordinates(spec.origin[ku], spec.size[ku], spec.cells[ku], spec.grading[ku]);
    extent = std::max(extent, spec.size[ku]);
    lo[ku] = spec.origin[ku];
    hi[ku] = spec.origin[ku] + spec.size[ku];
  }
  const double tolerance = 1e-9 * extent;
  const NodeMatcher matcher(mesh, lo, hi, tolerance);

  // Block-local (i, j, k) -> global node index, creating nodes not already present.
  const int nx = spec.cells[0], ny = spec.cells[1];
  const int nk = d == 3 ? nz + 1 : 1;
  std::vector<std::int64_t> node((static_cast<std::size_t>(nx) + 1) * (static_cast<std::size_t>(ny) + 1) *
                                 static_cast<std::size_t>(nk));
  auto local = [&](int i, int j, int k) {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny + 1) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(nx + 1) +
           static_cast<std::size_t>(i);
  };
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        std::array<double, 3> p{axis[0][static_cast<std::size_t>(i)], axis[1][static_cast<std::size_t>(j)],
                                d == 3 ? axis[2][static_cast<std::size_t>(k)] : 0.0};
        std::int64_t id = matcher.find(p);
        if (id < 0) {
          id = static_cast<std::int64_t>(mesh.node_count());
          for (int c = 0; c < d; ++c) mesh.coordinates.push_back(p[static_cast<std::size_t>(c)]);
        }
        node[local(i, j, k)] = id;
      }

  // Elements: counter-clockwise quads; hexes bottom face counter-clockwise from above, then top.
  for (int k = 0; k < std::max(nz, 1); ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int kk = d == 3 ? k : 0;
        const std::int64_t bottom[4] = {node[local(i, j, kk)], node[local(i + 1, j, kk)],
                                        node[local(i + 1, j + 1, kk)], node[local(i, j + 1, kk)]};
        for (auto n : bottom) mesh.connectivity.push_back(n);
        if (d == 3) {
          const std::int64_t top[4] = {node[local(i, j, k + 1)], node[local(i + 1, j, k + 1)],
                                       node[local(i + 1, j + 1, k + 1)], node[local(i, j + 1, k + 1)]};
          for (auto n : top) mesh.connectivity.push_back(n);
        }
        mesh.element_part.push_back(spec.part);
      }

  // Boundary faces with outward normals, and the node sets on them.
  std::map<std::string, std::vector<std::int64_t>> faces, nodes;
  const std::string p = spec.name + ".";
  if (d == 2) {
    for (int j = 0; j < ny; ++j) {
      faces[p + "xmin"].insert(faces[p + "xmin"].end(), {node[local(0, j + 1, 0)], node[local(0, j, 0)]});
      faces[p + "xmax"].insert(faces[p + "xmax"].end(), {node[local(nx, j, 0)], node[local(nx, j + 1, 0)]});
    }
    for (int i = 0; i < nx; ++i) {
      faces[p + "ymin"].insert(faces[p + "ymin"].end(), {node[local(i, 0, 0)], node[local(i + 1, 0, 0)]});
      faces[p + "ymax"].insert(faces[p + "ymax"].end(), {node[local(i + 1, ny, 0)], node[local(i, ny, 0)]});
    }
  } else {
    auto quad = [&](const std::string& set, std::array<std::int64_t, 4> q) {
      faces[p + set].insert(faces[p + set].end(), q.begin(), q.end());
    };
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j) {
        quad("xmin", {node[local(0, j + 1, k)], node[local(0, j, k)], node[local(0, j, k + 1)],
                      node[local(0, j + 1, k + 1)]});
        quad("xmax", {node[local(nx, j, k)], node[local(nx, j + 1, k)], node[local(nx, j + 1, k + 1)],
                      node[local(nx, j, k + 1)]});
      }
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) {
        quad("ymin", {node[local(i, 0, k)], node[local(i + 1, 0, k)], node[local(i + 1, 0, k + 1)],
                      node[local(i, 0, k + 1)]});
        quad("ymax", {node[local(i + 1, ny, k)], node[local(i, ny, k)], node[local(i, ny, k + 1)],
                      node[local(i + 1, ny, k + 1)]});
      }
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        quad("zmin", {node[local(i, j, 0)], node[local(i, j + 1, 0)], node[local(i + 1, j + 1, 0)],
                      node[local(i + 1, j, 0)]});
        quad("zmax", {node[local(i, j, nz)], node[local(i + 1, j, nz)], node[local(i + 1, j + 1, nz)],
                      node[local(i, j + 1, nz)]});
      }
  }
  for (auto& [name, list] : faces) {
    std::vector<std::int64_t> on_face;
    append_unique(on_face, list);
    std::sort(on_face.begin(), on_face.end());
    append_unique(mesh.node_sets[name], on_face);
    auto& f = mesh.face_sets[name];
    f.insert(f.end(), list.begin(), list.end());
  }
}

}  // namespace camouflet
