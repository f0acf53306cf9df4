// The geostatic initial state of the FEM soil parts under gravity (docs/theory/gravity.md): each
// element's point takes its part's overburden state at the element's centre
// (model/geostatic_stress.hpp, which the SPH package uses for its particles too).
#include "model/geostatic_stress.hpp"
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::set_geostatic_state() {
  constexpr int N = FemElements<D>::nodes;
  const std::size_t ne = elements_.size();
  set_geostatic_states(
      model_, PartKind::fem, "element", batches_,
      [&](std::size_t part, std::vector<GeostaticPoint>& points, std::vector<std::size_t>& ids) {
        for (std::size_t e = 0; e < ne; ++e) {
          if (static_cast<std::size_t>(model_.mesh.element_part[e]) != part) continue;
          GeostaticPoint point{elements_.point[e], {}};
          for (int a = 0; a < N; ++a)
            for (int i = 0; i < D; ++i)
              point.centre[static_cast<std::size_t>(i)] +=
                  position_[static_cast<std::size_t>(elements_.connectivity[e * N + a] * D + i)] / N;
          points.push_back(point);
          ids.push_back(e + 1);
        }
      });
}

template void Solver<2>::set_geostatic_state();
template void Solver<3>::set_geostatic_state();

}  // namespace camouflet
