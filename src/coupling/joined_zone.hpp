#pragma once
// Zone set-up of a joined SPH-FEM model: one region
// is declared SPH, the FEM mesh around it is given; make_joined_zone cuts the
// hole (every element whose centre lies inside the region), fills it with the
// part's particles (mesh/particle_fill.hpp, uniform or graded; a box region is
// snapped to the hole's bounding box so the particles tile exactly the cut
// cells) and records the
// join with the FEM parts around the hole. The user never places join pairs.
//
// Spacing limit: at the interface the particle spacing s_p and the size s_e of
// the elements beside the hole may differ by at most a factor
// join_spacing_ratio_limit (max(s_p/s_e, s_e/s_p) <= 2): beyond it the pair
// sums across the join see a lattice too unlike the particles' own and the
// reflection grows past 10 % (docs/theory/coupling.md). Beyond it ->
// InputError naming the part's `spacing` key.
#include "core/error.hpp"
#include "mesh/particle_fill.hpp"
#include "model/model.hpp"

namespace camouflet {

inline constexpr double join_spacing_ratio_limit = 2.0;

// Throws InputError (at spec.where) when the region cuts no element (nothing
// to join: key `region`) or the spacing ratio exceeds the limit (key `spacing`).
// cut_parts: the FEM parts the hole is cut from (indices into model.parts;
// empty: every FEM part). A listed part with no element in or beside the hole
// is not adjacent to the zone: InputError at cut_where.
void make_joined_zone(Model& model, const ParticleFillSpec& spec, const std::vector<int>& cut_parts = {},
                      const SourceLocation& cut_where = {});

}  // namespace camouflet
