// [[slide_surfaces]]: FEM parts detached from the rest of the mesh along the faces they share
// with it, the two sides meeting through a penalty contact with Coulomb friction
// (coupling/slide_surface.hpp, mesh/detach_parts.hpp; docs/case-format.md "Slide surfaces").
#include <fmt/format.h>

#include "case/sections.hpp"
#include "mesh/detach_parts.hpp"

namespace camouflet::case_detail {

void read_slide_surfaces(TomlReader& root, Model& model) {
  std::vector<DetachedInterface> detached_all;
  for (auto& t : root.tables("slide_surfaces")) {
    SlideSurface surface;
    surface.where = t.where();
    std::vector<std::string> fem_parts;
    for (const Part& p : model.parts)
      if (p.kind == PartKind::fem) fem_parts.push_back(p.name);
    std::vector<char> in_group(model.parts.size(), 0);
    for (const std::string& name : name_list(t, "parts")) {
      int index = -1;
      for (std::size_t k = 0; k < model.parts.size(); ++k)
        if (model.parts[k].name == name) index = static_cast<int>(k);
      if (index < 0) {
        const std::string guess = nearest(name, fem_parts);
        t.fail("parts", guess.empty()
                            ? fmt::format("no FEM part '{}' is defined", name)
                            : fmt::format("no FEM part '{}' is defined; did you mean '{}'?", name, guess));
      }
      if (model.parts[static_cast<std::size_t>(index)].kind != PartKind::fem)
        t.fail("parts",
               fmt::format("part '{}' is an SPH part: a slide surface detaches FEM parts (an SPH part "
                           "slides on FEM faces through [[contacts]])",
                           name));
      in_group[static_cast<std::size_t>(index)] = 1;
      surface.parts.push_back(index);
    }
    surface.friction = t.non_negative("friction", 0.0);
    surface.penalty_scale = t.positive("penalty_scale", 0.3);
    const double limit = 2.0 * (1.0 - model.run.cfl * model.run.cfl);
    if (!(surface.penalty_scale < limit))
      t.fail("penalty_scale",
             fmt::format("{} is too stiff at cfl {}: the contact is stable below 2 (1 - cfl^2) = {:.3g} "
                         "(coupling/slide_surface.hpp)",
                         surface.penalty_scale, model.run.cfl, limit));
    t.finish();
    DetachedInterface detached = detach_parts(model.mesh, in_group);
    if (detached.a.empty())
      t.fail("parts",
             "these parts share no face with the other FEM parts: there is nothing for them to slide on");
    for (const ElementFace& f : detached.a) surface.elements_a.push_back(f.element);
    for (const ElementFace& f : detached.b) surface.elements_b.push_back(f.element);
    detached_all.push_back(std::move(detached));
    model.slide_surfaces.push_back(std::move(surface));
  }
  // The faces' nodes once every surface is detached (a later one may have doubled an earlier one's nodes).
  for (std::size_t k = 0; k < detached_all.size(); ++k) {
    model.slide_surfaces[k].faces_a = element_face_nodes(model.mesh, detached_all[k].a);
    model.slide_surfaces[k].faces_b = element_face_nodes(model.mesh, detached_all[k].b);
  }
}

}  // namespace camouflet::case_detail
