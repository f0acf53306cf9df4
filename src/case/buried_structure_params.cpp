#include "case/buried_structure_params.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "case/toml_reader.hpp"

namespace camouflet {

namespace {

// Reads an optional number of `table`, recording where it was for later errors.
void read(TomlReader& table, const std::string& key, double& value, BuriedStructureSpec& spec) {
  if (!table.has(key)) return;
  value = table.number(key);
  spec.where[table.key_path(key)] = table.where(key);
}

void read(TomlReader& table, const std::string& key, std::string& value, BuriedStructureSpec& spec) {
  if (!table.has(key)) return;
  value = table.string(key);
  spec.where[table.key_path(key)] = table.where(key);
}

// `hourglass = { form = ..., coefficient = ... }` of [soil] or [structure].
void read_hourglass(TomlReader& table, std::string& form, double& coefficient, BuriedStructureSpec& spec) {
  auto h = table.table("hourglass");
  if (!h) return;
  spec.where[table.key_path("hourglass")] = table.where("hourglass");
  if (h->has("form")) {
    form = h->choice("form", {"stiffness", "viscous"}, "");
    spec.where[h->key_path("form")] = h->where("form");
  }
  read(*h, "coefficient", coefficient, spec);
  h->finish();
}

}  // namespace

BuriedStructureSpec read_buried_structure_params_text(const std::string& text,
                                                      const std::filesystem::path& file) {
  toml::table doc;
  try {
    doc = toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    SourceLocation w{file.string(), static_cast<int>(e.source().begin.line),
                     static_cast<int>(e.source().begin.column), ""};
    throw InputError(w, fmt::format("malformed TOML: {}", e.description()));
  }
  BuriedStructureSpec s;
  s.source = file.string();
  TomlReader root(doc, file.string(), "");
  read(root, "title", s.title, s);
  if (auto t = root.table("charge")) {
    read(*t, "mass", s.charge_mass, s);
    read(*t, "explosive", s.explosive, s);
    read(*t, "density", s.explosive_density, s);
    read(*t, "depth", s.burst_depth, s);
    if (t->has("particles_across_radius")) {
      s.charge_particles_across =
          static_cast<int>(t->integer("particles_across_radius", s.charge_particles_across));
      s.where["charge.particles_across_radius"] = t->where("particles_across_radius");
    }
    t->finish();
  }
  if (auto t = root.table("structure")) {
    read(*t, "standoff", s.standoff, s);
    read(*t, "length", s.box_length, s);
    read(*t, "height", s.box_height, s);
    read(*t, "wall_thickness", s.wall_thickness, s);
    read(*t, "top_depth", s.top_depth, s);
    read(*t, "width", s.box_width, s);
    read(*t, "concrete", s.concrete, s);
    if (t->has("kind")) {
      s.free_field = t->choice("kind", {"box", "free_field"}, "box") == "free_field";
      s.where["structure.kind"] = t->where("kind");
    }
    if (t->has("interface")) {
      s.slide_interface = t->choice("interface", {"fused", "slide"}, "fused") == "slide";
      s.where["structure.interface"] = t->where("interface");
    }
    if (t->has("friction")) {
      if (!s.slide_interface)
        t->fail("friction", "a friction coefficient needs interface = \"slide\" (a fused interface does not slide)");
      s.interface_friction = t->non_negative("friction", 0.0);
      s.where["structure.friction"] = t->where("friction");
    }
    read_hourglass(*t, s.structure_hourglass, s.structure_hourglass_coefficient, s);
    t->finish();
  }
  if (auto t = root.table("rebar")) {
    s.has_rebar = true;
    s.rebar_cover = t->number("cover");
    s.where["rebar.cover"] = t->where("cover");
    s.rebar_ratio = t->number("ratio");
    s.where["rebar.ratio"] = t->where("ratio");
    read(*t, "steel", s.steel, s);
    s.where["rebar"] = t->where();
    t->finish();
  }
  if (auto t = root.table("sph")) {
    read(*t, "radius", s.sph_radius, s);
    read(*t, "depth", s.sph_depth, s);
    t->finish();
  }
  if (auto t = root.table("soil")) {
    read(*t, "preset", s.soil, s);
    read(*t, "wave_speed", s.soil_wave_speed, s);
    read_hourglass(*t, s.soil_hourglass, s.soil_hourglass_coefficient, s);
    if (auto e = t->table("erosion")) {
      s.where[t->key_path("erosion")] = t->where("erosion");
      s.soil_erosion_strain = e->positive("geometric_strain");
      s.where[e->key_path("geometric_strain")] = e->where("geometric_strain");
      e->finish();
    }
    t->finish();
  }
  if (auto t = root.table("domain")) {
    read(*t, "radius", s.domain_radius, s);
    read(*t, "depth", s.domain_depth, s);
    read(*t, "side", s.domain_side, s);
    if (t->has("geometry")) {
      s.three_d = t->choice("geometry", {"axisymmetric", "3d"}, "") == "3d";
      s.where["domain.geometry"] = t->where("geometry");
    }
    if (t->has("far_edges"))
      s.transmitting = t->choice("far_edges", {"transmitting", "fixed"}, "") == "transmitting";
    t->finish();
  }
  if (auto t = root.table("mesh")) {
    read(*t, "near_radius", s.near_radius, s);
    read(*t, "near", s.size_near, s);
    read(*t, "structure", s.size_structure, s);
    read(*t, "soil", s.size_soil, s);
    read(*t, "far", s.size_far, s);
    t->finish();
  }
  if (auto t = root.table("run")) {
    read(*t, "end_time", s.run.end_time, s);
    read(*t, "field_interval", s.run.field_interval, s);
    read(*t, "gauge_interval", s.run.gauge_interval, s);
    read(*t, "cfl", s.run.cfl, s);
    read(*t, "hourglass_coefficient", s.hourglass_coefficient, s);
    read(*t, "gravity", s.run.gravity, s);
    read(*t, "relaxation_period", s.run.relaxation_period, s);
    t->finish();
  }
  if (auto t = root.table("gauges")) {
    s.gauge_count = static_cast<int>(t->integer("count", s.gauge_count));
    s.where["gauges.count"] = t->where("count");
    t->finish();
  }
  root.finish();
  return s;
}

BuriedStructureSpec read_buried_structure_params(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{file.string(), 0, 0, ""}, "cannot open the parameter file");
  std::stringstream text;
  text << in.rdbuf();
  return read_buried_structure_params_text(text.str(), file);
}

}  // namespace camouflet
