#pragma once
// Joined SPH-FEM interface (Wang et al. 2005, section 3.3, Fig. 1b): the FEM
// elements beside an SPH zone take part in the particle sums as neighbour
// points, and the reactions of the pair forces go back to their nodes.
//
// Formulation: every element of a joined FEM part whose centre lies within
// the kernel reach of a particle becomes a "coupling point" at its centre,
// carrying the element's mass, density, stress, wave speed and the mean
// velocity of its nodes, with h = smoothing_factor x (element size) scaled by
// (rho0 / rho)^(1/d). This is the linking of Johnson (1994, Nucl. Eng. Des.
// 150: "Linking of Lagrangian particle methods to standard finite element
// methods for high velocity impact computations"), where the elements at the
// interface are seen as particles by the particle side, and of the Autodyn
// SPH-Lagrange "join": the particle next to the interface has a full kernel
// support (the elements continue its lattice, exactly when the spacing
// matches the element size), so no free surface and no material interface
// appears where the zones meet. An element coarser than the particles beside
// it enters as k^d sub-points (k the spacing ratio rounded) with the particles'
// smoothing length, so that the lattice continues also at graded spacing.
//
// Conservation: the pair force F_ij of the (symmetric) momentum sum acts on
// particle i, and -F_ij goes to the FEM at the interface: spread equally over
// the nodes of the interface face nearest to element j (a boundary face of
// the joined elements facing the particles). Within reach of a corner of the
// interface (faces of two or three orientations) the reaction is split along
// the faces' normals, each part to the nearest face of its orientation
// (join_faces.cpp). So momentum is conserved pair by pair (in r-z the reaction
// is the pair force with the ring weights of the point, below), and a uniform stress passes the join as a
// traction on the interface nodes only: the elements inside the band are already in equilibrium through their
// own FEM forces (spreading the reactions over the band's nodes instead strains the band and drains the
// wave's energy) (mirror images of elements across the particle symmetry planes and the axis return their
// reaction mirrored: the plane's reaction). Mass is not exchanged: each element keeps its mass on its nodes.
// The element enters the sums with the stress its own nodal forces use (sigma - qI), divided by the lattice
// normalisation n (a lattice transmits n sigma across a plane, the FEM sigma; docs/theory/coupling.md).
// Energy: particle i books the part of the pair work conjugate to its own stress and half the viscous heat
// (sph_system.hpp), the element the other half of the viscous heat (settle()); the part conjugate to the
// element's stress, and the work of the pair forces through the offset between the coupling point and the
// face that takes its reaction, are the "join work", which the solver adds to the boundary work of the energy
// balance. It is the join's real energy error (the formulation conserves momentum, not energy): -0.6 to -0.8
// % of a 20-cell pulse over two crossings in plane strain, r-z and 3-D (tests/coupling/test_join.cpp).
// Erosion (join_erosion.cpp): an eroded element's points leave the sums and its faces leave the interface;
// the faces it shared with live joined elements take their place, so that no node left without an element
// keeps taking reactions.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "fem/fem_package.hpp"
#include "model/model.hpp"
#include "sph/sph_system.hpp"

namespace camouflet {

template <int D>
class SphFemJoin {
 public:
  SphFemJoin() = default;
  // Coupling points for the elements of model.joins' FEM parts within reach
  // of the particles, with their images across `planes` (the particle mirror
  // planes, axis included). The FEM package's nodes are read through its view
  // (FemPackage::nodes) at every use, its elements' state at every refresh; the package
  // must outlive this object, in place. The coupling points are registered with the
  // particle system, which has them written (fill) whenever it refreshes its ghosts: at its
  // own sub-stages (kick, kinematics, neighbour search), which no driver stage can reach.
  SphFemJoin(const Model& model, const FemPackage<D>& fem, sph::SphSystem<D>& particles,
             std::vector<sph::MirrorPlane> planes);

  bool empty() const { return points_.empty(); }
  std::size_t point_count() const { return points_.size(); }

  // After SphSystem::compute_accelerations (t_n): f (n*D) += the reactions of
  // the pair forces on the coupling points, spread over the interface face nodes.
  // Keeps the pairs for settle().
  void add_reactions(const sph::SphSystem<D>& particles, double* f);
  // After the kick (velocities at n+1/2, coupling points refreshed): the elements
  // take their half of the viscous pair heating over the impulse dt (J into their
  // specific energy); returns the join work over dt (J), the pair work that no
  // internal energy books: the part conjugate to the elements' stress, plus
  // face_offset_work().
  double settle(const sph::SphSystem<D>& particles, double dt, std::vector<MaterialPoints>& batches);
  // The part of the last settle()'s join work done by the pair forces through
  // the offset between a coupling point (the element centre, whose velocity
  // the pair sums see) and the interface face that takes its reaction:
  // sum (F . v_j + R . v_face) dt, R = -F but for the r-z ring weights (J,
  // centred velocities; docs/theory/coupling.md).
  double face_offset_work() const { return face_offset_work_; }
  // After elements eroded (FemElements::eroded), and after a restore: the interface as the erosion
  // leaves it (join_erosion.cpp). A pure function of the eroded flags and the set-up geometry, so a
  // restarted run rebuilds the same interface.
  void follow_erosion();

