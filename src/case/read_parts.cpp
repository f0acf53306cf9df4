// [[parts]]: a named part of one material, meshed by the built-in block
// generator or read from a Gmsh file (docs/case-format.md).
#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "case/sections.hpp"
#include "coupling/joined_zone.hpp"
#include "mesh/block_generator.hpp"
#include "mesh/gmsh_import.hpp"
#include "mesh/particle_fill.hpp"

namespace camouflet::case_detail {

int material_index(const Model& model, TomlReader& table, const std::string& key) {
  const std::string name = table.string(key);
  std::vector<std::string> names;
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    if (model.materials[m].name == name) return static_cast<int>(m);
    names.push_back(model.materials[m].name);
  }
  const std::string guess = nearest(name, names);
  table.fail(key,
             guess.empty()
                 ? fmt::format("no material '{}' is defined ({})", name,
                               names.empty() ? "the case has no [materials] section"
                                             : "defined: " + fmt::format("{}", fmt::join(names, ", ")))
                 : fmt::format("no material '{}' is defined; did you mean '{}'?", name, guess));
}

namespace {

// Reads the block and meshes it: a plain block, or a wall with its steel
// layers when the part has `rebar_layers` (case/read_reinforcement.cpp).
void read_block(TomlReader& block, Model& model, const std::string& name, int part_index, TomlReader& part) {
  const int dim = model.dimension();
  BlockSpec spec;
  spec.name = name;
  spec.part = part_index;
  spec.origin = block.vector("origin", dim, {0, 0, 0});
  spec.size = block.vector("size", dim);
  for (int i = 0; i < dim; ++i)
    if (!(spec.size[static_cast<std::size_t>(i)] > 0.0))
      block.fail("size", fmt::format("every extent must be positive, got {} along axis {}",
                                     spec.size[static_cast<std::size_t>(i)], "xyz"[i]));
  const auto cells = block.numbers("cells");
  if (static_cast<int>(cells.size()) != dim)
    block.fail("cells", fmt::format("expected {} cell counts, got {}", dim, cells.size()));
  for (int i = 0; i < dim; ++i) {
    const double c = cells[static_cast<std::size_t>(i)];
    if (!(c >= 1.0) || c != static_cast<double>(static_cast<long long>(c)) || c > 1e7)
      block.fail("cells", fmt::format("cell counts must be whole numbers from 1 to 1e7, got {}", c));
    spec.cells[static_cast<std::size_t>(i)] = static_cast<int>(c);
  }
  double total = 1.0;
  for (int i = 0; i < dim; ++i) total *= spec.cells[static_cast<std::size_t>(i)];
  if (total > 5e7)
    block.fail("cells", fmt::format("{:.0f} elements is more than this build handles (5e7)", total));
  spec.grading = block.vector("grading", dim, {1, 1, 1});
  if (dim == 2) spec.grading[2] = 1.0;
  for (int i = 0; i < dim; ++i)
    if (!(spec.grading[static_cast<std::size_t>(i)] > 0.0))
      block.fail("grading", "every ratio must be positive");
  block.finish();
  if (part.has("rebar_layers")) return read_rebar_wall(part, spec, model);
  try {
    add_block(model.mesh, spec);
  } catch (const InputError& e) {
    // The generator knows nothing of the case file: name the block instead.
    throw InputError(block.where(), e.message());
  }
}

// `fill = { shape = ..., spacing = ... }` of an SPH part (docs/case-format.md).
ParticleFillSpec read_fill(TomlReader& fill, Model& model, int part_index,
                           const std::filesystem::path& case_dir) {
  const int dim = model.dimension();
  ParticleFillSpec spec;
  spec.part = part_index;
  spec.where = fill.where();
  const std::string shape = fill.choice("shape", {"box", "sphere", "cylinder", "polygon", "gmsh"}, "box");
  auto& region = spec.region;
  if (shape == "box") {
    region.shape = ParticleRegion::Shape::box;
    region.min = fill.vector("min", dim);
    region.max = fill.vector("max", dim);
    for (int i = 0; i < dim; ++i)
      if (!(region.max[static_cast<std::size_t>(i)] > region.min[static_cast<std::size_t>(i)]))
        fill.fail("max", fmt::format("the box is empty: max <= min along axis {}", "xyz"[i]));
  } else if (shape == "sphere" || shape == "cylinder") {
    region.shape = shape == "sphere" ? ParticleRegion::Shape::sphere : ParticleRegion::Shape::cylinder;
    region.centre = fill.vector("centre", dim);
    region.radius = fill.positive("radius");
    if (shape == "cylinder") {
      region.length = fill.positive("length");
      if (dim == 3) region.axis = fill.vector("axis", dim, {0, 0, 1});
    }
  } else if (shape == "gmsh") {
    // A physical surface (2-D) or volume (3-D) of a Gmsh file, cut into simplices.
    region.shape = ParticleRegion::Shape::mesh;
    const std::filesystem::path file = fill.string("file");
    region.mesh = std::make_shared<const SimplexRegion>(
        import_gmsh_region(dim, file.is_absolute() ? file : case_dir / file, fill.string("physical"),
                           fill.where("file"), fill.where("physical")));
  } else {
    if (dim != 2) fill.fail("shape", "a polygon fills a 2-D region only");
    region.shape = ParticleRegion::Shape::polygon;
    const auto v = fill.numbers("vertices");
    if (v.size() < 6 || v.size() % 2 != 0)
      fill.fail("vertices", "a polygon needs at least 3 vertices as a flat list [x1, y1, x2, y2, ...]");
    for (std::size_t k = 0; k < v.size(); k += 2) region.polygon.push_back({v[k], v[k + 1]});
  }
  spec.spacing = fill.positive("spacing");
  if (fill.has("grading_point")) {
    spec.graded = true;
    spec.grading_point = fill.vector("grading_point", dim);
    spec.grading_ratio = fill.number("grading_ratio");
    if (!(spec.grading_ratio >= 1.0)) fill.fail("grading_ratio", "the grading ratio must be at least 1");
    spec.max_spacing = fill.positive("max_spacing");
    if (spec.max_spacing < spec.spacing)
      fill.fail("max_spacing",
                fmt::format("max_spacing {} is below spacing {}", spec.max_spacing, spec.spacing));
  }
  fill.finish();
  return spec;
}

// An SPH part's fill, read with the part and filled once every FEM part is
// meshed: a joined zone cuts its hole from them (docs/case-format.md,
// "Joined SPH zones").
struct PendingFill {
  ParticleFillSpec spec;
  bool join = false;
  std::vector<std::string> cut_from;  // FEM parts the hole is cut from; empty: every FEM part
  SourceLocation cut_where;           // `cut_from`, else `join`
  std::vector<std::string> exclude;   // SPH parts whose regions are left out
  SourceLocation exclude_where;
};

// `fill`, `join`, `cut_from` and `exclude` of an SPH part (part names are
// resolved once all parts are read: they may name a part defined later).
PendingFill read_sph_part(TomlReader& p, Model& model, int index, const std::filesystem::path& case_dir) {
  PendingFill pending;
  auto fill = p.table("fill");
  if (!fill) p.fail("fill", "an SPH part needs `fill = { shape = ..., spacing = ... }`");
  if (p.has("block") || p.has("gmsh"))
    p.fail(p.has("block") ? "block" : "gmsh", "an SPH part is filled, not meshed");
  pending.spec = read_fill(*fill, model, index, case_dir);
  if (const toml::node* j = p.node("join")) {
    if (!j->is_boolean()) p.fail("join", "expected true or false");
    pending.join = j->as_boolean()->get();
    pending.cut_where = p.where("join");
  }
  if (p.has("cut_from")) {
    pending.cut_from = name_list(p, "cut_from");
    pending.cut_where = p.where("cut_from");
    pending.join = true;
  }
  if (p.has("exclude")) {
    pending.exclude = name_list(p, "exclude");
    pending.exclude_where = p.where("exclude");
  }
  return pending;
}

// The index of part `name`, which must be of `kind` and not `self`; InputError at `where` otherwise.
int part_named(const Model& model, const std::string& name, PartKind kind, const SourceLocation& where,
               int self) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < model.parts.size(); ++k) {
    const Part& part = model.parts[k];
    if (part.name == name) {
      if (static_cast<int>(k) == self) throw InputError(where, fmt::format("part '{}' names itself", name));
      if (part.kind != kind)
        throw InputError(where, fmt::format("part '{}' is {} part, expected {} part here", name,
                                            part.kind == PartKind::sph ? "an SPH" : "a FEM",
                                            kind == PartKind::sph ? "an SPH" : "a FEM"));
      return static_cast<int>(k);
    }
    if (part.kind == kind) names.push_back(part.name);
  }
  const std::string guess = nearest(name, names);
  throw InputError(where, guess.empty()
                              ? fmt::format("no part '{}' is defined", name)
                              : fmt::format("no part '{}' is defined; did you mean '{}'?", name, guess));
}

