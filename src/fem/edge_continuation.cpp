#include "fem/edge_continuation.hpp"

#include <algorithm>
#include <cmath>

#include "fem/edge_viscosity.hpp"

namespace camouflet {

template <int D>
std::vector<std::int64_t> edge_continuations(const std::vector<std::int64_t>& connectivity, std::size_t node_count,
                                             const double* x) {
  using E = ElementEdges<D>;
  constexpr int N = E::nodes;
  const std::size_t ne = connectivity.size() / N;
  // The elements around each node (compressed rows).
  std::vector<std::size_t> start(node_count + 1, 0);
  for (const std::int64_t n : connectivity) ++start[static_cast<std::size_t>(n) + 1];
  for (std::size_t n = 0; n < node_count; ++n) start[n + 1] += start[n];
  std::vector<std::size_t> around(connectivity.size()), fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < ne; ++e)
    for (int a = 0; a < N; ++a) around[fill[static_cast<std::size_t>(connectivity[e * N + a])]++] = e;
  const auto holds = [&](std::size_t e, std::int64_t n) {
    const std::int64_t* c = &connectivity[e * N];
    return std::find(c, c + N, n) != c + N;
  };
  // The node beyond p on the line q -> p, or -1.
  const auto beyond = [&](std::int64_t p, std::int64_t q) -> std::int64_t {
    const auto P = static_cast<std::size_t>(p);
    double dir[D], length = 0.0;
    for (int i = 0; i < D; ++i) dir[i] = x[p * D + i] - x[q * D + i], length += dir[i] * dir[i];
    length = std::sqrt(length);
    std::int64_t best = -1;
    double best_cos = 0.5;  // within 60 degrees of q -> p
    for (std::size_t s = start[P]; s < start[P + 1]; ++s) {
      const std::size_t e = around[s];
      const std::int64_t* c = &connectivity[e * N];
      for (int k = 0; k < E::count; ++k) {
        const std::int64_t a = c[E::node[k][0]], b = c[E::node[k][1]];
        if (a != p && b != p) continue;
        const std::int64_t n = a == p ? b : a;
        if (n == q) continue;
        // n must not share an element with both p and q (an edge across the line, not along it).
        bool across = false;
        for (std::size_t t = start[P]; t < start[P + 1] && !across; ++t)
          across = holds(around[t], q) && holds(around[t], n);
        if (across) continue;
        double d[D], dl = 0.0, dot = 0.0;
        for (int i = 0; i < D; ++i) d[i] = x[n * D + i] - x[p * D + i], dl += d[i] * d[i], dot += d[i] * dir[i];
        const double cosine = dl > 0.0 && length > 0.0 ? dot / (std::sqrt(dl) * length) : 0.0;
        if (cosine > best_cos) best_cos = cosine, best = n;
      }
    }
    return best;
  };
  std::vector<std::int64_t> out(ne * E::count * 2, -1);
#pragma omp parallel for schedule(static)
  for (std::int64_t es = 0; es < static_cast<std::int64_t>(ne); ++es) {
    const auto e = static_cast<std::size_t>(es);
    for (int k = 0; k < E::count; ++k) {
      const std::int64_t p = connectivity[e * N + E::node[k][0]], q = connectivity[e * N + E::node[k][1]];
      out[(e * E::count + k) * 2] = beyond(p, q);
      out[(e * E::count + k) * 2 + 1] = beyond(q, p);
    }
  }
  return out;
}

template std::vector<std::int64_t> edge_continuations<2>(const std::vector<std::int64_t>&, std::size_t,
                                                         const double*);
template std::vector<std::int64_t> edge_continuations<3>(const std::vector<std::int64_t>&, std::size_t,
                                                         const double*);

}  // namespace camouflet
