#pragma once
// Slide surfaces between FEM parts (Wang et al. 2005, section 4.13: the smooth soil-structure
// interface that may separate, recontact and slide with Coulomb friction, where the paper's model
// fuses the nodes). Node-to-surface penalty contact, symmetric: every node of each side is tested
// against the faces of the other (the two passes of LS-DYNA's surface-to-surface contact, theory
// manual, "Contact-impact algorithm"), so neither side is master.
//
// A node behind the other side's surface, at distance d from its closest point on it (the faces
// of the other side within half their size; a linear segment in 2-D, the two triangles (0,1,2),
// (0,2,3) of a quad in 3-D), is pushed towards that point:
//   F = k d n,              k = penalty_scale m_eff / dt_stable^2
// n the face's outward normal when the closest point lies inside a face, the direction from the
// node to the point when it lies on an edge or corner between faces. The distance to the closest
// point is continuous however the node moves, across seams, convex edges and valleys, so the
// spring's potential k d^2 / 2 is too: the nearest face the node projected onto (the first form)
// left a node in a valley without force and gave it the full depth when its foot came back onto a
// face, and that jump fed energy into the 3-D box (coarse3d, stopped at 39 ms). "Behind" is behind
// the face, or, at an edge or corner, behind its pseudonormal: the sum of the normals of the
// pieces the surface's topology puts there, angle-weighted at a corner (Baerentzen and Aanaes
// 2005), not of those whose closest point ties with the foot's, which rounding can drop; where the
// closest point lies on the rim of the other side's surface (an edge or corner bounding one face
// only) the node is beside that surface and meets it only within 1e-3 of a face size.
// m_eff the mass of the node-face pair (1/m_eff = 1/m_node + sum_a w_a^2 / m_a, w_a the face
// nodes' weights at the foot). F acts on the node and -w_a F on the face's nodes, so momentum is
// conserved exactly; the force vanishes for g >= 0, so the sides separate and recontact freely.
// Friction acts on the velocities after the kick, pair after pair (a projected Gauss-Seidel
// sweep): the impulse along the pair's tangential relative velocity v_t,
//   J = min(mu F_n dt, m_eff |v_t|),
// stops the sliding within the step when the Coulomb bound allows (sticking) and is the Coulomb
// force over the step when it does not. Each impulse only takes kinetic energy out of the pair's
// relative motion, so the sweep cannot overshoot however many pairs share a node (a force-level
// stick bound, m_eff |v_t| / dt per pair, reverses the relative motion when the two passes or
// neighbouring pairs act on the same nodes, and grows: coarse3d with mu 0.4 blew up at 14.5 ms).
//
// The stiffness is a soft constraint (LS-DYNA's SOFT = 1): it scales with the step, so a pair's
// own frequency is sqrt(penalty_scale) / dt per pass and the step needs no limit of its own. With
// both passes on a pair and the element's own highest frequency 2 cfl / dt, the node stays stable
// while (2 cfl)^2 + 2 penalty_scale < 4: the case reader refuses penalty_scale >= 2 (1 - cfl^2)
// (1.28 at cfl 0.6). The default 0.3 lets the sides part about 4 steps late (10 at 0.1, 1 at 1.0;
// two bars meeting, docs/theory/coupling.md). A pressure sigma across the interface sinks a node
// by about (cfl^2 / penalty_scale) (sigma / (rho c^2)) h, h the element size: a fraction of h
// while sigma stays well below the material's modulus rho c^2.
//
// In r-z the node masses and forces are both per radian, so the same law holds ring by ring.
// Faces of eroded elements take no part. The contact holds no state between steps (the search is
// redone each step), so a restart continues it exactly.
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/vec.hpp"
#include "model/model.hpp"

namespace camouflet {

template <int D>
class SlideSurfaces {
 public:
  SlideSurfaces() = default;
  // Throws InputError (at the surface's `where`) for a friction < 0, a penalty scale outside
  // (0, 2 (1 - cfl^2)) or an interface without faces.
  explicit SlideSurfaces(const Model& model);

  bool empty() const { return surfaces_.empty(); }

