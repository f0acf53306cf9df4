#include "coupling/sph_fem_coupling.hpp"

namespace camouflet {

template <int D>
SphFemCoupling<D>::SphFemCoupling(const Model& model, FemPackage<D>& fem, sph::SphPackage<D>& particles)
    : fem_(fem), particles_(particles), eroded_seen_(fem.eroded_count) {
  if (!model.joins.empty()) {
    // The coupling points are mirrored in the particles' planes, in their order.
    join_ = std::make_unique<SphFemJoin<D>>(model, fem, particles.system(), particles.system().mirror_planes());
  }
  contact_ = SlidingContact<D>(model);
}

template <int D>
void SphFemCoupling<D>::add_forces(double dt_mean) {
  if (join_) join_->add_reactions(particles_.system(), fem_.force.data());  // reactions on the joined nodes
  if (!contact_.empty())
    contact_power_ = contact_.apply(particles_.system(), fem_.position.data(), fem_.velocity.data(),
                                    fem_.force.data(), dt_mean);
}

template <int D>
typename SphFemCoupling<D>::Powers SphFemCoupling<D>::settle(double dt_mean) {
  Powers powers;
  if (join_) {  // the elements' half of the viscous heating, and the join work (sph_fem_join.hpp)
    const double work = join_->settle(particles_.system(), dt_mean, fem_.batches);
    join_power_ = dt_mean > 0.0 ? work / dt_mean : 0.0;
    powers.join_face_work = join_->face_offset_work();
  }
  powers.join = join_power_;
  powers.contact = contact_power_;
  return powers;
}

template <int D>
void SphFemCoupling<D>::visit_state(StateVisitor& v) {
  visit(v, "join_power", join_power_);
  visit(v, "contact_power", contact_power_);
}

template class SphFemCoupling<2>;
template class SphFemCoupling<3>;

}  // namespace camouflet
