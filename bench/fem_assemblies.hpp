#pragma once
// The FEM force assemblies the solver does not use, kept to measure the one it
// does against (bench_fem_forces.cpp) and to check that all give the same
// forces (tests/fem/test_element_colouring.cpp). Each runs the solver's element
// force kernel (src/fem/element_forces.hpp) over the same packs in another
// order; docs/performance.md, "Colouring against per-thread buffers":
//   buffers:       packs of consecutive elements; each thread scatters into its
//                  own zeroed copy of the force arrays, the copies added in
//                  thread order after the loop (the sums depend on the thread
//                  count by round-off);
//   colours:       packs of single elements of one colour (no two share a node),
//                  one colour after the other, scattered straight into the
//                  force arrays (the same sums on any thread count, the element
//                  order's memory locality lost);
//   colour_blocks: the solver's (FemElements::add_internal_forces);
//   element_order: packs of consecutive elements write each element's node
//                  forces into slots of their own (ElementForceKernel::
//                  consecutive_into_slots: no two elements share one, so no
//                  colouring), then every node adds its slots up in ascending
//                  element number. The same sums on any thread count, and on
//                  any number of MPI ranks if a node on a cut received the other
//                  ranks' slots (not built: this measures what the order costs).
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "fem/element_colouring.hpp"
#include "fem/element_forces.hpp"
#include "fem/fem_elements.hpp"
#include "fem/parallel.hpp"

namespace camouflet::bench {

enum class Assembly { buffers, colours, colour_blocks, element_order };

inline const char* assembly_name(Assembly a) {
  return a == Assembly::buffers         ? "buffers"
         : a == Assembly::colours       ? "colours"
         : a == Assembly::colour_blocks ? "colour_blocks"
                                        : "element_order";
}

// What an assembly keeps between calls: the per-thread buffers (kept zeroed) or the colouring.
struct AssemblyScratch {
  std::vector<std::vector<double>> force, hourglass_force;  // threads 1 .. T-1
  ElementColouring single;                                 // colours of single elements
  std::vector<double> stored;                              // stiffness energy per pack
  // element_order: the slots, and per node its slots in ascending element number (CSR).
  std::vector<double> slots, hourglass_slots;
  std::vector<std::int64_t> node_start, node_slots;
};

template <int D>
double add_forces_with_buffers(FemElements<D>& el, const double* x, const double* v, double* f, double* fh,
                               const HourglassControl& hg, double dt_previous, AssemblyScratch& scratch) {
  const ElementForceKernel<D> kernel(el, x, v, hg, dt_previous);
  const std::size_t ne = el.size(), W = static_cast<std::size_t>(ElementForceKernel<D>::width());
  const std::int64_t packs = static_cast<std::int64_t>((ne + W - 1) / W);
  const auto count = [&](std::int64_t k) {
    return static_cast<int>(std::min<std::size_t>(W, ne - static_cast<std::size_t>(k) * W));
  };
  const int team = static_cast<std::int64_t>(ne) > parallel_threshold ? omp_get_max_threads() : 1;
  double stored = 0.0;
  if (team == 1) {
    for (std::int64_t k = 0; k < packs; ++k) stored += kernel.consecutive(k * W, count(k), f, fh);
    return stored;
  }
  std::size_t values = 0;
  for (std::size_t e = 0; e < el.connectivity.size(); ++e)
    values = std::max(values, static_cast<std::size_t>(el.connectivity[e] + 1) * D);
  scratch.force.resize(static_cast<std::size_t>(team - 1));
  scratch.hourglass_force.resize(static_cast<std::size_t>(team - 1));
  for (int t = 0; t < team - 1; ++t) {
    scratch.force[static_cast<std::size_t>(t)].resize(values, 0.0);
    if (fh) scratch.hourglass_force[static_cast<std::size_t>(t)].resize(values, 0.0);
  }
  const std::int64_t nv = static_cast<std::int64_t>(values);
#pragma omp parallel num_threads(team) reduction(+ : stored)
  {
    const int t = omp_get_thread_num();
    double* f_out = t == 0 ? f : scratch.force[static_cast<std::size_t>(t - 1)].data();
    double* fh_out = fh == nullptr ? nullptr
                     : t == 0      ? fh
                                   : scratch.hourglass_force[static_cast<std::size_t>(t - 1)].data();
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < packs; ++k) stored += kernel.consecutive(k * W, count(k), f_out, fh_out);
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < nv; ++k) {
      for (int s = 0; s < team - 1; ++s) {
        double& buffer = scratch.force[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)];
        f[k] += buffer;
        buffer = 0.0;
        if (fh) {
          double& hb = scratch.hourglass_force[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)];
          fh[k] += hb;
          hb = 0.0;
        }
      }
    }
  }
  return stored;
}