// `hourglass = { form = ..., coefficient = ..., subzonal = ... }` of a FEM part: its own
// hourglass control in place of [run.hourglass], and its own subzonal pressures (absent: the
// run's) (docs/case-format.md).
HourglassControl read_part_hourglass(TomlReader& h, Part& part) {
  if (h.has("subzonal")) part.subzonal = h.non_negative("subzonal", 0.0);
  HourglassControl control;
  const std::string form = h.choice("form", {"viscous", "stiffness"}, "");
  control.form = form == "stiffness" ? HourglassForm::stiffness : HourglassForm::viscous;
  if (h.has("coefficient")) {
    control.coefficient = h.number("coefficient");
    // A part asking for control gets some: 0 is "none", which a part does not choose.
    if (!(control.coefficient > 0.0 && control.coefficient <= 0.5))
      h.fail("coefficient", fmt::format("must lie in (0, 0.5], got {}", control.coefficient));
  }
  h.finish();
  return control;
}

// Fills the SPH parts in the order they are declared; a joined part first cuts
// its hole from the FEM mesh and records the join (coupling/joined_zone.hpp).
void fill_sph_parts(std::vector<PendingFill>& pending, Model& model) {
  for (PendingFill& f : pending) {
    for (const std::string& name : f.exclude) {
      const int other = part_named(model, name, PartKind::sph, f.exclude_where, f.spec.part);
      for (const PendingFill& g : pending)
        if (g.spec.part == other) f.spec.exclude.push_back(g.spec.region);
    }
    if (!f.join) {
      fill_particles(model.particles, f.spec, model.run.mode);
      continue;
    }
    std::vector<int> cut;
    for (const std::string& name : f.cut_from)
      cut.push_back(part_named(model, name, PartKind::fem, f.cut_where, f.spec.part));
    make_joined_zone(model, f.spec, cut, f.cut_where);
  }
}

