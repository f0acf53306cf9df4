#include "model/bar_hosts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "model/isoparametric.hpp"

namespace camouflet {

namespace {

// The lowest-numbered element of `host_part` (any part when -1) containing x, with its natural
// coordinates; nothing when none does.
std::optional<ElementLocation> find_host(const FemMesh& mesh, int host_part, const double* x) {
  const int dim = mesh.dimension, npe = mesh.nodes_per_element;
  const std::size_t ne = mesh.element_count();
  std::vector<double> nodes(static_cast<std::size_t>(npe * dim));
  for (std::size_t e = 0; e < ne; ++e) {
    if (host_part >= 0 && mesh.element_part[e] != host_part) continue;
    gather_element(dim, mesh.coordinates, mesh.connectivity, static_cast<std::int64_t>(e), nodes.data());
    bool inside_box = true;
    for (int i = 0; i < dim && inside_box; ++i) {
      double lo = std::numeric_limits<double>::max(), hi = -lo;
      for (int a = 0; a < npe; ++a) {
        lo = std::min(lo, nodes[static_cast<std::size_t>(a * dim + i)]);
        hi = std::max(hi, nodes[static_cast<std::size_t>(a * dim + i)]);
      }
      const double tol = 1e-9 * (hi - lo);
      inside_box = x[i] >= lo - tol && x[i] <= hi + tol;
    }
    if (!inside_box) continue;
    const auto xi = inverse_map(dim, nodes, std::span<const double>(x, static_cast<std::size_t>(dim)));
    if (!xi) continue;
    bool inside = true;
    for (int i = 0; i < dim; ++i)
      inside = inside && std::abs((*xi)[static_cast<std::size_t>(i)]) <= 1.0 + 1e-8;
    if (inside) return ElementLocation{static_cast<std::int64_t>(e), *xi};
  }
  return std::nullopt;
}

}  // namespace

BarHosts locate_bar_nodes(const Model& model, const std::vector<double>& x0) {
  const FemMesh& mesh = model.mesh;
  const int dim = mesh.dimension;
  const bool axisymmetric = model.run.mode == GeometryMode::axisymmetric;
  BarHosts hosts;
  hosts.host_nodes = mesh.nodes_per_element;
  for (const BarSet& spec : model.bars) {
    const auto where_key = [&](const char* key) {
      SourceLocation w = spec.where;
      w.key = w.key.empty() ? key : w.key + "." + key;
      return w;
    };
    if (spec.segments < 1)
      throw InputError(where_key("segments"), fmt::format("bar '{}' needs at least one segment", spec.name));
    if (!(spec.area > 0.0))
      throw InputError(where_key("area"), fmt::format("bar '{}': the area must be positive", spec.name));
    if (spec.material < 0 || static_cast<std::size_t>(spec.material) >= model.materials.size())
      throw InputError(where_key("material"), fmt::format("bar '{}' has no material", spec.name));
    if (spec.orientation == BarOrientation::hoop && !axisymmetric)
      throw InputError(where_key("orientation"),
                       fmt::format("bar '{}': hoop bars (rings) need axisymmetric geometry", spec.name));
    double length0 = 0.0;
    for (int i = 0; i < dim; ++i)
      length0 += std::pow(spec.to[static_cast<std::size_t>(i)] - spec.from[static_cast<std::size_t>(i)], 2);
    if (!(std::sqrt(length0) > 0.0))
      throw InputError(where_key("to"), fmt::format("bar '{}' has zero length", spec.name));

    for (int b = 0; b <= spec.segments; ++b) {
      double x[3];
      for (std::size_t i = 0; i < 3; ++i)
        x[i] = spec.from[i] + (spec.to[i] - spec.from[i]) * b / spec.segments;
      const auto host = find_host(mesh, spec.host_part, x);
      if (!host)
        throw InputError(
            spec.where,
            fmt::format("bar '{}': node {} at ({:.6g}, {:.6g}{}) lies outside {}", spec.name, b + 1, x[0],
                        x[1], dim == 3 ? fmt::format(", {:.6g}", x[2]) : std::string(),
                        spec.host_part >= 0
                            ? "host part '" + model.parts[static_cast<std::size_t>(spec.host_part)].name + "'"
                            : std::string("the mesh")));
      double n[8];
      shape_functions(dim, host->xi, n);
      hosts.element.push_back(host->element);
      // The bar node's position at t = 0 as the bars interpolate it, summed in the same order.
      double at[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < hosts.host_nodes; ++a) {
        const std::int64_t node = mesh.connectivity[static_cast<std::size_t>(host->element) *
                                                        static_cast<std::size_t>(hosts.host_nodes) +
                                                    static_cast<std::size_t>(a)];
        hosts.node.push_back(node);
        hosts.weight.push_back(n[a]);
        for (int i = 0; i < dim; ++i) at[i] += n[a] * x0[static_cast<std::size_t>(node * dim + i)];
      }
      hosts.position.insert(hosts.position.end(), at, at + 3);
    }
  }
  return hosts;
}

}  // namespace camouflet
