// The geostatic initial state of the FEM soil parts under gravity (docs/theory/gravity.md): each
// element's point takes its part's overburden state at the element's centre
// (model/geostatic_stress.hpp, which the SPH package uses for its particles too).
#include <fmt/format.h>

#include "model/geostatic_stress.hpp"
#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::set_geostatic_state() {
  const Model& model = model_;
  const std::size_t ne = elements_.size();
  constexpr int N = FemElements<D>::nodes;
  std::vector<GeostaticRequest> request;
  for (const MaterialPoints& pts : batches_) request.emplace_back(pts.size());
  bool any = false;
  for (std::size_t part_index = 0; part_index < model.parts.size(); ++part_index) {
    const Part& part = model.parts[part_index];
    if (!part.geostatic || part.kind != PartKind::fem) continue;
    any = true;
    std::vector<GeostaticPoint> points;
    std::vector<std::size_t> element;
    for (std::size_t e = 0; e < ne; ++e) {
      if (static_cast<std::size_t>(model.mesh.element_part[e]) != part_index) continue;
      GeostaticPoint point{elements_.point[e], {}};
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < D; ++i)
          point.centre[static_cast<std::size_t>(i)] +=
              position_[static_cast<std::size_t>(elements_.connectivity[e * N + a] * D + i)] / N;
      points.push_back(point);
      element.push_back(e);
    }
    ask_geostatic_stress(
        model, part_index, points, [&](std::size_t k) { return fmt::format("element {}", element[k] + 1); },
        request[static_cast<std::size_t>(part.material)]);
  }
  if (!any) return;
  for (std::size_t m = 0; m < batches_.size(); ++m) commit_geostatic_state(model, m, batches_[m], request[m]);
}

template void Solver<2>::set_geostatic_state();
template void Solver<3>::set_geostatic_state();

}  // namespace camouflet
