#include "mesh/detach_parts.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "mesh/element_face_tables.hpp"

namespace camouflet {

namespace {

struct FaceTable {
  int faces = 0, nodes = 0;
  int local(int f, int a) const {
    return nodes == 2 ? element_face_tables::quad[f][a] : element_face_tables::hex[f][a];
  }
};

using Key = std::array<std::int64_t, 4>;

Key sorted_key(const std::int64_t* q, int n) {
  Key k{-1, -1, -1, -1};
  std::copy(q, q + n, k.begin());
  std::sort(k.begin(), k.begin() + n);
  return k;
}

// Whether b is a cyclic rotation of a in the same direction (the same outward face); an edge
// (n = 2) only in the same order.
bool same_turn(const std::int64_t* a, const std::int64_t* b, int n) {
  for (int shift = 0; shift < (n == 2 ? 1 : n); ++shift) {
    bool all = true;
    for (int i = 0; i < n && all; ++i) all = a[i] == b[(i + shift) % n];
    if (all) return true;
  }
  return false;
}

}  // namespace

std::vector<std::int64_t> element_face_nodes(const FemMesh& mesh, const std::vector<ElementFace>& faces) {
  const FaceTable table{mesh.dimension == 2 ? 4 : 6, mesh.dimension == 2 ? 2 : 4};
  std::vector<std::int64_t> out;
  out.reserve(faces.size() * static_cast<std::size_t>(table.nodes));
  for (const ElementFace& f : faces)
    for (int a = 0; a < table.nodes; ++a)
      out.push_back(mesh.connectivity[static_cast<std::size_t>(f.element * mesh.nodes_per_element) +
                                      static_cast<std::size_t>(table.local(f.face, a))]);
  return out;
}

DetachedInterface detach_parts(FemMesh& mesh, const std::vector<char>& in_group) {
  DetachedInterface out;
  const int npe = mesh.nodes_per_element;
  const FaceTable table{mesh.dimension == 2 ? 4 : 6, mesh.dimension == 2 ? 2 : 4};
  const std::size_t elements = mesh.element_count(), nodes = mesh.node_count();
  auto group = [&](std::size_t e) {
    const auto p = static_cast<std::size_t>(mesh.element_part[e]);
    return p < in_group.size() && in_group[p] != 0;
  };

  // Nodes used on both sides.
  std::vector<char> used_a(nodes, 0), used_b(nodes, 0);
  for (std::size_t e = 0; e < elements; ++e)
    for (int a = 0; a < npe; ++a) {
      const auto n = static_cast<std::size_t>(
          mesh.connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(a)]);
      (group(e) ? used_a : used_b)[n] = 1;
    }
  std::vector<std::int64_t> copy(nodes, -1);
  std::int64_t next = static_cast<std::int64_t>(nodes);
  for (std::size_t n = 0; n < nodes; ++n)
    if (used_a[n] && used_b[n]) copy[n] = next++;
  out.doubled_nodes = static_cast<std::size_t>(next) - nodes;
  if (out.doubled_nodes == 0) return out;

  // Every element face with its owner, before the copies (keys of original nodes).
  struct Owner {
    std::size_t element;
    int face;
  };
  std::map<Key, std::vector<Owner>> owners;
  auto face_nodes = [&](std::size_t e, int f, std::int64_t* q) {
    for (int a = 0; a < table.nodes; ++a)
      q[a] =
          mesh.connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(table.local(f, a))];
  };
  for (std::size_t e = 0; e < elements; ++e)
    for (int f = 0; f < table.faces; ++f) {
      std::int64_t q[4];
      face_nodes(e, f, q);
      owners[sorted_key(q, table.nodes)].push_back({e, f});
    }

  // The interface: faces with an owner on each side.
  std::vector<std::pair<Owner, Owner>> interface;
  for (const auto& [key, list] : owners) {
    const Owner* a = nullptr;
    const Owner* b = nullptr;
    for (const Owner& o : list) (group(o.element) ? a : b) = &o;
    if (a && b) interface.push_back({*a, *b});
  }

  // Face sets: a face bounding an element outside the group moves to the copies. Decided on the
  // original nodes, before the connectivity changes.
  for (auto& [name, faces] : mesh.face_sets)
    for (std::size_t k = 0; k + static_cast<std::size_t>(table.nodes) <= faces.size();
         k += static_cast<std::size_t>(table.nodes)) {
      std::int64_t* q = &faces[k];
      const auto it = owners.find(sorted_key(q, table.nodes));
      if (it == owners.end()) continue;
      for (const Owner& o : it->second) {
        std::int64_t local[4];
        face_nodes(o.element, o.face, local);
        if (!same_turn(local, q, table.nodes)) continue;
        if (!group(o.element))
          for (int a = 0; a < table.nodes; ++a)
            if (copy[static_cast<std::size_t>(q[a])] >= 0) q[a] = copy[static_cast<std::size_t>(q[a])];
        break;
      }
    }

  // The copies: coordinates appended, the outside elements renumbered.
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  mesh.coordinates.resize(static_cast<std::size_t>(next) * dim);
  for (std::size_t n = 0; n < nodes; ++n)
    if (copy[n] >= 0)
      for (std::size_t i = 0; i < dim; ++i)
        mesh.coordinates[static_cast<std::size_t>(copy[n]) * dim + i] = mesh.coordinates[n * dim + i];
  for (std::size_t e = 0; e < elements; ++e) {
    if (group(e)) continue;
    for (int a = 0; a < npe; ++a) {
      std::int64_t& n = mesh.connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(a)];
      if (copy[static_cast<std::size_t>(n)] >= 0) n = copy[static_cast<std::size_t>(n)];
    }
  }
  for (auto& [name, set] : mesh.node_sets) {
    const std::size_t size = set.size();
    for (std::size_t k = 0; k < size; ++k)
      if (copy[static_cast<std::size_t>(set[k])] >= 0) set.push_back(copy[static_cast<std::size_t>(set[k])]);
  }

  for (const auto& [a, b] : interface) {
    out.a.push_back({static_cast<std::int64_t>(a.element), a.face});
    out.b.push_back({static_cast<std::int64_t>(b.element), b.face});
  }
  return out;
}

}  // namespace camouflet
