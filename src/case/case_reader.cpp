#include "case/case_reader.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "case/sections.hpp"

namespace camouflet {

namespace {

Model build(const toml::table& doc, const std::filesystem::path& file) {
  Model model;
  model.case_file = file.string();
  TomlReader root(doc, file.string(), "");
  model.title = root.string("title", "");
  // Sections in dependency order: the geometry fixes the dimension of every
  // vector; materials come before the parts that name them; sets exist only
  // once the mesh is built.
  auto run = root.table("run");
  if (!run) throw InputError(root.where("run"), "the case needs a [run] section with at least end_time");
  case_detail::read_run(*run, model);
  if (auto output = root.table("output")) case_detail::read_output(*output, model);
  if (auto checkpoint = root.table("checkpoint")) case_detail::read_checkpoint(*checkpoint, model);
  if (auto materials = root.table("materials")) case_detail::read_materials(*materials, model);
  case_detail::read_parts(root, model, file.parent_path());
  case_detail::read_bars(root, model);
  if (auto sph = root.table("sph")) case_detail::read_sph(*sph, model);
  case_detail::read_boundaries(root, model);
  case_detail::read_slide_surfaces(root, model);  // detaches parts: after the meshes and their sets
  case_detail::read_contacts(root, model);
  case_detail::read_gauges(root, model);
  case_detail::read_detonations(root, model);
  root.finish();
  case_detail::check_model(model);
  return model;
}

}  // namespace

Model read_case_text(const std::string& text, const std::filesystem::path& file) {
  toml::table doc;
  try {
    doc = toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    SourceLocation w;
    w.file = file.string();
    w.line = static_cast<int>(e.source().begin.line);
    w.column = static_cast<int>(e.source().begin.column);
    throw InputError(w, fmt::format("malformed TOML: {}", e.description()));
  }
  return build(doc, file);
}

Model read_case(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{file.string(), 0, 0, ""}, "cannot open the case file");
  std::stringstream text;
  text << in.rdbuf();
  return read_case_text(text.str(), file);
}

std::string describe_model(const Model& model) {
  std::string s;
  auto out = std::back_inserter(s);
  if (!model.title.empty()) fmt::format_to(out, "{}\n", model.title);
  fmt::format_to(out, "geometry {}, end time {:g} s, CFL {:g}\n", to_string(model.run.mode),
                 model.run.end_time, model.run.cfl);
  fmt::format_to(out, "{} material(s):", model.materials.size());
  for (const auto& m : model.materials) {
    fmt::format_to(out, " {} ({}", m.name, m.material->eos().type());
    if (m.material->strength()) fmt::format_to(out, ", {}", m.material->strength()->type());
    if (m.material->damage()) fmt::format_to(out, ", {}", m.material->damage()->type());
    fmt::format_to(out, ", {:g} kg/m^3)", m.material->reference_density());
  }
  s += '\n';
  std::vector<std::size_t> per_part(model.parts.size(), 0);
  for (const int p : model.mesh.element_part) ++per_part[static_cast<std::size_t>(p)];
  fmt::format_to(out, "{} part(s), {} nodes, {} elements:", model.parts.size(), model.mesh.node_count(),
                 model.mesh.element_count());
  for (std::size_t p = 0; p < model.parts.size(); ++p)
    fmt::format_to(out, " {} ({} elements of {})", model.parts[p].name, per_part[p],
                   model.materials[static_cast<std::size_t>(model.parts[p].material)].name);
  s += '\n';
  std::size_t gauges = 0;
  for (const auto& g : model.gauges) gauges += g.points.size();
  fmt::format_to(out,
                 "{} boundary condition(s), {} gauge group(s) with {} gauge(s), {} detonation point(s)\n",
                 model.boundaries.size(), model.gauges.size(), gauges, model.detonations.size());
  for (const SlideSurface& slide : model.slide_surfaces) {
    fmt::format_to(out, "slide surface:");
    for (const int p : slide.parts) fmt::format_to(out, " {}", model.parts[static_cast<std::size_t>(p)].name);
    fmt::format_to(out, " detached from the other FEM parts along {} faces, friction {:g}, penalty scale {:g}\n",
                   slide.elements_a.size(), slide.friction, slide.penalty_scale);
  }
  return s;
}

}  // namespace camouflet
