#pragma once
// The SPH particles as a package of the cycle (model/package.hpp): the
// particle system (sph_system.hpp) driven at the driver's stages, with gravity
// on the particles, their checks and failure descriptions, their share of the
// energy and their part in a dynamic relaxation. The couplings (coupling/)
// reach the particle system itself through system().
#include <memory>
#include <vector>

#include "boundary/mirror_planes.hpp"
#include "model/model.hpp"
#include "model/package.hpp"
#include "sph/sph_system.hpp"

namespace camouflet::sph {

template <int D>
class SphPackage final : public Package<D> {
 public:
  // The particles of model.particles, mirrored in the planes the model's boundaries give them
  // (Boundaries::mirror_planes, boundary/boundaries.hpp: the axis of an r-z model and the
  // symmetry planes).
  SphPackage(const Model& model, std::vector<MirrorPlane> planes);

  SphSystem<D>& system() { return system_; }
  const SphSystem<D>& system() const { return system_; }

  std::string name() const override { return "sph"; }
  void add_forces(const StepClock& clock) override;
  void add_gravity(const std::array<double, 3>& g, double& power) override;
  void kick(const StepClock& clock) override { system_.kick(clock.dt_mean()); }
  double drift(const StepClock& clock) override;
  void check() const override;
  // The particles' state at t_(n+1); their viscous heating is in their internal energy already.
  void update_state(const StepClock& clock, EnergyBalance&) override { system_.update_state(clock.dt, clock.time); }
  typename Package<D>::Vote vote() const override;
  double kinetic_energy() const override { return system_.kinetic_energy(); }
  double internal_energy() const override { return system_.internal_energy(); }
  std::string describe(EntityKind kind, std::int64_t id) const override;
  void fill_snapshot(FieldSnapshot& snapshot) const override { system_.fill_snapshot(snapshot); }
  void visit_state(StateVisitor& visitor) override { system_.visit_state(visitor); }
  bool relaxes() const override { return true; }
  void scale_velocities(double factor) override { system_.scale_velocities(factor); }
  void hold_still(const std::vector<char>& held_material) override;
  void come_to_rest() override { system_.come_to_rest(); }

 private:
  const Model& model_;
  SphSystem<D> system_;
};

extern template class SphPackage<2>;
extern template class SphPackage<3>;

}  // namespace camouflet::sph
