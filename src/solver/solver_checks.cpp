// Numerical-failure diagnostics of the cycle: nodes must stay finite and
// inside the case's domain box ([run] domain_min / domain_max), as the
// packages check their points (SphPackage::check), and every failure names
// the entity's material and position.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "model/domain_box.hpp"
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
std::string Solver<D>::describe(EntityKind kind, std::int64_t id) const {
  if (id < 1) return {};
  const auto k = static_cast<std::size_t>(id - 1);
  if (kind == EntityKind::element && k < fem_.elements.size()) {
    constexpr int N = FemElements<D>::nodes;
    double c[D] = {};
    for (int a = 0; a < N; ++a)
      for (int i = 0; i < D; ++i)
        c[i] += fem_.position[static_cast<std::size_t>(
                    fem_.elements.connectivity[k * N + static_cast<std::size_t>(a)] * D + i)] /
                N;
    return fmt::format("material '{}', centre {}",
                       model_.materials[static_cast<std::size_t>(fem_.elements.material[k])].name,
                       position_text<D>(c));
  }
  if (kind == EntityKind::node && k < fem_.node_mass.size())
    return fmt::format("position {}", position_text<D>(&fem_.position[k * D]));
  return describe_package_point(kind, id);
}

template <int D>
void Solver<D>::check_axis_crossings() {
  // r-z: a node that has moved to r < 0 has crossed the axis; the ring volumes around it stop
  // meaning anything (join-face nodes next to the axis were once driven across it, and the run
  // went on for 20 ms with inverted elements, unreported, since the element centres stayed at
  // r > 0). Reported like a tangled element (a warning naming the node, cycle and time, at most 20
  // lines), not fatal: the rest of the model is still meaningful, and the buried-structure cases
  // reach it (docs/reliability.md). Nodes that start on the axis keep r = 0 exactly (the axis
  // condition); a node at r0 > 0 counts from the step that takes it below r = 0.
  if (D != 2 || mode_ != GeometryMode::axisymmetric) return;
  const std::size_t nn = fem_.node_mass.size();
  if (axis_reported_.size() != nn) axis_reported_.assign(nn, 0);
  for (std::size_t n = 0; n < nn; ++n) {
    if (!(fem_.position[n * D] < 0.0 && fem_.displacement[n * D] < 0.0) || axis_reported_[n]) continue;
    axis_reported_[n] = 1;
    const auto id = static_cast<std::int64_t>(n) + 1;
    if (first_axis_cycle_ < 0) first_axis_node_ = id, first_axis_cycle_ = cycle_;
    if (axis_reports_ >= 20) continue;
    ++axis_reports_;
    fmt::print(stderr,
               "warning: node {} ({}) at cycle {}, time {:.6e} s: crossed the axis of the axisymmetric model "
               "(r = {:.6g} m; it started at r = {:.6g} m): the elements around it are inverted{}\n",
               id, describe(EntityKind::node, id), cycle_, time_, fem_.position[n * D],
               fem_.position[n * D] - fem_.displacement[n * D],
               axis_reports_ == 20 ? " (no more such warnings)" : "");
  }
}

template <int D>
void Solver<D>::fail_node(std::int64_t bad) const {
  const RunControl& run = model_.run;
  const auto n = static_cast<std::size_t>(bad);
  const double* x = &fem_.position[n * D];
  const double* v = &fem_.velocity[n * D];
  bool finite = true;
  for (int i = 0; i < D; ++i) finite = finite && std::isfinite(x[i]) && std::isfinite(v[i]);
  if (!finite)
    fail(NumericalError(EntityKind::node, bad + 1, "velocity",
                        fmt::format("non-finite position or velocity (v = {})", position_text<D>(v))));
  const int axis = first_outside_domain<D>(model_.run, x);
  fail(NumericalError(EntityKind::node, bad + 1, "position",
                      fmt::format("left the domain box: coordinate {} = {:.6g} m outside [{:.6g}, {:.6g}] m",
                                  axis + 1, x[axis], run.domain_min[static_cast<std::size_t>(axis)],
                                  run.domain_max[static_cast<std::size_t>(axis)])));
}

template <int D>
void Solver<D>::check_nodes_and_packages() const {
  const std::int64_t nn = static_cast<std::int64_t>(fem_.node_mass.size());
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
#pragma omp parallel for schedule(static) reduction(min : bad) if (nn > 20000)
  for (std::int64_t n = 0; n < nn; ++n) {
    const double* x = &fem_.position[static_cast<std::size_t>(n * D)];
    const double* v = &fem_.velocity[static_cast<std::size_t>(n * D)];
    bool ok = first_outside_domain<D>(model_.run, x) < 0;
    for (int i = 0; i < D; ++i) ok = ok && std::isfinite(v[i]);
    if (!ok) bad = std::min(bad, n);
  }
  if (bad != std::numeric_limits<std::int64_t>::max()) fail_node(bad);
  check_packages();
}

template std::string Solver<2>::describe(EntityKind, std::int64_t) const;
template std::string Solver<3>::describe(EntityKind, std::int64_t) const;
template void Solver<2>::check_nodes_and_packages() const;
template void Solver<3>::check_nodes_and_packages() const;
template void Solver<2>::fail_node(std::int64_t) const;
template void Solver<3>::fail_node(std::int64_t) const;
template void Solver<2>::check_axis_crossings();
template void Solver<3>::check_axis_crossings();

}  // namespace camouflet
