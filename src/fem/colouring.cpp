#include "fem/colouring.hpp"

#include <bit>
#include <stdexcept>

namespace camouflet {

std::vector<std::vector<std::int64_t>> colour_elements(const std::vector<std::int64_t>& connectivity,
                                                       int nodes_per_element, std::size_t node_count) {
  const std::size_t npe = static_cast<std::size_t>(nodes_per_element);
  const std::size_t n = connectivity.size() / npe;
  // Bit c of used[node] is set when an element of colour c touches the node.
  std::vector<std::uint64_t> used(node_count, 0);
  std::vector<std::vector<std::int64_t>> colours;
  for (std::size_t e = 0; e < n; ++e) {
    std::uint64_t taken = 0;
    for (std::size_t a = 0; a < npe; ++a) taken |= used[static_cast<std::size_t>(connectivity[e * npe + a])];
    if (~taken == 0) throw std::runtime_error("element colouring needs more than 64 colours");
    const int c = std::countr_one(taken);
    for (std::size_t a = 0; a < npe; ++a)
      used[static_cast<std::size_t>(connectivity[e * npe + a])] |= 1ull << c;
    if (static_cast<std::size_t>(c) >= colours.size()) colours.resize(static_cast<std::size_t>(c) + 1);
    colours[static_cast<std::size_t>(c)].push_back(static_cast<std::int64_t>(e));
  }
  return colours;
}

}  // namespace camouflet
