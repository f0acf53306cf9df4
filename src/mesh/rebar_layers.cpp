#include "mesh/rebar_layers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "mesh/block_generator.hpp"

namespace camouflet {

namespace {

[[noreturn]] void fail(const RebarWallSpec& spec, const std::string& key, const std::string& message) {
  SourceLocation w = spec.where;
  w.key = w.key.empty() ? key : w.key + "." + key;
  throw InputError(w, message);
}

void merge_set(std::map<std::string, std::vector<std::int64_t>>& sets, const std::string& from,
               const std::string& to) {
  const auto it = sets.find(from);
  if (it == sets.end()) return;
  auto& target = sets[to];
  for (const auto n : it->second)
    if (std::find(target.begin(), target.end(), n) == target.end()) target.push_back(n);
}

void merge_faces(std::map<std::string, std::vector<std::int64_t>>& faces, const std::string& from,
                 const std::string& to) {
  const auto it = faces.find(from);
  if (it == faces.end()) return;
  auto& target = faces[to];
  target.insert(target.end(), it->second.begin(), it->second.end());
}

}  // namespace

std::vector<RebarStackLayer> rebar_stack(const RebarWallSpec& spec) {
  const double y_lo = spec.origin[1], thickness = spec.size[1];
  if (!(thickness > 0.0)) fail(spec, "size", "the wall thickness (size along y) must be positive");
  if (spec.layers.empty()) fail(spec, "rebar_layers", "give at least one rebar layer");
  std::vector<RebarStackLayer> steel;
  for (std::size_t k = 0; k < spec.layers.size(); ++k) {
    const RebarLayer& l = spec.layers[k];
    const std::string key = fmt::format("rebar_layers[{}]", k);
    if (!(l.cover >= 0.0) || !std::isfinite(l.cover))
      fail(spec, key + ".cover", fmt::format("the cover must be zero or positive, got {} m", l.cover));
    if (!(l.steel_area_per_length > 0.0) || !std::isfinite(l.steel_area_per_length))
      fail(spec, key + ".steel_area_per_length",
           fmt::format("the steel area per unit length must be positive, got {} m^2/m",
                       l.steel_area_per_length));
    const double t = l.steel_area_per_length;
    if (l.cover + t > thickness * (1.0 + 1e-12))
      fail(spec, key + ".cover",
           fmt::format("cover {} m + steel layer {} m is thicker than the wall ({} m)", l.cover, t,
                       thickness));
    const double y0 = l.face == RebarFace::ymin ? y_lo + l.cover : y_lo + thickness - l.cover - t;
    steel.push_back({y0, t, 1, l.part, static_cast<int>(k)});
  }
  std::sort(steel.begin(), steel.end(), [](const auto& a, const auto& b) { return a.y0 < b.y0; });
  for (std::size_t k = 1; k < steel.size(); ++k)
    if (steel[k].y0 < steel[k - 1].y0 + steel[k - 1].thickness - 1e-12 * thickness)
      fail(spec, fmt::format("rebar_layers[{}].cover", steel[k].steel_layer),
           fmt::format("steel layers {} and {} overlap", steel[k - 1].steel_layer, steel[k].steel_layer));

  // Concrete between the steel layers (gaps of zero width are left out: a
  // steel layer at zero cover is the face itself).
  std::vector<RebarStackLayer> stack;
  double y = y_lo, steel_total = 0.0;
  for (const auto& s : steel) {
    if (s.y0 - y > 1e-9 * thickness) stack.push_back({y, s.y0 - y, 1, spec.concrete_part, -1});
    stack.push_back(s);
    y = s.y0 + s.thickness;
    steel_total += s.thickness;
  }
  if (y_lo + thickness - y > 1e-9 * thickness)
    stack.push_back({y, y_lo + thickness - y, 1, spec.concrete_part, -1});
  const double concrete_total = thickness - steel_total;
  for (auto& l : stack)
    if (l.steel_layer < 0)
      l.cells = std::max(1, static_cast<int>(std::lround(spec.cells[1] * l.thickness / concrete_total)));
  return stack;
}

void add_rebar_wall(FemMesh& mesh, const RebarWallSpec& spec) {
  const int d = mesh.dimension;
  if (!(spec.size[0] > 0.0)) fail(spec, "size", "the wall span (size along x) must be positive");
  if (d == 3 && !(spec.size[2] > 0.0)) fail(spec, "size", "the wall depth (size along z) must be positive");
  const std::vector<RebarStackLayer> stack = rebar_stack(spec);
  const std::string p = spec.name + ".";
  for (std::size_t k = 0; k < stack.size(); ++k) {
    const RebarStackLayer& l = stack[k];
    BlockSpec b;
    b.name = fmt::format("{}layer{}", p, k);
    b.part = l.part;
    b.origin = {spec.origin[0], l.y0, spec.origin[2]};
    b.size = {spec.size[0], l.thickness, spec.size[2]};
    b.cells = {spec.cells[0], l.cells, spec.cells[2]};
    add_block(mesh, b);
    for (const char* side : {"xmin", "xmax", "zmin", "zmax"}) {
      merge_set(mesh.node_sets, b.name + "." + side, p + side);
      merge_faces(mesh.face_sets, b.name + "." + side, p + side);
    }
    if (k == 0) {
      merge_set(mesh.node_sets, b.name + ".ymin", p + "ymin");
      merge_faces(mesh.face_sets, b.name + ".ymin", p + "ymin");
    }
    if (k + 1 == stack.size()) {
      merge_set(mesh.node_sets, b.name + ".ymax", p + "ymax");
      merge_faces(mesh.face_sets, b.name + ".ymax", p + "ymax");
    }
  }
  for (auto& [name, nodes] : mesh.node_sets)
    if (name.rfind(p, 0) == 0 && name.find(".layer") == std::string::npos)
      std::sort(nodes.begin(), nodes.end());
}

}  // namespace camouflet
