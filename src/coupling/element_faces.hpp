#pragma once
// The faces of quad4 and hex8 elements as the SPH-FEM join sees them: the
// local face tables (outward node order: quad edges counter-clockwise, hex
// faces as their outward normals turn), one face's nodes, and the element
// across each face. Shared by the join's set-up (sph_fem_join.cpp) and its
// rebuild after erosion (join_erosion.cpp).
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "fem/fem_elements.hpp"
#include "mesh/element_face_tables.hpp"

namespace camouflet::join_faces {

template <int D>
inline constexpr int per_element = D == 2 ? 4 : 6;
template <int D>
inline constexpr int nodes_per_face = D == 2 ? 2 : 4;

using element_face_tables::hex;
using element_face_tables::quad;

// The nodes of local face f of element e, in the table's order.
template <int D>
std::array<std::int64_t, nodes_per_face<D>> nodes(const FemElements<D>& elements, std::size_t e, int f) {
  constexpr int N = FemElements<D>::nodes;
  std::array<std::int64_t, nodes_per_face<D>> q{};
  for (std::size_t a = 0; a < q.size(); ++a)
    q[a] = elements.connectivity[e * N + static_cast<std::size_t>(D == 2 ? quad[f][a] : hex[f][a])];
  return q;
}

// For element e and local face f, entry e * per_element<D> + f: the element across that face,
// or -1 where the face bounds the mesh. A face of a conforming mesh has at most two elements; a
// face listed by more (not a conforming mesh) counts as shared by the first two.
template <int D>
std::vector<std::int64_t> neighbours(const FemElements<D>& elements) {
  constexpr int F = per_element<D>;
  std::map<std::array<std::int64_t, nodes_per_face<D>>, std::int64_t> first;
  std::vector<std::int64_t> across(elements.size() * F, -1);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (int f = 0; f < F; ++f) {
      auto key = nodes<D>(elements, e, f);
      std::sort(key.begin(), key.end());
      const std::size_t here = e * F + static_cast<std::size_t>(f);
      const auto [it, inserted] = first.try_emplace(key, static_cast<std::int64_t>(here));
      if (inserted) continue;
      const auto other = static_cast<std::size_t>(it->second);
      across[here] = static_cast<std::int64_t>(other / F);
      if (across[other] < 0) across[other] = static_cast<std::int64_t>(e);
    }
  return across;
}

}  // namespace camouflet::join_faces
