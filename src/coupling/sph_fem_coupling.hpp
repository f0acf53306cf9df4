#pragma once
// The couplings between the SPH particle package and the FEM package, as one
// object of the cycle: the join (sph_fem_join.hpp, Wang et al. 2005, section
// 3.3, the first option) and the particle-face sliding contact
// (sliding_contact.hpp, the second), with the power each does, which the
// driver books under the coupling's own names (join, join_face, contact in
// energy.csv). It holds the two packages it couples; the driver calls it at
// three stages and after an erosion.
#include <memory>

#include "core/state_visitor.hpp"
#include "coupling/sliding_contact.hpp"
#include "coupling/sph_fem_join.hpp"
#include "fem/fem_package.hpp"
#include "model/model.hpp"
#include "sph/sph_package.hpp"

namespace camouflet {

template <int D>
class SphFemCoupling {
 public:
  // The join of model.joins' FEM parts (its coupling points join the particle sums, registered
  // with the particle system here) and the contacts of model.contacts. Throws InputError as
  // SphFemJoin and SlidingContact do. Both packages must outlive this object, in place.
  SphFemCoupling(const Model& model, FemPackage<D>& fem, sph::SphPackage<D>& particles);

  // Forces at t_n, after the packages' own: the join's reactions on the joined FEM nodes, the
  // contact forces on particles and face nodes. dt_mean: the contact's impulse span.
  void add_forces(double dt_mean);

  // After every kick and the node constraints (v(n+1/2)): the join settles (the elements take
  // their half of the viscous pair heating). The powers of the pair work that no internal
  // energy books (W), which the driver books over dt_mean: the join's, of which
  // `join_face_work` (J) went through the coupling points' centre-face offset, and the contact's.
  struct Powers {
    double join = 0.0;            // W
    double contact = 0.0;         // W
    double join_face_work = 0.0;  // J over dt_mean
  };
  Powers settle(double dt_mean);

  // After the packages' update: when FEM elements eroded (its eroded_count moved on), the join's
  // interface as the erosion leaves it.
  void follow_packages() {
    if (fem_.eroded_count != eroded_seen_) follow_erosion();
  }
  // After a restore: the join's interface as the restored erosion leaves it.
  void follow_erosion() {
    eroded_seen_ = fem_.eroded_count;
    if (join_) join_->follow_erosion();
  }

  // The powers of the last step (a restart books the next step's work with them), by name in
  // the caller's scope.
  void visit_state(StateVisitor& visitor);

 private:
  FemPackage<D>& fem_;
  sph::SphPackage<D>& particles_;
  std::unique_ptr<SphFemJoin<D>> join_;  // null without joins; in place: registered with the particles
  SlidingContact<D> contact_;
  double join_power_ = 0.0;     // W, pair work across the join that no internal energy books
  double contact_power_ = 0.0;  // W, power of the contact forces
  std::size_t eroded_seen_ = 0;  // the FEM package's eroded_count the join last followed
};

extern template class SphFemCoupling<2>;
extern template class SphFemCoupling<3>;

}  // namespace camouflet
