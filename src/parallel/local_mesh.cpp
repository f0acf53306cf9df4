#include "parallel/local_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "mesh/element_face_tables.hpp"
#include "parallel/face_key.hpp"

namespace camouflet {

LocalMesh local_mesh(const FemMesh& global, std::span<const int> part, int rank,
                     std::span<const std::vector<std::int64_t>> extra_nodes) {
  const std::size_t elements = global.element_count(), nodes = global.node_count();
  if (part.size() != elements)
    throw std::invalid_argument(fmt::format("local_mesh: {} parts for {} elements", part.size(), elements));
  const auto npe = static_cast<std::size_t>(global.nodes_per_element);
  const auto dim = static_cast<std::size_t>(global.dimension);
  LocalMesh local;
  local.mesh.dimension = global.dimension;
  local.mesh.nodes_per_element = global.nodes_per_element;

  // The ranks that hold each node, as a sorted list per node (most nodes: one).
  std::vector<std::vector<int>> holders(nodes);
  for (std::size_t e = 0; e < elements; ++e)
    for (std::size_t a = 0; a < npe; ++a) {
      auto& h = holders[static_cast<std::size_t>(global.connectivity[e * npe + a])];
      if (std::find(h.begin(), h.end(), part[e]) == h.end()) h.push_back(part[e]);
    }
  for (std::size_t r = 0; r < extra_nodes.size(); ++r)
    for (const std::int64_t n : extra_nodes[r]) {
      auto& h = holders[static_cast<std::size_t>(n)];
      if (std::find(h.begin(), h.end(), static_cast<int>(r)) == h.end()) h.push_back(static_cast<int>(r));
    }
  for (auto& h : holders) std::sort(h.begin(), h.end());

  std::vector<std::int64_t> local_of(nodes, -1);
  for (std::size_t n = 0; n < nodes; ++n)
    if (std::binary_search(holders[n].begin(), holders[n].end(), rank)) {
      local_of[n] = static_cast<std::int64_t>(local.global_node.size());
      local.global_node.push_back(static_cast<std::int64_t>(n));
      for (std::size_t d = 0; d < dim; ++d) local.mesh.coordinates.push_back(global.coordinates[n * dim + d]);
      local.owned.push_back(holders[n].front() == rank ? 1 : 0);
    }
  for (std::size_t e = 0; e < elements; ++e) {
    if (part[e] != rank) continue;
    local.global_element.push_back(static_cast<std::int64_t>(e));
    for (std::size_t a = 0; a < npe; ++a)
      local.mesh.connectivity.push_back(local_of[static_cast<std::size_t>(global.connectivity[e * npe + a])]);
    local.mesh.element_part.push_back(global.element_part[e]);
  }

  for (const auto& [name, set] : global.node_sets) {
    auto& mine = local.mesh.node_sets[name];
    for (std::int64_t n : set)
      if (local_of[static_cast<std::size_t>(n)] >= 0) mine.push_back(local_of[static_cast<std::size_t>(n)]);
  }
  // A face of a set belongs to the element that has it among its faces; it stays with that
  // element's rank.
  const int face_nodes = global.dimension == 3 ? 4 : 2, faces_per_element = global.dimension == 3 ? 6 : 4;
  using Key = std::array<std::int64_t, 4>;
  std::map<Key, int> face_rank;
  bool have_face_sets = false;
  for (const auto& [name, set] : global.face_sets) have_face_sets = have_face_sets || !set.empty();
  if (have_face_sets)
    for (std::size_t e = 0; e < elements; ++e)
      for (int f = 0; f < faces_per_element; ++f) {
        const Key key = face_key(face_nodes, [&](int i) {
          const int l =
              global.dimension == 3 ? element_face_tables::hex[f][i] : element_face_tables::quad[f][i];
          return global.connectivity[e * npe + static_cast<std::size_t>(l)];
        });
        face_rank.emplace(key, part[e]);  // an interior face: either element's rank; boundary faces are one's
      }
  for (const auto& [name, set] : global.face_sets) {
    auto& mine = local.mesh.face_sets[name];
    for (std::size_t k = 0; k + static_cast<std::size_t>(face_nodes) <= set.size();
         k += static_cast<std::size_t>(face_nodes)) {
      const Key key = face_key(face_nodes, [&](int i) { return set[k + static_cast<std::size_t>(i)]; });
      const auto found = face_rank.find(key);
      if (found == face_rank.end() || found->second != rank) continue;
      for (int a = 0; a < face_nodes; ++a)
        mine.push_back(local_of[static_cast<std::size_t>(set[k + static_cast<std::size_t>(a)])]);
    }
  }

  // Neighbours: every other rank holding one of this rank's nodes; their shared nodes in
  // ascending global id (the local numbering already is).
  std::map<int, std::vector<std::int64_t>> shared;
  for (std::size_t l = 0; l < local.global_node.size(); ++l)
    for (int r : holders[static_cast<std::size_t>(local.global_node[l])])
      if (r != rank) shared[r].push_back(static_cast<std::int64_t>(l));
  for (std::size_t l = 0; l < local.global_node.size(); ++l)
    if (holders[static_cast<std::size_t>(local.global_node[l])].size() > 1)
      local.shared_nodes.push_back(static_cast<std::int64_t>(l));
  for (auto& [r, list] : shared) {
    LocalMesh::Neighbour nb{r, std::move(list), {}};
    for (const std::int64_t n : nb.nodes)
      nb.slots.push_back(std::lower_bound(local.shared_nodes.begin(), local.shared_nodes.end(), n) -
                         local.shared_nodes.begin());
    local.neighbours.push_back(std::move(nb));
  }
  return local;
}

void sum_shared_nodes(const Communicator& comm, const LocalMesh& local, std::span<double> values,
                      int components) {
  if (local.neighbours.empty()) return;
  const auto c = static_cast<std::size_t>(components);
  std::vector<std::vector<double>> sends(local.neighbours.size()), receives(local.neighbours.size());
  std::vector<int> ranks;
  for (std::size_t i = 0; i < local.neighbours.size(); ++i) {
    const auto& nb = local.neighbours[i];
    ranks.push_back(nb.rank);
    for (std::int64_t n : nb.nodes)
      for (std::size_t k = 0; k < c; ++k) sends[i].push_back(values[static_cast<std::size_t>(n) * c + k]);
    receives[i].resize(sends[i].size());
  }
  comm.exchange(ranks, sends, receives);
  // In ascending rank order: the ranks below this one, this one, the ranks above. A node's sum
  // starts from nought on every rank, so every holder adds the same values in the same order.
  const std::size_t ns = local.shared_nodes.size();
  std::vector<double> total(ns * c, 0.0);
  auto add_from = [&](std::size_t i) {
    const auto& nb = local.neighbours[i];
    for (std::size_t j = 0; j < nb.nodes.size(); ++j)
      for (std::size_t k = 0; k < c; ++k) total[static_cast<std::size_t>(nb.slots[j]) * c + k] += receives[i][j * c + k];
  };
  std::size_t i = 0;
  for (; i < local.neighbours.size() && local.neighbours[i].rank < comm.rank(); ++i) add_from(i);
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t k = 0; k < c; ++k) total[s * c + k] += values[static_cast<std::size_t>(local.shared_nodes[s]) * c + k];
  for (; i < local.neighbours.size(); ++i) add_from(i);
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t k = 0; k < c; ++k) values[static_cast<std::size_t>(local.shared_nodes[s]) * c + k] = total[s * c + k];
}

}  // namespace camouflet