// `geostatic = { surface = ..., k0 = 0.5 | "jaky", surcharge = ... }` of a FEM or SPH part: its initial
// stress from the overburden under [run] gravity (docs/case-format.md, docs/theory/gravity.md).
GeostaticState read_part_geostatic(TomlReader& t, const Model& model, const Part& part) {
  GeostaticState geo;
  geo.where = t.where();
  if (!model.run.has_gravity())
    t.fail("surface", "a geostatic state needs [run] gravity = [...] (m/s^2), which is not set");
  geo.surface = t.number("surface");
  geo.surcharge = t.non_negative("surcharge", 0.0);
  if (!t.has("k0")) t.fail("k0", "missing: a number (sigma_h / sigma_v) or \"jaky\" (1 - sin(phi))");
  const toml::node* k0 = t.node("k0");
  if (k0->is_string()) {
    const std::string word = t.string("k0");
    if (word != "jaky") t.fail("k0", fmt::format("expected a number or \"jaky\", got \"{}\"", word));
    const NamedMaterial& material = model.materials[static_cast<std::size_t>(part.material)];
    const StrengthModel* strength = material.material->strength();
    if (!strength || !strength->friction_angle())
      t.fail("k0", fmt::format("\"jaky\" takes K0 = 1 - sin(phi) from the friction angle, and material '{}' "
                               "({}) has none; give k0 as a number",
                               material.name, strength ? strength->type() : "no strength"));
  } else {
    geo.k0 = t.number("k0");
    if (!(*geo.k0 >= 0.0)) t.fail("k0", fmt::format("must not be negative, got {}", *geo.k0));
  }
  t.finish();
  return geo;
}

}  // namespace

