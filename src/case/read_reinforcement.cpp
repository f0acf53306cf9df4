// Reinforced-concrete keys (docs/case-format.md "Reinforcement and erosion"):
// `rebar_layers = [...]` on a block part (thin steel layers sharing nodes
// with the concrete), [[bars]] (embedded bar elements) and a material's
// `erosion = {...}`.
#include <fmt/format.h>

#include "case/sections.hpp"
#include "mesh/rebar_layers.hpp"

namespace camouflet::case_detail {

void read_rebar_wall(TomlReader& part, const BlockSpec& block, Model& model) {
  if (block.grading[0] != 1.0 || block.grading[1] != 1.0 || block.grading[2] != 1.0)
    part.fail("rebar_layers", "a part with rebar_layers takes no `grading` in its block");
  RebarWallSpec wall;
  wall.name = block.name;
  wall.concrete_part = block.part;
  wall.origin = block.origin;
  wall.size = block.size;
  wall.cells = block.cells;
  wall.where = part.where("rebar_layers");
  wall.where.key.clear();  // the generator names "rebar_layers[k].<key>"
  auto layers = part.tables("rebar_layers");
  if (layers.empty())
    part.fail("rebar_layers", "give at least one layer {cover, steel_area_per_length, face, material}");
  const Part concrete = model.parts[static_cast<std::size_t>(block.part)];
  for (std::size_t k = 0; k < layers.size(); ++k) {
    TomlReader& l = layers[k];
    RebarLayer layer;
    layer.cover = l.number("cover");
    layer.steel_area_per_length = l.number("steel_area_per_length");
    layer.face = l.choice("face", {"ymin", "ymax"}, "ymin") == "ymin" ? RebarFace::ymin : RebarFace::ymax;
    Part steel;
    steel.name = fmt::format("{}.rebar{}", block.name, k);
    steel.material = material_index(model, l, "material");
    steel.initial_velocity = concrete.initial_velocity;
    steel.hourglass = concrete.hourglass;  // the layers are elements of the wall
    steel.where = l.where();
    layer.part = static_cast<int>(model.parts.size());
    model.parts.push_back(steel);
    l.finish();
    wall.layers.push_back(layer);
  }
  try {
    add_rebar_wall(model.mesh, wall);
  } catch (const InputError& e) {
    // Name the offending layer key with the part's file and line.
    SourceLocation w = part.where("rebar_layers");
    w.key = part.key_path(e.where().key.empty() ? "rebar_layers" : e.where().key);
    throw InputError(w, e.message());
  }
}

void read_bars(TomlReader& root, Model& model) {
  const int dim = model.dimension();
  for (auto& b : root.tables("bars")) {
    BarSet bar;
    bar.where = b.where();
    bar.name = b.string("name");
    check_name(b, "name", bar.name);
    for (const auto& other : model.bars)
      if (other.name == bar.name) b.fail("name", fmt::format("bar '{}' is defined twice", bar.name));
    bar.from = b.vector("from", dim);
    bar.to = b.vector("to", dim);
    const std::int64_t segments = b.integer("segments", 1);
    if (segments < 1 || segments > 10000000)
      b.fail("segments", fmt::format("must be from 1 to 1e7, got {}", segments));
    bar.segments = static_cast<int>(segments);
    bar.area = b.positive("area");
    bar.material = material_index(model, b, "material");
    if (b.has("host")) {
      const std::string host = b.string("host");
      for (std::size_t p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].name == host) bar.host_part = static_cast<int>(p);
      if (bar.host_part < 0) b.fail("host", fmt::format("no part '{}' is defined", host));
    }
    const std::string orientation = b.choice("orientation", {"along", "hoop"}, "along");
    bar.orientation = orientation == "hoop" ? BarOrientation::hoop : BarOrientation::along;
    if (bar.orientation == BarOrientation::hoop && model.run.mode != GeometryMode::axisymmetric)
      b.fail("orientation", "hoop bars (rings) need geometry = \"axisymmetric\"");
    b.finish();
    model.bars.push_back(std::move(bar));
  }
}

ErosionCriteria read_erosion(TomlReader& material) {
  ErosionCriteria erosion;
  auto e = material.table("erosion");
  if (!e) return erosion;
  if (e->has("geometric_strain")) erosion.geometric_strain = e->positive("geometric_strain");
  if (e->has("damage")) {
    erosion.damage = e->positive("damage");
    if (erosion.damage > 1.0)
      e->fail("damage", fmt::format("a damage threshold lies in (0, 1], got {}", erosion.damage));
  }
  e->finish();
  if (!erosion.enabled())
    material.fail("erosion", "give `geometric_strain` and/or `damage` (or leave `erosion` out)");
  return erosion;
}

}  // namespace camouflet::case_detail
