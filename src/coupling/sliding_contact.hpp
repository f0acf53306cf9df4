#pragma once
// Sliding interface between SPH particles and FEM faces (Wang et al. 2005,
// section 3.3, the second coupling option; Attaway, Heinstein & Swegle 1994,
// Nucl. Eng. Des. 150, 199: particles as slave nodes against master element
// faces): a penalty node-to-surface contact with Coulomb friction.
//
// Each particle of the contact part is a sphere (disc) of radius r = s / 2
// (s its initial spacing). Against the face it projects into (linear segment
// in 2-D; the two triangles (0,1,2), (0,2,3) of a quad in 3-D) at signed
// distance g along the outward normal n, it is in contact while g < r:
//   normal   F_n = k (r - g) n,          k = penalty_scale m_p / dt^2
//   friction F_t = -min(mu |F_n|, m_p |v_t| / dt) v_t / |v_t|
// with v_t the tangential velocity of the particle relative to the face
// (interpolated from its nodes). F acts on the particle and -F on the face
// nodes with the same interpolation weights, so momentum is conserved
// exactly; the force vanishes when g >= r, so bodies separate and re-contact
// freely. The soft-constraint stiffness (as LS-DYNA's SOFT = 1) keeps the
// particle-face spring stable for penalty_scale < 4 and lets a particle sink
// at most about v dt / sqrt(penalty_scale) into its radius at impact speed v.
// Documented tolerance: no particle centre crosses a face (g > 0), i.e. an
// interpenetration below r = s / 2.
#include <cstdint>
#include <vector>

#include "model/model.hpp"
#include "sph/sph_system.hpp"

namespace camouflet {

template <int D>
class SlidingContact {
 public:
  SlidingContact() = default;
  // Throws InputError (at the contact's `where`) for an unknown face set, a
  // part that is not an SPH part, or a negative friction / non-positive penalty scale.
  explicit SlidingContact(const Model& model);

  bool empty() const { return contacts_.empty(); }

  // After SphSystem::compute_accelerations (t_n): adds the contact forces to
  // the particle accelerations and their reactions to f (n*D). dt: the
  // impulse span. Returns the power of the contact forces on the whole system (W).
  double apply(sph::SphSystem<D>& particles, const double* x, const double* v, double* f, double dt);

  // Smallest signed distance g of a contacting particle centre to its face at the last apply (m).
  double smallest_gap() const { return smallest_gap_; }

 private:
  struct Surface {
    int part = -1;
    std::vector<std::int64_t> faces;  // 2 or 4 nodes per face
    double friction = 0.0;
    double penalty_scale = 0.1;
  };
  std::vector<Surface> contacts_;
  double smallest_gap_ = 0.0;
};

extern template class SlidingContact<2>;
extern template class SlidingContact<3>;

}  // namespace camouflet
