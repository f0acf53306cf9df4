#include "fem/element_colouring.hpp"

#include <algorithm>

namespace camouflet {

ElementColouring colour_elements(const std::vector<std::int64_t>& connectivity, int nodes_per_element,
                                 std::size_t node_count) {
  const std::size_t per = static_cast<std::size_t>(nodes_per_element);
  const std::size_t ne = per > 0 ? connectivity.size() / per : 0;
  // The elements around each node (compressed rows).
  std::vector<std::size_t> first(node_count + 1, 0);
  for (const std::int64_t node : connectivity) ++first[static_cast<std::size_t>(node) + 1];
  for (std::size_t k = 0; k < node_count; ++k) first[k + 1] += first[k];
  std::vector<std::uint32_t> around(connectivity.size());
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t e = 0; e < ne; ++e)
      for (std::size_t a = 0; a < per; ++a)
        around[fill[static_cast<std::size_t>(connectivity[e * per + a])]++] = static_cast<std::uint32_t>(e);
  }
  // Greedy: stamp the colours of the already coloured elements that share a node, take the
  // smallest colour not stamped. taken[c] == e + 1 marks colour c as forbidden for element e.
  std::vector<int> colour(ne, -1);
  std::vector<std::size_t> taken;
  std::vector<std::size_t> size;  // elements per colour
  for (std::size_t e = 0; e < ne; ++e) {
    for (std::size_t a = 0; a < per; ++a) {
      const std::size_t node = static_cast<std::size_t>(connectivity[e * per + a]);
      for (std::size_t k = first[node]; k < first[node + 1]; ++k) {
        const int c = colour[around[k]];
        if (c >= 0) taken[static_cast<std::size_t>(c)] = e + 1;
      }
    }
    std::size_t c = 0;
    while (c < taken.size() && taken[c] == e + 1) ++c;
    if (c == taken.size()) {
      taken.push_back(0);
      size.push_back(0);
    }
    colour[e] = static_cast<int>(c);
    ++size[c];
  }
  ElementColouring result;
  result.begin.assign(size.size() + 1, 0);
  for (std::size_t c = 0; c < size.size(); ++c) result.begin[c + 1] = result.begin[c] + size[c];
  result.elements.resize(ne);
  std::vector<std::size_t> fill(result.begin.begin(), result.begin.end() - 1);
  for (std::size_t e = 0; e < ne; ++e)
    result.elements[fill[static_cast<std::size_t>(colour[e])]++] = static_cast<std::uint32_t>(e);
  return result;
}

}  // namespace camouflet
