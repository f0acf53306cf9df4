#include "sph/mirror_boundary.hpp"

#include <cmath>

namespace camouflet::sph {

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
