// The SPH-FEM join after erosion.
//
// An eroded element carries no force, but its nodes keep their mass
// (solver erosion). If it bounded the interface, its face kept taking the
// reactions of the pairs around it, and a node left with no live element (the
// top axis node of the needle under the buried case's SPH zone) was driven by
// the particles' stress alone, at about 2 km/s (83 m by 70 ms in `default`),
// dragging its neighbour across the axis. So the interface follows the
// erosion:
//
// * an eroded element's coupling points leave the particle sums (fill()
//   gives them no mass: the particles beside them see a free surface there,
//   as beside any void);
// * its interface faces leave the interface, and each face it shared with a
//   live joined element becomes an interface face of that element: the surface
//   the void exposes. Eroded elements reached from the set-up interface through
//   eroded neighbours open their faces too, so a hole can deepen;
// * a live point whose face left sends its reactions to the interface face
//   nearest to it in the set-up geometry (the exposed face of its own element,
//   where it has one).
//
// The discrete normalisation n of the points (compute_normalisation) is kept
// from the set-up: beside the void it is that of the full lattice, which the
// points there no longer have (a local error of the order of 1 - n, a few per
// cent of the traction on those points).
#include <algorithm>

#include "coupling/element_faces.hpp"
#include "coupling/sph_fem_join.hpp"
#include "core/error.hpp"

namespace camouflet {

template <int D>
void SphFemJoin<D>::keep_setup_interface() {
  const FemElements<D>& el = fem_->elements;
  setup_faces_ = faces_;
  setup_face_element_ = face_element_;
  setup_point_face_.resize(points_.size());
  for (std::size_t k = 0; k < points_.size(); ++k) setup_point_face_[k] = points_[k].face;
  std::int64_t node_count = 0;
  for (const std::int64_t n : el.connectivity) node_count = std::max(node_count, n + 1);
  x_setup_.assign(x(), x() + node_count * D);
  // The face neighbours (neighbour_) were found with the interface (find_interface_faces).
  joined_element_.assign(el.size(), 0);
  for (const Point& pt : points_) joined_element_[pt.element] = 1;
  for (const std::int64_t e : face_element_) joined_element_[static_cast<std::size_t>(e)] = 1;
}

template <int D>
void SphFemJoin<D>::follow_erosion() {
  if (points_.empty()) return;
  constexpr int faces_per_element = D == 2 ? 4 : 6;
  const FemElements<D>& el = fem_->elements;
  const std::vector<char>& eroded = el.eroded;
  // Open: eroded elements of the set-up interface (a face or a point), and eroded elements
  // across a face from an open one.
  std::vector<char> open(el.size(), 0);
  std::vector<std::size_t> front;
  for (std::size_t e = 0; e < el.size(); ++e)
    if (joined_element_[e] && eroded[e]) open[e] = 1, front.push_back(e);
  while (!front.empty()) {
    const std::size_t e = front.back();
    front.pop_back();
    for (int f = 0; f < faces_per_element; ++f) {
      const std::int64_t other = neighbour_[e * faces_per_element + static_cast<std::size_t>(f)];
      if (other < 0 || open[static_cast<std::size_t>(other)] || !eroded[static_cast<std::size_t>(other)]) continue;
      open[static_cast<std::size_t>(other)] = 1;
      front.push_back(static_cast<std::size_t>(other));
    }
  }
  // The interface: the set-up faces of live elements, then the faces the open elements expose.
  faces_.clear();
  face_element_.clear();
  std::vector<std::size_t> kept(setup_faces_.size(), static_cast<std::size_t>(-1));
  for (std::size_t k = 0; k < setup_faces_.size(); ++k) {
    if (eroded[static_cast<std::size_t>(setup_face_element_[k])]) continue;
    kept[k] = faces_.size();
    faces_.push_back(setup_faces_[k]);
    face_element_.push_back(setup_face_element_[k]);
  }
  for (std::size_t e = 0; e < el.size(); ++e) {
    if (eroded[e] || !joined_element_[e]) continue;
    for (int f = 0; f < faces_per_element; ++f) {
      const std::int64_t other = neighbour_[e * faces_per_element + static_cast<std::size_t>(f)];
      if (other < 0 || !open[static_cast<std::size_t>(other)]) continue;
      faces_.push_back(join_faces::nodes<D>(el, e, f));
      face_element_.push_back(static_cast<std::int64_t>(e));
    }
  }
  update_face_geometry(x_setup_.data());
  // Each point's face: its set-up face while that stays, else the nearest one.
  for (std::size_t k = 0; k < points_.size(); ++k) {
    Point& pt = points_[k];
    if (kept[setup_point_face_[k]] != static_cast<std::size_t>(-1)) {
      pt.face = kept[setup_point_face_[k]];
      continue;
    }
    if (faces_.empty())
      throw NumericalError(EntityKind::element, static_cast<std::int64_t>(pt.element), "SPH-FEM join",
                           "every interface face of the SPH-FEM join has eroded: the particles' reactions "
                           "have no element to go to");
    const Vec<D> where = interpolate(x_setup_.data(), pt);
    double best = 1e300;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      const Vec<D> d = face_centre_[f] - where;
      if (dot(d, d) < best) best = dot(d, d), pt.face = f;
    }
  }
  find_corner_faces(x_setup_.data());
  update_face_geometry(x());
}

template void SphFemJoin<2>::keep_setup_interface();
template void SphFemJoin<3>::keep_setup_interface();
template void SphFemJoin<2>::follow_erosion();
template void SphFemJoin<3>::follow_erosion();

}  // namespace camouflet
