// The reinforced-concrete stages of the cycle: embedded bars and
// element erosion. Kept apart from solver.cpp so each stage reads on its own;
// docs/theory/reinforcement.md.
#include <cmath>

#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::setup_reinforcement() {
  // Bars take their hosts' velocity: their mass joins the nodes after the
  // initial velocities are set, so the parts' initial velocities stay exact.
  bars_ = EmbeddedBars<D>(model_, position_);
  bars_.add_masses(node_mass_);
  for (const auto& criteria : model_.erosion) {
    erosion_ = erosion_ || criteria.enabled();
    if (criteria.geometric_strain > 0.0) total_strain_.assign(elements_.size(), SymTensor{});
  }
}

template <int D>
void Solver<D>::add_bar_forces() {
  if (!bars_.empty()) bars_.add_forces(position_.data(), force_.data());
}

template <int D>
void Solver<D>::update_bars() {
  if (!bars_.empty()) bars_.update(position_.data(), velocity_.data(), dt_, time_);
}

template <int D>
void Solver<D>::erode_elements() {
  if (!erosion_) return;
  const std::size_t eroded_before = eroded_count_;
  const std::size_t ne = elements_.size();
  for (std::size_t e = 0; e < ne; ++e) {
    if (elements_.eroded[e]) continue;
    const auto m = static_cast<std::size_t>(elements_.material[e]);
    const ErosionCriteria criteria = model_.erosion_of(m);
    if (!criteria.enabled()) continue;
    MaterialPoints& pts = batches_[m];
    const std::size_t p = elements_.point[e];
    bool erode = criteria.damage > 0.0 && pts.damage[p] >= criteria.damage;
    if (criteria.geometric_strain > 0.0) {
      // Geometric strain: the equivalent of the total strain summed from the
      // strain rates, sqrt(2/3 eps:eps) (the Autodyn "geometric strain").
      SymTensor& eps = total_strain_[e];
      eps += pts.strain_rate[p] * dt_;
      erode = erode || std::sqrt(2.0 / 3.0 * contract(eps, eps)) >= criteria.geometric_strain;
    }
    if (!erode) continue;
    // The mass stays on the nodes (momentum and kinetic energy are kept); the
    // internal energy the element holds leaves the internal sum for the eroded one.
    elements_.eroded[e] = 1;
    energy_.eroded += elements_.mass[e] * pts.specific_energy[p];
    pts.deviator[p] = SymTensor{};
    pts.pressure[p] = 0.0;
    pts.strain_rate[p] = SymTensor{};
    pts.spin[p] = Spin{};
    pts.artificial_viscosity[p] = 0.0;
    pts.density_previous[p] = pts.density[p];
    elements_.viscosity[e] = 0.0;
    ++eroded_count_;
  }
  // The SPH-FEM interface loses the eroded elements' faces and gains those they exposed.
  if (join_ && eroded_count_ != eroded_before) join_->follow_erosion();
}

#define CAMOUFLET_INSTANTIATE_REINFORCEMENT(D)    \
  template void Solver<D>::setup_reinforcement(); \
  template void Solver<D>::add_bar_forces();      \
  template void Solver<D>::update_bars();         \
  template void Solver<D>::erode_elements();
CAMOUFLET_INSTANTIATE_REINFORCEMENT(2)
CAMOUFLET_INSTANTIATE_REINFORCEMENT(3)

}  // namespace camouflet
