#include "mesh/gmsh_import.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <map>
#include <mutex>
#include <set>
#include <unordered_map>

#include "core/parameters.hpp"
#include "model/isoparametric.hpp"

namespace camouflet {

namespace {

// Gmsh element type numbers (Gmsh reference manual, "MSH file format").
constexpr int gmsh_point = 15;
constexpr int gmsh_line2 = 1;
constexpr int gmsh_quad4 = 3;
constexpr int gmsh_hex8 = 5;
constexpr int gmsh_triangle3 = 2;
constexpr int gmsh_tet4 = 4;
constexpr int gmsh_prism6 = 6;
constexpr int gmsh_pyramid5 = 7;

// Element corners (Gmsh node order) of each simplex of a linear element:
// quad along diagonal 0-2, hex into six tetrahedra around diagonal 0-6.
const std::vector<std::vector<int>>& simplices_of(int type) {
  static const std::vector<std::vector<int>> triangle{{0, 1, 2}}, quad{{0, 1, 2}, {0, 2, 3}},
      tet{{0, 1, 2, 3}},
      hex{{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}},
      prism{{0, 1, 2, 5}, {0, 1, 5, 4}, {0, 4, 5, 3}}, pyramid{{0, 1, 2, 4}, {0, 2, 3, 4}}, none;
  switch (type) {
    case gmsh_triangle3:
      return triangle;
    case gmsh_quad4:
      return quad;
    case gmsh_tet4:
      return tet;
    case gmsh_hex8:
      return hex;
    case gmsh_prism6:
      return prism;
    case gmsh_pyramid5:
      return pyramid;
    default:
      return none;
  }
}

// The Gmsh library is a process-wide singleton: initialise it once, quietly,
// and serialise every use.
std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}
void ensure_gmsh() {
  static bool initialised = false;
  if (initialised) return;
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 0);
  initialised = true;
}

std::string last_gmsh_error() {
  std::string e;
  try {
    gmsh::logger::getLastError(e);
  } catch (...) {
  }
  return e.empty() ? std::string("Gmsh could not read it") : e;
}

struct PhysicalGroup {
  int dim;
  int tag;
  std::string name;
};

std::vector<PhysicalGroup> physical_groups() {
  gmsh::vectorpair dim_tags;
  gmsh::model::getPhysicalGroups(dim_tags);
  std::vector<PhysicalGroup> groups;
  for (const auto& [d, t] : dim_tags) {
    std::string name;
    gmsh::model::getPhysicalName(d, t, name);
    if (name.empty()) name = fmt::format("physical_{}_{}", d, t);
    groups.push_back({d, t, name});
  }
  return groups;
}

// Elements of a physical group: (type, node tags) over all its entities.
std::vector<std::pair<int, std::vector<std::size_t>>> group_elements(const PhysicalGroup& g) {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(g.dim, g.tag, entities);
  std::vector<std::pair<int, std::vector<std::size_t>>> out;
  for (int entity : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, g.dim, entity);
    for (std::size_t k = 0; k < types.size(); ++k) out.emplace_back(types[k], std::move(node_tags[k]));
  }
  return out;
}

class Importer {
 public:
  Importer(FemMesh& mesh, const GmshPartRequest& r) : mesh_(mesh), r_(r), dim_(mesh.dimension) {}

  void run() {
    const auto groups = physical_groups();
    const PhysicalGroup* part_group = nullptr;
    std::vector<std::string> names;
    for (const auto& g : groups) {
      names.push_back(g.name);
      if (g.name == r_.physical && g.dim == dim_) part_group = &g;
    }
    if (!part_group) {
      const std::string guess = nearest(r_.physical, names);
      throw InputError(r_.physical_where,
                       fmt::format("no {}-D physical group '{}' in {}{}", dim_, r_.physical, r_.file.string(),
                                   guess.empty() ? fmt::format(" (it has: {})", fmt::join(names, ", "))
                                                 : fmt::format("; did you mean '{}'?", guess)));
    }
    read_nodes();
    read_elements(*part_group);
    for (const auto& g : groups)
      if (g.dim < dim_) read_set(g);
  }

