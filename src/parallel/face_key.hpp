#pragma once
// A face as the set of its nodes: sorted, unused slots -1 (2 nodes in 2-D, 4 in 3-D), so that
// the two elements sharing a face give the same key.
#include <array>
#include <cstdint>

namespace camouflet {

template <class NodeOf>
std::array<std::int64_t, 4> face_key(int count, const NodeOf& node_of) {
  std::array<std::int64_t, 4> key{-1, -1, -1, -1};
  for (int a = 0; a < count; ++a) {
    // Insertion into the sorted front: at most four nodes.
    std::int64_t n = node_of(a);
    int i = a;
    for (; i > 0 && key[static_cast<std::size_t>(i - 1)] > n; --i)
      key[static_cast<std::size_t>(i)] = key[static_cast<std::size_t>(i - 1)];
    key[static_cast<std::size_t>(i)] = n;
  }
  return key;
}

}  // namespace camouflet
