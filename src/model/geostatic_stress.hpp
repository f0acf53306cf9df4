#pragma once
// The geostatic initial state of soil parts under gravity (docs/theory/gravity.md) for the
// points of a material batch, whichever method carries them: FEM element points and SPH
// particles ask their part's overburden stress at their centres, then each batch commits it
// at once (the density at which the EOS carries the mean stress, the deviator, the strength
// check). The solver and the SPH package call the same two functions.
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace camouflet {

// What the geostatic parts ask of the points of one material batch, before it is committed.
struct GeostaticRequest {
  std::vector<SymTensor> stress;  // Pa, tension positive
  std::vector<double> depth;      // m below the part's surface, along gravity
  std::vector<char> active;       // 1: the point takes a geostatic state
  std::vector<std::size_t> part;  // Model::parts index of each active point

  explicit GeostaticRequest(std::size_t points = 0)
      : stress(points), depth(points, 0.0), active(points, 0), part(points, 0) {}
  bool any() const;
};

// A point of a geostatic part: its slot in the batch of the part's material and its centre (m,
// padded to three components).
struct GeostaticPoint {
  std::size_t slot = 0;
  std::array<double, 3> centre{};
};

// Asks part `part_index`'s overburden state (vertical stress, K0 times it across) at `points`.
// `name(k)` names points[k] in an error ("element 12", "particle 5"). Refuses a part without
// gravity, a point above the part's surface and Jaky's K0 on a material without a friction angle.
void ask_geostatic_stress(const Model& model, std::size_t part_index,
                          const std::vector<GeostaticPoint>& points,
                          const std::function<std::string(std::size_t)>& name, GeostaticRequest& request);

// Commits the asked state to `pts`, the batch of material `m`: each active point's density is the
// one at which the EOS carries the asked mean stress (history states committed there), its
// deviator the rest. A state outside the strength is refused: clamping it would start the model
// out of equilibrium. Does nothing when no point of the batch is active.
void commit_geostatic_state(const Model& model, std::size_t m, MaterialPoints& pts,
                            const GeostaticRequest& request);

// The whole geostatic initial state of one method's points: for every part of `kind` with a
// geostatic state, points_of(part, points, ids) lists its points and their 1-based ids (named
// "<noun> <id>" in errors); each batch (by Model::materials index) is then committed at once.
void set_geostatic_states(const Model& model, PartKind kind, const char* noun,
                          std::vector<MaterialPoints>& batches,
                          const std::function<void(std::size_t, std::vector<GeostaticPoint>&,
                                                   std::vector<std::size_t>&)>& points_of);

}  // namespace camouflet