 private:
  void read_nodes() {
    std::vector<std::size_t> tags;
    std::vector<double> coord, parametric;
    gmsh::model::mesh::getNodes(tags, coord, parametric, -1, -1, false, false);
    for (std::size_t k = 0; k < tags.size(); ++k)
      file_coordinates_[tags[k]] = {coord[3 * k], coord[3 * k + 1], coord[3 * k + 2]};
    // Existing mesh nodes by exact coordinates: a node shared by two parts of
    // one file has the same coordinates bit for bit.
    for (std::size_t n = 0; n < mesh_.node_count(); ++n) {
      std::array<double, 3> x{};
      for (int i = 0; i < dim_; ++i) x[static_cast<std::size_t>(i)] = mesh_.coordinates[n * dim_ + i];
      existing_[x] = static_cast<std::int64_t>(n);
    }
  }

  // Mesh node index of a file node, creating it on first use.
  std::int64_t node(std::size_t tag) {
    if (const auto it = index_.find(tag); it != index_.end()) return it->second;
    const auto c = file_coordinates_.find(tag);
    if (c == file_coordinates_.end())
      throw InputError(r_.file_where,
                       fmt::format("{}: element refers to undefined node {}", r_.file.string(), tag));
    if (dim_ == 2 && c->second[2] != 0.0)
      throw InputError(r_.file_where,
                       fmt::format("{}: node {} has z = {}; a 2-D mesh must lie in the plane z = 0",
                                   r_.file.string(), tag, c->second[2]));
    std::array<double, 3> x = c->second;
    if (dim_ == 2) x[2] = 0.0;
    std::int64_t n;
    if (const auto e = existing_.find(x); e != existing_.end()) {
      n = e->second;
    } else {
      n = static_cast<std::int64_t>(mesh_.node_count());
      for (int i = 0; i < dim_; ++i) mesh_.coordinates.push_back(x[static_cast<std::size_t>(i)]);
      existing_[x] = n;
    }
    index_[tag] = n;
    return n;
  }

  void read_elements(const PhysicalGroup& g) {
    const int wanted = dim_ == 3 ? gmsh_hex8 : gmsh_quad4;
    const int npe = dim_ == 3 ? 8 : 4;
    std::size_t count = 0;
    for (const auto& [type, tags] : group_elements(g)) {
      if (type != wanted) {
        std::string type_name;
        int edim = 0, order = 0, nn = 0, nprimary = 0;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(type, type_name, edim, order, nn, local, nprimary);
        throw InputError(r_.physical_where,
                         fmt::format("physical group '{}' in {} has {} elements; only {} are supported here "
                                     "(recombine the mesh)",
                                     g.name, r_.file.string(), type_name,
                                     dim_ == 3 ? "8-node hexahedra" : "4-node quadrilaterals"));
      }
      for (std::size_t e = 0; e + static_cast<std::size_t>(npe) <= tags.size();
           e += static_cast<std::size_t>(npe)) {
        std::array<std::int64_t, 8> conn{};
        for (int a = 0; a < npe; ++a)
          conn[static_cast<std::size_t>(a)] = node(tags[e + static_cast<std::size_t>(a)]);
        orient(conn);
        mesh_.connectivity.insert(mesh_.connectivity.end(), conn.begin(), conn.begin() + npe);
        mesh_.element_part.push_back(r_.part);
        ++count;
      }
    }
    if (count == 0)
      throw InputError(r_.physical_where,
                       fmt::format("physical group '{}' in {} has no elements", g.name, r_.file.string()));
  }

  // Counter-clockwise quads and right-handed hexes: a surface meshed with its
  // normal along -z comes out of Gmsh clockwise. Mirroring the node order
  // (swap 1<->3, and 5<->7 in 3-D) fixes that without changing the element.
  // Truly inverted (self-intersecting) elements are left for the case check.
  void orient(std::array<std::int64_t, 8>& conn) const {
    const int npe = dim_ == 3 ? 8 : 4;
    double x[24];
    gather_element(dim_, mesh_.coordinates,
                   std::span<const std::int64_t>(conn.data(), static_cast<std::size_t>(npe)), 0, x);
    const double j = jacobian_determinant(
        dim_, std::span<const double>(x, static_cast<std::size_t>(npe * dim_)), Natural{0, 0, 0});
    if (j < 0.0) {
      std::swap(conn[1], conn[3]);
      if (dim_ == 3) std::swap(conn[5], conn[7]);
    }
  }

