// [[contacts]]: sliding interfaces between the particles of an SPH part and a
// set of FEM faces (Wang et al. 2005, section 3.3, the second coupling option;
// coupling/sliding_contact.hpp; docs/case-format.md "Sliding contacts").
#include <fmt/format.h>

#include "case/sections.hpp"

namespace camouflet::case_detail {

void read_contacts(TomlReader& root, Model& model) {
  for (auto& c : root.tables("contacts")) {
    Contact contact;
    contact.where = c.where();
    const std::string part = c.string("part");
    std::vector<std::string> sph_parts;
    for (std::size_t k = 0; k < model.parts.size(); ++k) {
      if (model.parts[k].kind != PartKind::sph) continue;
      sph_parts.push_back(model.parts[k].name);
      if (model.parts[k].name == part) contact.sph_part = static_cast<int>(k);
    }
    if (contact.sph_part < 0) {
      bool fem = false;
      for (const Part& p : model.parts) fem = fem || p.name == part;
      const std::string guess = nearest(part, sph_parts);
      c.fail("part", fem ? fmt::format("part '{}' is a FEM part: the particle side of a sliding contact is "
                                       "an SPH part (a FEM-FEM interface shares nodes instead)",
                                       part)
                     : guess.empty()
                         ? fmt::format("no SPH part '{}' is defined", part)
                         : fmt::format("no SPH part '{}' is defined; did you mean '{}'?", part, guess));
    }
    contact.face_set = c.string("set");
    if (!model.mesh.face_sets.count(contact.face_set)) {
      std::vector<std::string> names;
      for (const auto& [name, faces] : model.mesh.face_sets) names.push_back(name);
      const std::string guess = nearest(contact.face_set, names);
      c.fail("set", guess.empty()
                        ? fmt::format("no face set named '{}'", contact.face_set)
                        : fmt::format("no face set named '{}'; did you mean '{}'?", contact.face_set, guess));
    }
    if (model.mesh.face_sets.at(contact.face_set).empty())
      c.fail("set", fmt::format("face set '{}' has no face left (a joined SPH zone may have cut them)",
                                contact.face_set));
    contact.friction = c.non_negative("friction", 0.0);
    contact.penalty_scale = c.positive("penalty_scale", 0.1);
    if (!(contact.penalty_scale < 4.0))
      c.fail(
          "penalty_scale",
          fmt::format("{} is too stiff: the contact spring is stable below 4 (coupling/sliding_contact.hpp)",
                      contact.penalty_scale));
    c.finish();
    model.contacts.push_back(std::move(contact));
  }
}

}  // namespace camouflet::case_detail
