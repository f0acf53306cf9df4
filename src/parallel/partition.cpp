#include "parallel/partition.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "mesh/element_face_tables.hpp"
#include "parallel/face_key.hpp"

namespace camouflet {

namespace {

int weight_of(std::span<const int> weights, std::size_t e) {
  return weights.empty() ? 1 : weights[e];
}

}  // namespace

ElementGraph element_face_graph(const FemMesh& mesh) {
  const std::size_t elements = mesh.element_count();
  const auto npe = static_cast<std::size_t>(mesh.nodes_per_element);
  const bool hex = mesh.dimension == 3;
  const int faces_per_element = hex ? 6 : 4, face_nodes = hex ? 4 : 2;
  // Every face as its sorted nodes (unused slots -1) then its element; two elements sharing the
  // nodes share the face.
  using Face = std::array<std::int64_t, 5>;
  std::vector<Face> faces;
  faces.reserve(elements * static_cast<std::size_t>(faces_per_element));
  for (std::size_t e = 0; e < elements; ++e)
    for (int f = 0; f < faces_per_element; ++f) {
      const auto key = face_key(face_nodes, [&](int a) {
        const int local = hex ? element_face_tables::hex[f][a] : element_face_tables::quad[f][a];
        return mesh.connectivity[e * npe + static_cast<std::size_t>(local)];
      });
      Face face{key[0], key[1], key[2], key[3], 0};
      face[4] = static_cast<std::int64_t>(e);
      faces.push_back(face);
    }
  std::sort(faces.begin(), faces.end());
  auto same_nodes = [](const Face& a, const Face& b) {
    return std::equal(a.begin(), a.begin() + 4, b.begin());
  };
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (std::size_t i = 0; i + 1 < faces.size(); ++i)
    if (same_nodes(faces[i], faces[i + 1]) && faces[i][4] != faces[i + 1][4]) {
      pairs.emplace_back(faces[i][4], faces[i + 1][4]);
      pairs.emplace_back(faces[i + 1][4], faces[i][4]);
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  ElementGraph graph;
  graph.offsets.assign(elements + 1, 0);
  for (const auto& [a, b] : pairs) ++graph.offsets[static_cast<std::size_t>(a) + 1];
  std::partial_sum(graph.offsets.begin(), graph.offsets.end(), graph.offsets.begin());
  graph.neighbours.reserve(pairs.size());
  for (const auto& [a, b] : pairs) graph.neighbours.push_back(b);
  return graph;
}

std::vector<int> partition_elements(const FemMesh& mesh, int parts, std::span<const int> weights) {
  const std::size_t elements = mesh.element_count();
  if (parts < 1) throw std::invalid_argument("partition_elements: parts must be >= 1");
  if (!weights.empty() && weights.size() != elements)
    throw std::invalid_argument("partition_elements: one weight per element");
  if (parts == 1 || elements == 0) return std::vector<int>(elements, 0);
  if (static_cast<std::size_t>(parts) > elements)
    throw std::invalid_argument(fmt::format(
        "partition_elements: {} parts for {} elements: at least one element a part", parts, elements));
  if (elements > static_cast<std::size_t>(std::numeric_limits<idx_t>::max() / 8))
    throw std::invalid_argument(fmt::format(
        "partition_elements: {} elements is beyond this METIS's 32-bit indices (idx_t)", elements));
  const ElementGraph graph = element_face_graph(mesh);
  std::vector<idx_t> xadj(graph.offsets.begin(), graph.offsets.end());
  std::vector<idx_t> adjncy(graph.neighbours.begin(), graph.neighbours.end());
  std::vector<idx_t> vwgt(elements);
  for (std::size_t e = 0; e < elements; ++e) {
    const int w = weight_of(weights, e);
    if (w < 1)
      throw std::invalid_argument(fmt::format("partition_elements: weight {} of element {} is < 1", w, e));
    vwgt[e] = w;
  }
  idx_t nvtxs = static_cast<idx_t>(elements), ncon = 1, nparts = parts, objval = 0;
  std::vector<idx_t> part(elements, 0);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_CONTIG] = 1;  // each part one piece: no halo between a part's own islands
  int status = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr, nullptr,
                                   &nparts, nullptr, nullptr, options, &objval, part.data());
  if (status == METIS_ERROR_INPUT && options[METIS_OPTION_CONTIG] == 1) {
    // A mesh of several unconnected bodies cannot have contiguous parts.
    options[METIS_OPTION_CONTIG] = 0;
    status = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr, nullptr,
                                 &nparts, nullptr, nullptr, options, &objval, part.data());
  }
  if (status != METIS_OK)
    throw std::runtime_error(
        fmt::format("partition_elements: METIS_PartGraphKway failed (status {}) for {} parts of "
                    "{} elements",
                    status, parts, elements));
  return {part.begin(), part.end()};
}

PartitionQuality measure_partition(const FemMesh& mesh, std::span<const int> part, int parts,
                                   std::span<const int> weights) {
  const std::size_t elements = mesh.element_count();
  PartitionQuality q;
  if (elements == 0 || parts < 1) return q;
  std::vector<double> load(static_cast<std::size_t>(parts), 0.0);
  double total = 0.0;
  for (std::size_t e = 0; e < elements; ++e) {
    load[static_cast<std::size_t>(part[e])] += weight_of(weights, e);
    total += weight_of(weights, e);
  }
  q.imbalance = *std::max_element(load.begin(), load.end()) / (total / parts);
  const ElementGraph graph = element_face_graph(mesh);
  for (std::size_t e = 0; e < elements; ++e)
    for (auto k = graph.offsets[e]; k < graph.offsets[e + 1]; ++k)
      if (part[e] != part[static_cast<std::size_t>(graph.neighbours[static_cast<std::size_t>(k)])] &&
          static_cast<std::int64_t>(e) < graph.neighbours[static_cast<std::size_t>(k)])
        ++q.cut_faces;
  // Pieces of each part: a flood fill over the graph within the part.
  std::vector<char> seen(elements, 0);
  std::vector<int> pieces(static_cast<std::size_t>(parts), 0);
  std::vector<std::int64_t> stack;
  for (std::size_t start = 0; start < elements; ++start) {
    if (seen[start]) continue;
    ++pieces[static_cast<std::size_t>(part[start])];
    seen[start] = 1;
    stack.assign(1, static_cast<std::int64_t>(start));
    while (!stack.empty()) {
      const auto e = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      for (auto k = graph.offsets[e]; k < graph.offsets[e + 1]; ++k) {
        const auto n = static_cast<std::size_t>(graph.neighbours[static_cast<std::size_t>(k)]);
        if (!seen[n] && part[n] == part[e]) seen[n] = 1, stack.push_back(static_cast<std::int64_t>(n));
      }
    }
  }
  for (int p : pieces) q.split_parts += p > 1 ? 1 : 0;
  return q;
}

}  // namespace camouflet