  void read_set(const PhysicalGroup& g) {
    const int face_type = dim_ == 3 ? gmsh_quad4 : gmsh_line2;
    const int fpn = dim_ == 3 ? 4 : 2;
    std::set<std::int64_t> nodes;
    auto& node_set = mesh_.node_sets[g.name];
    nodes.insert(node_set.begin(), node_set.end());
    auto& face_set = mesh_.face_sets[g.name];
    for (const auto& [type, tags] : group_elements(g)) {
      const int per = type == face_type ? fpn : (type == gmsh_point ? 1 : (type == gmsh_line2 ? 2 : 0));
      if (per == 0) continue;  // other boundary element types carry no set we can use
      for (std::size_t e = 0; e + static_cast<std::size_t>(per) <= tags.size();
           e += static_cast<std::size_t>(per)) {
        // Only nodes of this part's elements belong to its sets.
        std::array<std::int64_t, 4> face{};
        bool ours = true;
        for (int a = 0; a < per && ours; ++a) {
          const auto it = index_.find(tags[e + static_cast<std::size_t>(a)]);
          ours = it != index_.end();
          if (ours) face[static_cast<std::size_t>(a)] = it->second;
        }
        if (!ours) continue;
        for (int a = 0; a < per; ++a) nodes.insert(face[static_cast<std::size_t>(a)]);
        if (type == face_type && outward(face))
          face_set.insert(face_set.end(), face.begin(), face.begin() + fpn);
      }
    }
    node_set.assign(nodes.begin(), nodes.end());
    if (node_set.empty()) mesh_.node_sets.erase(g.name);
    if (face_set.empty()) mesh_.face_sets.erase(g.name);
  }

  // Orders a face so its normal points out of the element it bounds; false
  // when no element of this part has all its nodes (an interior-only group).
  bool outward(std::array<std::int64_t, 4>& face) {
    const int npe = dim_ == 3 ? 8 : 4, fpn = dim_ == 3 ? 4 : 2;
    if (node_elements_.empty()) {
      for (std::size_t e = 0; e < mesh_.element_count(); ++e)
        if (mesh_.element_part[e] == r_.part)
          for (int a = 0; a < npe; ++a)
            node_elements_[mesh_
                               .connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(a)]]
                .push_back(static_cast<std::int64_t>(e));
    }
    const auto it = node_elements_.find(face[0]);
    if (it == node_elements_.end()) return false;
    for (const std::int64_t e : it->second) {
      const auto* conn = &mesh_.connectivity[static_cast<std::size_t>(e * npe)];
      bool all = true;
      for (int a = 1; a < fpn && all; ++a)
        all = std::find(conn, conn + npe, face[static_cast<std::size_t>(a)]) != conn + npe;
      if (!all) continue;
      auto at = [&](std::int64_t n, int i) {
        return mesh_.coordinates[static_cast<std::size_t>(n * dim_ + i)];
      };
      std::array<double, 3> centre{}, face_centre{}, normal{};
      for (int a = 0; a < npe; ++a)
        for (int i = 0; i < dim_; ++i) centre[static_cast<std::size_t>(i)] += at(conn[a], i) / npe;
      for (int a = 0; a < fpn; ++a)
        for (int i = 0; i < dim_; ++i)
          face_centre[static_cast<std::size_t>(i)] += at(face[static_cast<std::size_t>(a)], i) / fpn;
      if (dim_ == 2) {
        // Edge a->b of a counter-clockwise boundary has outward normal (dy, -dx).
        normal = {at(face[1], 1) - at(face[0], 1), -(at(face[1], 0) - at(face[0], 0)), 0.0};
      } else {
        std::array<double, 3> d1{}, d2{};
        for (int i = 0; i < 3; ++i) {
          d1[static_cast<std::size_t>(i)] = at(face[2], i) - at(face[0], i);
          d2[static_cast<std::size_t>(i)] = at(face[3], i) - at(face[1], i);
        }
        normal = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                  d1[0] * d2[1] - d1[1] * d2[0]};
      }
      double s = 0.0;
      for (int i = 0; i < 3; ++i)
        s += normal[static_cast<std::size_t>(i)] *
             (face_centre[static_cast<std::size_t>(i)] - centre[static_cast<std::size_t>(i)]);
      if (s < 0.0) std::reverse(face.begin(), face.begin() + fpn);
      return true;
    }
    return false;
  }

  FemMesh& mesh_;
  const GmshPartRequest& r_;
  int dim_;
  std::unordered_map<std::size_t, std::array<double, 3>> file_coordinates_;
  std::map<std::array<double, 3>, std::int64_t> existing_;
  std::unordered_map<std::size_t, std::int64_t> index_;
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> node_elements_;
};

