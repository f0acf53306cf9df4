#include "boundary/mirror_planes.hpp"

#include <algorithm>
#include <cmath>

namespace camouflet::sph {

std::vector<MirrorPlane> symmetry_mirror_planes(const Model& model) {
  const int dimension = model.mesh.dimension;
  std::vector<MirrorPlane> planes;
  for (const BoundaryCondition& bc : model.boundaries) {
    if (bc.kind != BoundaryKind::symmetry) continue;
    int axis = -1;
    for (int i = 0; i < dimension; ++i)
      if (std::abs(bc.normal[static_cast<std::size_t>(i)]) > 0.999) axis = i;
    const auto set = model.mesh.node_sets.find(bc.set);
    if (axis < 0 || set == model.mesh.node_sets.end() || set->second.empty()) continue;
    const double position =
        model.mesh.coordinates[static_cast<std::size_t>(set->second.front() * dimension + axis)];
    if (model.run.mode == GeometryMode::axisymmetric && axis == 0 && std::abs(position) < 1e-12) continue;
    // One plane once, however many sets (e.g. one per block) it is split into:
    // a repeated plane would mirror each particle again (a ghost of a ghost).
    const auto same = [&](const MirrorPlane& p) {
      return p.axis == axis && std::abs(p.position - position) <= 1e-9 * (1.0 + std::abs(position));
    };
    if (std::any_of(planes.begin(), planes.end(), same)) continue;
    planes.push_back({axis, position, PlaneKind::symmetry});
  }
  return planes;
}

std::vector<MirrorPlane> axis_mirror_planes(GeometryMode mode) {
  if (mode == GeometryMode::axisymmetric) return {MirrorPlane{0, 0.0, PlaneKind::axis}};
  return {};
}

std::vector<MirrorPlane> particle_mirror_planes(const Model& model) {
  std::vector<MirrorPlane> planes = axis_mirror_planes(model.run.mode);
  for (const MirrorPlane& plane : symmetry_mirror_planes(model)) planes.push_back(plane);
  return planes;
}

template <int D>
std::vector<Ghost> make_ghosts(std::vector<Vec<D>>& x, std::size_t n_real,
                               const std::vector<MirrorPlane>& planes, double reach) {
  x.resize(n_real);
  std::vector<Ghost> ghosts;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    const std::size_t n_now = x.size();  // particles and the ghosts of earlier planes
    for (std::size_t i = 0; i < n_now; ++i) {
      if (std::abs(x[i][planes[p].axis] - planes[p].position) >= reach) continue;
      ghosts.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(p)});
      x.push_back(mirror_position(x[i], planes[p]));
    }
  }
  return ghosts;
}

template std::vector<Ghost> make_ghosts<2>(std::vector<Vec<2>>&, std::size_t, const std::vector<MirrorPlane>&,
                                           double);
template std::vector<Ghost> make_ghosts<3>(std::vector<Vec<3>>&, std::size_t, const std::vector<MirrorPlane>&,
                                           double);

}  // namespace camouflet::sph