  // At t_n, after the element forces: adds the contact forces to f (n * D) from the positions x
  // and velocities v (v(n-1/2)) of the nodes, their masses m and the element erosion flags.
  // dt_stable: the step the packages' stability vote gave, which sets the stiffness (a step cut
  // short to land on an output or the end time must not stiffen the spring: its force would kick
  // the nodes by penalty_scale |g| / dt).
  void apply(const double* x, const double* v, const double* m, const std::vector<char>& eroded, double* f,
             double dt_stable);

  // After the kick, before the node constraints: the friction impulses of the last apply's pairs
  // on the velocities v (v(n+1/2), n * D) of nodes of masses m, over the impulse span dt.
  void apply_friction(double* v, const double* m, double dt);

  // After the kick and the node constraints (v(n+1/2)): the work of the last apply's forces over
  // dt (J), on the mean of the relative velocities before and after, as the central difference
  // changes the kinetic energy: the work of the normal springs (given back on separation) and of
  // friction (lost).
  double settle(const double* v, double dt) const;

  // Of the last apply: the number of node-face pairs in contact and the deepest penetration (m).
  std::size_t pairs() const { return pairs_; }
  double deepest() const { return deepest_; }

 private:
  static constexpr int F = D == 2 ? 2 : 4;  // nodes per face
  struct Side {
    std::vector<std::int64_t> faces;     // F nodes per face
    std::vector<std::int64_t> elements;  // the element each face bounds
    std::vector<std::int64_t> nodes;     // every node of the faces, once
    // The surface's rim: edges bounding one face only (sorted node pairs; unused in 2-D) and the
    // nodes on it (sorted).
    std::vector<std::pair<std::int64_t, std::int64_t>> rim_edges;
    std::vector<std::int64_t> rim_nodes;
    // The pieces (face * 2 + piece: a segment in 2-D, one of a quad's two triangles in 3-D) that
    // hold each node of `nodes`: those of nodes[i] at piece_list[piece_start[i] ..
    // piece_start[i + 1]).
    std::vector<std::size_t> piece_start;
    std::vector<std::size_t> piece_list;
  };
  struct Surface {
    Side a, b;
    double friction = 0.0;
    double penalty_scale = 0.3;
  };
  // The closest point of piece `piece` of face k (a segment in 2-D; triangle (0, 1, 2) or
  // (0, 2, 3) of a quad in 3-D) to the point p, the face's nodes placed by point(node).
  struct Foot {
    std::size_t face = 0;
    int count = 0;  // face nodes carrying the foot: 2 or 3 (0: none found)
    std::array<std::int64_t, 3> on{};
    std::array<double, 3> weight{};
    Vec<D> normal{};        // the piece's outward unit normal
    bool interior = false;  // inside the piece, not on its edge or corner
    double distance2 = std::numeric_limits<double>::infinity();
  };
  // The nodes of piece `piece` of face k: a segment's 2, a triangle's 3.
  static std::array<std::int64_t, 3> piece_nodes(const Side& faces, std::size_t k, int piece);
  // Fills side.piece_start and side.piece_list from its faces.
  static void index_pieces(Side& side);

  template <class Point>
  static bool closest_foot(const Side& faces, std::size_t k, int piece, const Vec<D>& p, const Point& point,
                           Foot& foot);

  // The nodes of `nodes` against the faces of `faces`.
  void pass(const Surface& s, const Side& nodes, const Side& faces, const double* x, const double* v,
            const double* m, const std::vector<char>& eroded, double* f, double dt_stable);

  // A node-face pair in contact at the last apply: the node, the face nodes at the foot with
  // their weights, the face's outward normal, the pair's mass, its friction coefficient, the
  // force on the node (N: the spring's, then with the friction impulse over the step) and the
  // node's velocity relative to the foot at v(n-1/2).
  struct Pair {
    std::int64_t node = 0;
    int count = 0;
    std::array<std::int64_t, 3> on{};
    std::array<double, 3> weight{};
    Vec<D> normal{};
    double m_eff = 0.0;
    double friction = 0.0;
    Vec<D> force{};
    Vec<D> v_rel_before{};
  };
  // The relative velocity of a pair's node to its foot on the face.
  Vec<D> relative_velocity(const Pair& pair, const double* v) const;

  std::vector<Surface> surfaces_;
  std::vector<Pair> contacts_;
  std::size_t pairs_ = 0;
  double deepest_ = 0.0;
};

extern template class SlideSurfaces<2>;
extern template class SlideSurfaces<3>;

}  // namespace camouflet