// The region of one physical group as simplices (import_gmsh_region).
std::vector<std::array<double, 3>> region_simplices(int dim, const std::filesystem::path& file,
                                                    const std::string& physical,
                                                    const SourceLocation& file_where,
                                                    const SourceLocation& physical_where) {
  const auto groups = physical_groups();
  const PhysicalGroup* group = nullptr;
  std::vector<std::string> names;
  for (const auto& g : groups) {
    names.push_back(g.name);
    if (g.name == physical && g.dim == dim) group = &g;
  }
  if (!group) {
    const std::string guess = nearest(physical, names);
    throw InputError(physical_where,
                     fmt::format("no {}-D physical group '{}' in {}{}", dim, physical, file.string(),
                                 guess.empty() ? fmt::format(" (it has: {})", fmt::join(names, ", "))
                                               : fmt::format("; did you mean '{}'?", guess)));
  }
  std::vector<std::size_t> tags;
  std::vector<double> coord, parametric;
  gmsh::model::mesh::getNodes(tags, coord, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::array<double, 3>> nodes;
  for (std::size_t k = 0; k < tags.size(); ++k)
    nodes[tags[k]] = {coord[3 * k], coord[3 * k + 1], coord[3 * k + 2]};
  std::vector<std::array<double, 3>> corners;
  for (const auto& [type, element_nodes] : group_elements(*group)) {
    const auto& cut = simplices_of(type);
    std::string type_name;
    int edim = 0, order = 0, nn = 0, nprimary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, type_name, edim, order, nn, local, nprimary);
    if (cut.empty())
      throw InputError(
          physical_where,
          fmt::format(
              "physical group '{}' in {} has {} elements; a particle region takes linear "
              "{} only",
              physical, file.string(), type_name,
              dim == 2 ? "triangles and quadrilaterals" : "tetrahedra, hexahedra, prisms and pyramids"));
    for (std::size_t e = 0; e + static_cast<std::size_t>(nn) <= element_nodes.size();
         e += static_cast<std::size_t>(nn))
      for (const auto& simplex : cut)
        for (const int a : simplex) {
          const auto it = nodes.find(element_nodes[e + static_cast<std::size_t>(a)]);
          if (it == nodes.end())
            throw InputError(file_where, fmt::format("{}: element refers to undefined node {}", file.string(),
                                                     element_nodes[e + static_cast<std::size_t>(a)]));
          if (dim == 2 && it->second[2] != 0.0)
            throw InputError(file_where,
                             fmt::format("{}: node {} has z = {}; a 2-D region must lie in the plane z = 0",
                                         file.string(), it->first, it->second[2]));
          corners.push_back(it->second);
        }
  }
  if (corners.empty())
    throw InputError(physical_where,
                     fmt::format("physical group '{}' in {} has no elements", physical, file.string()));
  return corners;
}

}  // namespace

SimplexRegion import_gmsh_region(int dimension, const std::filesystem::path& file,
                                 const std::string& physical, const SourceLocation& file_where,
                                 const SourceLocation& physical_where) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw InputError(file_where, fmt::format("mesh file '{}' not found", file.string()));
  std::lock_guard<std::mutex> lock(gmsh_mutex());
  std::vector<std::array<double, 3>> corners;
  try {
    ensure_gmsh();
    gmsh::clear();
    gmsh::open(file.string());
    corners = region_simplices(dimension, file, physical, file_where, physical_where);
  } catch (const InputError&) {
    gmsh::clear();
    throw;
  } catch (...) {
    const std::string why = last_gmsh_error();
    try {
      gmsh::clear();
    } catch (...) {
    }
    throw InputError(file_where, fmt::format("cannot read mesh file '{}': {}", file.string(), why));
  }
  gmsh::clear();
  return SimplexRegion(dimension, std::move(corners));
}

void import_gmsh_part(FemMesh& mesh, const GmshPartRequest& request) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(request.file, ec))
    throw InputError(request.file_where, fmt::format("mesh file '{}' not found", request.file.string()));
  std::lock_guard<std::mutex> lock(gmsh_mutex());
  // Work on a copy so a failure half-way leaves the caller's mesh untouched.
  FemMesh work = mesh;
  try {
    ensure_gmsh();
    gmsh::clear();
    gmsh::open(request.file.string());
    Importer(work, request).run();
  } catch (const InputError&) {
    gmsh::clear();
    throw;
  } catch (...) {
    // Gmsh reports parse errors by exceptions of its own type; its logger keeps the text.
    const std::string why = last_gmsh_error();
    try {
      gmsh::clear();
    } catch (...) {
    }
    throw InputError(request.file_where,
                     fmt::format("cannot read mesh file '{}': {}", request.file.string(), why));
  }
  gmsh::clear();
  mesh = std::move(work);
}

}  // namespace camouflet