 private:
  struct Point {
    std::size_t element = 0;
    std::array<double, 3> xi{};            // natural coordinates in the element (0: its centre)
    double share = 1.0;                    // of the element's area (sub-points of a coarse element)
    std::array<std::uint8_t, 3> planes{};  // images: planes applied in order
    std::uint8_t image_count = 0;
    bool across_axis = false;  // r-z: an image across the axis (its ring weight is signed, fill())
    double h0 = 0.0;           // m, smoothing length at the reference density
    double rho0 = 0.0;         // kg/m^3
    std::size_t face = 0;      // index into faces_: where its reactions go
    std::uint32_t corner_begin = 0, corner_end = 0;  // into corner_faces_ (empty: a straight face)
    double planar_volume = 0.0;                      // m^3 (m^2 per radian x 2 pi in r-z), at set-up
    double normalisation = 1.0;  // n: discrete kernel normalisation around the point (fill())
  };
  // Where a pair's reaction goes: up to D parts, each on one interface face (real frame).
  struct ReactionParts {
    std::array<Vec<D>, D> force{};      // N
    std::array<std::size_t, D> face{};  // index into faces_
    int count = 0;
  };
  struct Pair {
    std::size_t i = 0, j = 0;  // particle, point (index in the particle arrays)
    Vec<D> other{};            // N, force on i from the element's stress
    Vec<D> viscous{};          // N, m_i m_j Pi_ij grad W (the viscous force on i is minus this)
    Vec<D> dv_old{};           // m/s, v_i - v_j at n-1/2
    Vec<D> force{};            // N, the whole pair force on i
    ReactionParts reaction{};  // what the faces take (-force, but for the r-z ring weights)
    double power_old = 0.0;    // W, force . v_j + sum reaction . v_face at n-1/2
  };
  Vec<D> face_velocity(std::size_t face) const;  // mean of the face nodes' v_ (real frame)
  // join_faces.cpp: the interface faces' centres and normals (towards the particles) at node
  // positions x (n*D), the faces of other orientations within reach of each point (corners), and the
  // split of a reaction.
  void update_face_geometry(const double* x);
  void find_corner_faces(const double* x);
  ReactionParts split_reaction(const Point& point, const Vec<D>& reaction) const;
  std::vector<std::int64_t> face_element_;         // the joined element each face bounds
  std::vector<Vec<D>> face_centre_, face_normal_;  // m, unit; at the last update_face_geometry()
  std::vector<std::size_t> corner_faces_;          // per point [corner_begin, corner_end): faces ...
  std::vector<std::uint8_t> corner_group_;         // ... and their orientation group (0: the point's face's)
  std::vector<double> ring_;                       // m, r-z: ring radius of each point's element there
  double face_offset_work_ = 0.0;
  std::vector<Pair> pairs_;
  static constexpr int face_nodes = D == 2 ? 2 : 4;
  std::vector<std::array<std::int64_t, face_nodes>> faces_;  // interface faces
  void fill(sph::ParticleArrays<D>& p, std::size_t begin) const;
  void compute_normalisation(const sph::SphSystem<D>& particles, const std::vector<Point>& candidates,
                             const std::vector<Vec<D>>& where, double reach);
  void find_interface_faces(const Model& model, const FemElements<D>& elements,
                            const sph::SphSystem<D>& particles,
                            const std::unordered_map<std::int64_t, std::vector<std::uint32_t>>& bins,
                            double reach);
  Vec<D> element_centre(std::size_t e, const double* x) const;        // at node positions x (n*D)
  Vec<D> element_centre(std::size_t e) const { return element_centre(e, x()); }
  Vec<D> interpolate(const double* field, const Point& point) const;  // node field (n*D) at the point
  // join_erosion.cpp: the set-up interface and the face neighbours of the joined elements.
  void keep_setup_interface();
  std::vector<std::array<std::int64_t, face_nodes>> setup_faces_;  // the interface before any erosion
  std::vector<std::int64_t> setup_face_element_;
  std::vector<std::size_t> setup_point_face_;  // per point, into setup_faces_
  std::vector<double> x_setup_;                // m, node positions at set-up (n*D)
  std::vector<std::int64_t> neighbour_;        // per joined element and local face: the element across (-1)
  std::vector<char> joined_element_;           // 1: the element belongs to a joined part
  double reach_ = 0.0;                         // m, as at set-up
  Vec<D> image(Vec<D> x, const Point& point) const;

  const FemPackage<D>* fem_ = nullptr;
  const double* x() const { return fem_->nodes().position.data(); }  // m, n*D, at this use
  const double* v() const { return fem_->nodes().velocity.data(); }  // m/s, n*D, at this use
  std::vector<Point> points_;
  std::vector<sph::MirrorPlane> planes_;
  sph::SphOptions options_;
  bool axisymmetric_ = false;
};

extern template class SphFemJoin<2>;
extern template class SphFemJoin<3>;

}  // namespace camouflet