std::vector<std::string> name_list(TomlReader& p, const std::string& key) {
  const toml::array* list = p.array(key);
  if (!list || list->empty()) p.fail(key, "expected a non-empty list of part names");
  std::vector<std::string> out;
  for (const auto& item : *list) {
    const auto name = item.value<std::string>();
    if (!name) p.fail(key, "expected a list of part names (strings)");
    out.push_back(*name);
  }
  return out;
}

void read_parts(TomlReader& root, Model& model, const std::filesystem::path& case_dir) {
  const int dim = model.dimension();
  model.mesh.dimension = dim;
  model.mesh.nodes_per_element = dim == 3 ? 8 : 4;
  std::set<std::string> seen;
  std::vector<PendingFill> pending;  // SPH parts, filled once the FEM parts are meshed
  auto parts = root.tables("parts");
  if (parts.empty()) throw InputError(root.where("parts"), "the case has no [[parts]]: nothing to simulate");
  for (auto& p : parts) {
    Part part;
    part.where = p.where();
    part.name = p.string("name");
    check_name(p, "name", part.name);
    if (!seen.insert(part.name).second) p.fail("name", fmt::format("part '{}' is defined twice", part.name));
    part.material = material_index(model, p, "material");
    const std::string kind = p.choice("kind", {"fem", "sph"}, "fem");
    part.kind = kind == "sph" ? PartKind::sph : PartKind::fem;
    part.initial_velocity = p.vector("initial_velocity", dim, {0, 0, 0});
    if (auto geo = p.table("geostatic")) part.geostatic = read_part_geostatic(*geo, model, part);
    if (part.kind == PartKind::fem) {
      if (auto h = p.table("hourglass")) part.hourglass = read_part_hourglass(*h, part);
      if (auto v = p.table("viscosity")) {
        part.viscosity_form = read_viscosity_form(*v, model.run.viscosity_form);
        v->finish();
      }
      if (p.has("axisymmetric_momentum")) {
        if (model.run.mode != GeometryMode::axisymmetric)
          p.fail("axisymmetric_momentum", "a momentum form is chosen in geometry mode 'axisymmetric' only");
        part.area_weighted_momentum =
            p.choice("axisymmetric_momentum", {"volume", "area"}, "volume") == "area";
      }
    } else {
      if (p.has("hourglass"))
        p.fail("hourglass", "only a FEM part has hourglass control (SPH particles have no hourglass modes)");
      if (p.has("viscosity"))
        p.fail("viscosity",
               "only a FEM part takes a FEM viscosity form (the particles' is [sph] viscosity_alpha, "
               "viscosity_beta)");
      if (p.has("axisymmetric_momentum"))
        p.fail("axisymmetric_momentum",
               "only a FEM part takes a momentum form (the particles' r-z sums are set in [sph])");
    }
    const int index = static_cast<int>(model.parts.size());
    model.parts.push_back(part);
    if (part.kind == PartKind::sph) {
      pending.push_back(read_sph_part(p, model, index, case_dir));
      p.finish();
      continue;
    }
    for (const char* key : {"join", "cut_from", "exclude"})
      if (p.has(key))
        p.fail(key, "only an SPH part (kind = \"sph\") is joined to FEM parts or excludes regions");

    const bool has_block = p.has("block"), has_gmsh = p.has("gmsh");
    if (has_block == has_gmsh)
      p.fail(has_block ? "gmsh" : "block",
             "a part needs exactly one mesh source: `block = {...}` or `gmsh = \"file.msh\"`");
    if (has_block) {
      auto block = p.table("block");
      read_block(*block, model, part.name, index, p);
    } else {
      GmshPartRequest request;
      const std::filesystem::path file = p.string("gmsh");
      request.file = file.is_absolute() ? file : case_dir / file;
      request.file_where = p.where("gmsh");
      request.physical = p.string("physical");
      request.physical_where = p.where("physical");
      request.part = index;
      import_gmsh_part(model.mesh, request);
    }
    p.finish();
  }
  fill_sph_parts(pending, model);
}

void check_name(const TomlReader& table, const std::string& key, const std::string& name) {
  const bool ok =
      !name.empty() && name.size() <= 64 &&
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") ==
          std::string::npos &&
      name.front() != '.';
  if (!ok)
    table.fail(key,
               fmt::format("'{}' is not a valid name: use 1 to 64 letters, digits, '_', '-' or '.'", name));
}

}  // namespace camouflet::case_detail
