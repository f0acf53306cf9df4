// The SPH state for checkpoints: every particle and ghost array,
// the material batches, and the neighbour lists with their build state, so
// that a restarted run sums the same neighbours in the same order and stays
// bit-identical to the uninterrupted one.
#include "materials/material_points_state.hpp"
#include "sph/neighbour_search.hpp"
#include "sph/sph_system.hpp"

namespace camouflet::sph {

template <int D>
void NeighbourSearch<D>::visit_state(StateVisitor& v) {
  StateScope scope(v, "neighbours");
  std::vector<std::uint64_t> offset(offset_.begin(), offset_.end());
  visit(v, "offset", offset);
  if (v.loading()) offset_.assign(offset.begin(), offset.end());
  visit(v, "list", list_);
  visit(v, "sorted", sorted_);
  visit(v, "x_build", x_build_);
  visit(v, "h_build", h_build_);
  std::uint64_t owned = n_owned_;
  visit(v, "n_owned", owned);
  n_owned_ = owned;
  visit(v, "skin", skin_);
  visit(v, "builds", builds_);
}

template <int D>
void SphSystem<D>::visit_state(StateVisitor& v) {
  StateScope scope(v, "sph");
  ParticleArrays<D>& p = p_;
  std::uint64_t real = p.real;
  visit(v, "real", real);
  p.real = real;
  visit(v, "position", p.position);
  visit(v, "velocity", p.velocity);
  visit(v, "mass", p.mass);
  visit(v, "planar_density", p.planar_density);
  visit(v, "smoothing_length", p.smoothing_length);
  visit(v, "stress_term", p.stress_term);
  visit(v, "tensile_term", p.tensile_term);
  visit(v, "wave_speed", p.wave_speed);
  visit(v, "stable_wave_speed", p.stable_wave_speed);
  visit(v, "correction", p.correction);
  visit(v, "viscosity_alpha", p.viscosity_alpha);
  visit(v, "acceleration", p.acceleration);
  visit(v, "displacement", p.displacement);
  visit(v, "density", p.density);
  visit(v, "reference_smoothing_length", p.reference_smoothing_length);
  visit(v, "reference_planar_density", p.reference_planar_density);
  visit(v, "spacing", p.spacing);
  visit(v, "stress", p.stress);
  visit(v, "pressure", p.pressure);
  visit(v, "plastic_strain", p.plastic_strain);
  visit(v, "damage", p.damage);
  visit(v, "temperature", p.temperature);
  visit(v, "material", p.material);
  visit(v, "part", p.part);
  visit(v, "slot", p.slot);
  visit(v, "heating", p.heating);
  visit(v, "compression_rate", p.compression_rate);
  visit(v, "neighbour_count", p.neighbour_count);
  visit(v, "strain_rate", p.strain_rate);
  visit(v, "spin", p.spin);
  visit(v, "id", p.id);
  visit(v, "builds_at_sort", builds_at_sort_);
  visit(v, "sorts", sorts_);
  int force_rebuild = force_rebuild_ ? 1 : 0;
  visit(v, "force_rebuild", force_rebuild);
  force_rebuild_ = force_rebuild != 0;

  std::vector<std::uint32_t> ghost_source, ghost_plane;
  for (const Ghost& g : ghosts_) {
    ghost_source.push_back(g.source);
    ghost_plane.push_back(g.plane);
  }
  visit(v, "ghost_source", ghost_source);
  visit(v, "ghost_plane", ghost_plane);
  if (v.loading()) {
    if (ghost_plane.size() != ghost_source.size())
      throw std::runtime_error("checkpoint: ghost arrays of different lengths");
    ghosts_.resize(ghost_source.size());
    for (std::size_t g = 0; g < ghosts_.size(); ++g) ghosts_[g] = {ghost_source[g], ghost_plane[g]};
    // The coupling points follow the restored ghosts, not the ghosts of the set-up this run
    // made before loading: until the next list rebuild they are written and read from here.
    external_begin_ = p.real + ghosts_.size();
  }
  int correction_current = correction_current_ ? 1 : 0;
  visit(v, "correction_current", correction_current);
  correction_current_ = correction_current != 0;
  visit(v, "skin", skin_);
  visit(v, "ghost_reach", ghost_reach_);
  visit(v, "velocity_old", velocity_old_);
  // The pair terms of the last force pass are not stored: kick() recomputes them.
  // Nor is the active pair list (active_pairs.hpp): any complete list gives the same sums to round-off.
  if (v.loading()) pair_dissipation_current_ = false, active_.forget();
  for (std::size_t m = 0; m < batches_.size(); ++m) {
    StateScope batch(v, "batch" + std::to_string(m));
    camouflet::visit_state(v, batches_[m]);
  }
  for (std::size_t m = 0; m < batch_particles_.size(); ++m)
    visit(v, "batch_particles" + std::to_string(m), batch_particles_[m]);
  search_.visit_state(v);
}

template void NeighbourSearch<2>::visit_state(StateVisitor&);
template void NeighbourSearch<3>::visit_state(StateVisitor&);
template void SphSystem<2>::visit_state(StateVisitor&);
template void SphSystem<3>::visit_state(StateVisitor&);

}  // namespace camouflet::sph
