// The internal forces of the FEM elements at t_n (fem_elements.hpp): the
// colour-block assembly of the element force kernel (element_forces.hpp).
#include <omp.h>

#include <algorithm>

#include "fem/element_forces.hpp"
#include "fem/fem_elements.hpp"
#include "fem/parallel.hpp"

namespace camouflet {

template <int D>
double FemElements<D>::add_internal_forces(const double* x, const double* v, double* f, double* f_hourglass,
                                           const HourglassControl& hg, double dt_previous) {
  const ElementForceKernel<D> kernel(*this, x, v, hg, dt_previous);
  const std::size_t ne = size();
  const std::size_t W = static_cast<std::size_t>(ElementForceKernel<D>::width());
  const bool any_stiff_hg = kernel.holds_stiffness_energy();
  const int team = static_cast<std::int64_t>(ne) > parallel_threshold ? omp_get_max_threads() : 1;
  // One colour after the other, the blocks of a colour shared out among the threads and
  // scattered straight into f: no two blocks of a colour share a node, so each node gets its
  // contributions in colour order whatever the thread count (the barrier at the end of each
  // colour's loop keeps the colours apart).
  colour_if_needed();
  const std::size_t colours = colouring_.colours(), block = colouring_.block;
  if (any_stiff_hg) pack_stored_.assign(colouring_.blocks.size(), 0.0);
  const std::uint32_t* const listed = colouring_.blocks.data();
#pragma omp parallel num_threads(team) if (team > 1)
  {
    for (std::size_t c = 0; c < colours; ++c) {
      const std::size_t first = colouring_.begin[c];
      const std::int64_t n_blocks = static_cast<std::int64_t>(colouring_.begin[c + 1] - first);
#pragma omp for schedule(static)
      for (std::int64_t k = 0; k < n_blocks; ++k) {
        const std::size_t e_begin = listed[first + static_cast<std::size_t>(k)] * block;
        const std::size_t e_end = std::min(ne, e_begin + block);
        double held = 0.0;
        for (std::size_t e0 = e_begin; e0 < e_end; e0 += W)
          held += kernel.consecutive(e0, static_cast<int>(std::min(W, e_end - e0)), f, f_hourglass);
        if (any_stiff_hg) pack_stored_[first + static_cast<std::size_t>(k)] = held;
      }
    }
  }
  double stored = 0.0;
  for (const double held : pack_stored_) stored += held;  // block order: any thread count, the same sum
  if (!any_stiff_hg) pack_stored_.clear();
  return stored;
}

template double FemElements<2>::add_internal_forces(const double*, const double*, double*, double*,
                                                    const HourglassControl&, double);
template double FemElements<3>::add_internal_forces(const double*, const double*, double*, double*,
                                                    const HourglassControl&, double);

}  // namespace camouflet