template <int D>
double add_forces_by_single_colours(FemElements<D>& el, const double* x, const double* v, double* f,
                                    double* fh, const HourglassControl& hg, double dt_previous,
                                    AssemblyScratch& scratch) {
  const ElementForceKernel<D> kernel(el, x, v, hg, dt_previous);
  const std::size_t ne = el.size(), W = static_cast<std::size_t>(ElementForceKernel<D>::width());
  if (scratch.single.begin.back() < ne) {
    std::size_t nodes = 0;
    for (const std::int64_t n : el.connectivity) nodes = std::max(nodes, static_cast<std::size_t>(n + 1));
    scratch.single = colour_elements(el.connectivity, FemElements<D>::nodes, nodes, 1);
  }
  const ElementColouring& colouring = scratch.single;
  const std::size_t colours = colouring.colours();
  const auto packs_of = [&](std::size_t c) { return (colouring.begin[c + 1] - colouring.begin[c] + W - 1) / W; };
  std::size_t all = 0;
  for (std::size_t c = 0; c < colours; ++c) all += packs_of(c);
  scratch.stored.assign(all, 0.0);
  const int team = static_cast<std::int64_t>(ne) > parallel_threshold ? omp_get_max_threads() : 1;
#pragma omp parallel num_threads(team) if (team > 1)
  {
    std::size_t base = 0;  // first pack of colour c among all colours' packs
    for (std::size_t c = 0; c < colours; ++c) {
      const std::size_t first = colouring.begin[c], in_colour = colouring.begin[c + 1] - first;
      const std::int64_t packs = static_cast<std::int64_t>(packs_of(c));
#pragma omp for schedule(static)
      for (std::int64_t k = 0; k < packs; ++k) {
        const std::size_t offset = static_cast<std::size_t>(k) * W;
        scratch.stored[base + static_cast<std::size_t>(k)] =
            kernel.listed(colouring.blocks.data() + first + offset,
                          static_cast<int>(std::min(W, in_colour - offset)), f, fh);
      }
      base += static_cast<std::size_t>(packs);
    }
  }
  double stored = 0.0;
  for (const double held : scratch.stored) stored += held;
  return stored;
}

template <int D>
double add_forces_in_element_order(FemElements<D>& el, const double* x, const double* v, double* f, double* fh,
                                   const HourglassControl& hg, double dt_previous, AssemblyScratch& scratch) {
  constexpr std::size_t N = FemElements<D>::nodes;
  const ElementForceKernel<D> kernel(el, x, v, hg, dt_previous);
  const std::size_t ne = el.size(), W = static_cast<std::size_t>(ElementForceKernel<D>::width());
  if (scratch.node_start.empty()) {
    std::size_t nodes = 0;
    for (const std::int64_t n : el.connectivity) nodes = std::max(nodes, static_cast<std::size_t>(n + 1));
    scratch.node_start.assign(nodes + 1, 0);
    for (const std::int64_t n : el.connectivity) ++scratch.node_start[static_cast<std::size_t>(n) + 1];
    for (std::size_t n = 0; n < nodes; ++n) scratch.node_start[n + 1] += scratch.node_start[n];
    scratch.node_slots.resize(el.connectivity.size());
    std::vector<std::int64_t> next(scratch.node_start.begin(), scratch.node_start.end() - 1);
    for (std::size_t slot = 0; slot < el.connectivity.size(); ++slot)  // ascending element, then corner
      scratch.node_slots[static_cast<std::size_t>(next[static_cast<std::size_t>(el.connectivity[slot])]++)] =
          static_cast<std::int64_t>(slot);
  }
  scratch.slots.resize(ne * N * D);
  if (fh) scratch.hourglass_slots.resize(ne * N * D);
  double* slots = scratch.slots.data();
  double* h_slots = fh ? scratch.hourglass_slots.data() : nullptr;
  const std::int64_t packs = static_cast<std::int64_t>((ne + W - 1) / W);
  scratch.stored.assign(static_cast<std::size_t>(packs), 0.0);
  const std::int64_t nodes = static_cast<std::int64_t>(scratch.node_start.size()) - 1;
  const int team = static_cast<std::int64_t>(ne) > parallel_threshold ? omp_get_max_threads() : 1;
#pragma omp parallel num_threads(team) if (team > 1)
  {
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < packs; ++k)
      scratch.stored[static_cast<std::size_t>(k)] = kernel.consecutive_into_slots(
          static_cast<std::size_t>(k) * W,
          static_cast<int>(std::min<std::size_t>(W, ne - static_cast<std::size_t>(k) * W)), slots, h_slots);
#pragma omp for schedule(static)
    for (std::int64_t n = 0; n < nodes; ++n) {
      const std::int64_t* s0 = scratch.node_slots.data() + scratch.node_start[static_cast<std::size_t>(n)];
      const std::int64_t* s1 = scratch.node_slots.data() + scratch.node_start[static_cast<std::size_t>(n) + 1];
      double sum[D];
      for (int i = 0; i < D; ++i) sum[i] = f[n * D + i];
      for (const std::int64_t* s = s0; s != s1; ++s)
        for (int i = 0; i < D; ++i) sum[i] += slots[*s * D + i];
      for (int i = 0; i < D; ++i) f[n * D + i] = sum[i];
      if (h_slots) {
        for (int i = 0; i < D; ++i) sum[i] = fh[n * D + i];
        for (const std::int64_t* s = s0; s != s1; ++s)
          for (int i = 0; i < D; ++i) sum[i] += h_slots[*s * D + i];
        for (int i = 0; i < D; ++i) fh[n * D + i] = sum[i];
      }
    }
  }
  double stored = 0.0;
  for (const double held : scratch.stored) stored += held;
  return stored;
}

// f += the internal forces by `assembly` (FemElements::add_internal_forces's arguments).
template <int D>
double add_internal_forces(Assembly assembly, FemElements<D>& el, const double* x, const double* v, double* f,
                           double* fh, const HourglassControl& hg, double dt_previous, AssemblyScratch& scratch) {
  switch (assembly) {
    case Assembly::buffers:
      return add_forces_with_buffers(el, x, v, f, fh, hg, dt_previous, scratch);
    case Assembly::colours:
      return add_forces_by_single_colours(el, x, v, f, fh, hg, dt_previous, scratch);
    case Assembly::element_order:
      return add_forces_in_element_order(el, x, v, f, fh, hg, dt_previous, scratch);
    case Assembly::colour_blocks:
      break;
  }
  return el.add_internal_forces(x, v, f, fh, hg, dt_previous);
}

}  // namespace camouflet::bench
