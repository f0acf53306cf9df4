#pragma once
// Reinforcement as thin steel element layers sharing nodes with the concrete
// (Wang et al. 2005, section 5.1): a wall or slab strip built from stacked
// blocks through its thickness (y) -- cover concrete, steel layer, core
// concrete, steel layer, cover -- joined by add_block's node sharing. Each
// steel layer is one element thick with thickness t = steel area per unit
// width (m^2/m), so the steel volume equals the real rebar volume.
// docs/theory/reinforcement.md, section 1.
#include <array>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace camouflet {

enum class RebarFace { ymin, ymax };

struct RebarLayer {
  double cover = 0.0;                  // m, clear distance from `face` to the steel layer
  double steel_area_per_length = 0.0;  // m^2/m: bar area / bar spacing (the layer thickness)
  RebarFace face = RebarFace::ymin;
  int part = -1;  // index into Model::parts (the steel part of this layer)
};

struct RebarWallSpec {
  std::string name;                   // prefixes the block and set names
  int concrete_part = -1;             // index into Model::parts
  std::array<double, 3> origin{};     // m, min corner
  std::array<double, 3> size{};       // m: span (x), thickness (y), depth (z, 3-D)
  std::array<int, 3> cells{1, 1, 1};  // along x; through the concrete thickness (y, shared by the
                                      // concrete layers by thickness, at least 1 each); along z (3-D)
  std::vector<RebarLayer> layers;
  SourceLocation where;  // for error messages; keys are named "rebar_layers[k].<key>"
};

// One concrete or steel layer of the stack, bottom (ymin) to top.
struct RebarStackLayer {
  double y0 = 0.0, thickness = 0.0;  // m
  int cells = 1;
  int part = -1;
  int steel_layer = -1;  // index into spec.layers; -1 for concrete
};

// The stack through the thickness; throws InputError naming the key for a
// negative cover, a non-positive area, a layer outside the wall or two
// overlapping layers.
std::vector<RebarStackLayer> rebar_stack(const RebarWallSpec& spec);

// Appends the wall to the mesh. Sets: "<name>.xmin", ".xmax", ".ymin",
// ".ymax" (".zmin", ".zmax" in 3-D) over the whole wall, and each layer's
// own block sets "<name>.layer<k>.*" (k from 0 at ymin).
void add_rebar_wall(FemMesh& mesh, const RebarWallSpec& spec);

}  // namespace camouflet
