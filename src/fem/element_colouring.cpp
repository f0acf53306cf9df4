#include "fem/element_colouring.hpp"

#include <algorithm>

namespace camouflet {

ElementColouring colour_elements(const std::vector<std::int64_t>& connectivity, int nodes_per_element,
                                 std::size_t node_count, std::size_t block) {
  const std::size_t per = static_cast<std::size_t>(nodes_per_element);
  const std::size_t ne = per > 0 ? connectivity.size() / per : 0;
  block = std::max<std::size_t>(block, 1);
  const std::size_t nb = (ne + block - 1) / block;
  const auto block_of = [&](std::size_t e) { return e / block; };
  // The blocks around each node (compressed rows; a block may appear more than once).
  std::vector<std::size_t> first(node_count + 1, 0);
  for (const std::int64_t node : connectivity) ++first[static_cast<std::size_t>(node) + 1];
  for (std::size_t k = 0; k < node_count; ++k) first[k + 1] += first[k];
  std::vector<std::uint32_t> around(connectivity.size());
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t e = 0; e < ne; ++e)
      for (std::size_t a = 0; a < per; ++a)
        around[fill[static_cast<std::size_t>(connectivity[e * per + a])]++] =
            static_cast<std::uint32_t>(block_of(e));
  }
  // Greedy: stamp the colours of the already coloured blocks that share a node, take the
  // smallest colour not stamped. taken[c] == b + 1 marks colour c as forbidden for block b.
  std::vector<int> colour(nb, -1);
  std::vector<std::size_t> taken;
  std::vector<std::size_t> size;  // blocks per colour
  for (std::size_t b = 0; b < nb; ++b) {
    for (std::size_t e = b * block; e < std::min(ne, (b + 1) * block); ++e)
      for (std::size_t a = 0; a < per; ++a) {
        const std::size_t node = static_cast<std::size_t>(connectivity[e * per + a]);
        for (std::size_t k = first[node]; k < first[node + 1]; ++k) {
          const int c = colour[around[k]];
          if (c >= 0) taken[static_cast<std::size_t>(c)] = b + 1;
        }
      }
    std::size_t c = 0;
    while (c < taken.size() && taken[c] == b + 1) ++c;
    if (c == taken.size()) {
      taken.push_back(0);
      size.push_back(0);
    }
    colour[b] = static_cast<int>(c);
    ++size[c];
  }
  ElementColouring result;
  result.block = block;
  result.begin.assign(size.size() + 1, 0);
  for (std::size_t c = 0; c < size.size(); ++c) result.begin[c + 1] = result.begin[c] + size[c];
  result.blocks.resize(nb);
  std::vector<std::size_t> fill(result.begin.begin(), result.begin.end() - 1);
  for (std::size_t b = 0; b < nb; ++b)
    result.blocks[fill[static_cast<std::size_t>(colour[b])]++] = static_cast<std::uint32_t>(b);
  return result;
}

}  // namespace camouflet
