#include "sph/sph_package.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "model/domain_box.hpp"

namespace camouflet::sph {

template <int D>
SphPackage<D>::SphPackage(const Model& model, std::vector<MirrorPlane> planes)
    : model_(model), system_(model, model.sph, std::move(planes)) {
  if (model.run.mode == GeometryMode::axisymmetric && !model.sph.volume_form)
    fmt::print(stderr,
               "warning: [sph] volume_form = false in r-z: the particle columns next to the axis feel a "
               "stress divergence up to ~1.4x too large (mirror images with |r| ring weights; "
               "docs/theory/sph.md, \"The first columns\")\n");
}

template <int D>
void SphPackage<D>::add_forces(const StepClock&) {
  system_.compute_accelerations();  // sets the accelerations: the couplings and gravity add after it
}

template <int D>
void SphPackage<D>::add_gravity(const std::array<double, 3>& g, double& power) {
  ParticleArrays<D>& p = system_.particles();
  for (std::size_t k = 0; k < p.real; ++k)
    for (int i = 0; i < D; ++i) {
      p.acceleration[k][i] += g[static_cast<std::size_t>(i)];
      power += p.mass[k] * g[static_cast<std::size_t>(i)] * p.velocity[k][i];
    }
}

template <int D>
double SphPackage<D>::drift(const StepClock& clock) {
  // The kinetic energy at t_n in the centred form, before the particles move.
  const double kinetic = system_.centred_kinetic_energy();
  system_.drift(clock.dt_next);
  return kinetic;
}

template <int D>
typename Package<D>::Vote SphPackage<D>::vote() const {
  const TimeStepLimit limit = system_.stable_time_step();
  return {limit.dt, limit.reason};
}

template <int D>
void SphPackage<D>::check() const {
  const RunControl& run = model_.run;
  const ParticleArrays<D>& p = system_.particles();
  for (std::size_t i = 0; i < p.real; ++i) {
    const double* x = p.position[i].c.data();
    bool finite = true;
    for (int d = 0; d < D; ++d) finite = finite && std::isfinite(x[d]) && std::isfinite(p.velocity[i][d]);
    if (!finite)
      throw NumericalError(EntityKind::particle, static_cast<std::int64_t>(p.id[i]) + 1, "velocity",
                           "non-finite position or velocity");
    const int axis = first_outside_domain<D>(run, x);
    if (axis >= 0)
      throw NumericalError(
          EntityKind::particle, static_cast<std::int64_t>(p.id[i]) + 1, "position",
          fmt::format("left the domain box: coordinate {} = {:.6g} m outside [{:.6g}, {:.6g}] m", axis + 1,
                      x[axis], run.domain_min[static_cast<std::size_t>(axis)],
                      run.domain_max[static_cast<std::size_t>(axis)]));
  }
}

template <int D>
std::string SphPackage<D>::describe(EntityKind kind, std::int64_t id) const {
  if (kind != EntityKind::particle || id < 1 || static_cast<std::size_t>(id - 1) >= system_.size()) return {};
  // Particles are named by id; the memory index differs once they are re-sorted by cell.
  const auto k = static_cast<std::size_t>(id - 1);
  const ParticleArrays<D>& p = system_.particles();
  std::size_t i = k;
  for (std::size_t j = 0; j < p.real; ++j)
    if (p.id[j] == k) i = j;
  return fmt::format("material '{}', position {}", model_.materials[static_cast<std::size_t>(p.material[i])].name,
                     position_text<D>(p.position[i].c.data()));
}

template <int D>
void SphPackage<D>::hold_still(const std::vector<char>& held_material) {
  if (std::any_of(held_material.begin(), held_material.end(), [](char c) { return c; }))
    system_.hold_still(held_material);
}

template class SphPackage<2>;
template class SphPackage<3>;

}  // namespace camouflet::sph
