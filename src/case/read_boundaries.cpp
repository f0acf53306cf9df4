// [[boundary]]: conditions on named node or face sets (docs/case-format.md).
#include <fmt/format.h>

#include <cmath>

#include "case/sections.hpp"

namespace camouflet::case_detail {

namespace {

const std::vector<std::string> kinds{"fixed", "velocity", "symmetry", "axis", "pressure", "transmitting"};

BoundaryKind kind_of(const std::string& s) {
  if (s == "velocity") return BoundaryKind::velocity;
  if (s == "symmetry") return BoundaryKind::symmetry;
  if (s == "axis") return BoundaryKind::axis;
  if (s == "pressure") return BoundaryKind::pressure;
  if (s == "transmitting") return BoundaryKind::transmitting;
  return BoundaryKind::fixed;
}

bool on_faces(BoundaryKind k) {
  return k == BoundaryKind::pressure || k == BoundaryKind::transmitting;
}

void check_set(TomlReader& b, const Model& model, const std::string& set, bool faces) {
  const auto& sets = faces ? model.mesh.face_sets : model.mesh.node_sets;
  if (sets.count(set)) return;
  // "part.face" of an SPH part: particles have no element faces to carry a
  // dashpot or a load, and no transmitting formulation exists for an SPH
  // edge (docs/theory/coupling.md); say so rather than "no such set".
  const std::string part = set.substr(0, set.find('.'));
  for (const Part& p : model.parts)
    if (p.kind == PartKind::sph && p.name == part)
      b.fail("set", fmt::format("part '{}' is an SPH part: {} boundary acts on FEM faces or nodes only (an "
                                "SPH edge has no transmitting formulation; join the zone to FEM parts "
                                "and put the boundary on their faces)",
                                part, faces ? "a face" : "a node"));
  std::vector<std::string> names;
  for (const auto& [name, members] : sets) names.push_back(name);
  const std::string guess = nearest(set, names);
  const char* what = faces ? "face set" : "node set";
  b.fail("set", guess.empty() ? fmt::format("no {} named '{}' (the mesh has: {})", what, set,
                                            names.empty() ? std::string("none")
                                                          : fmt::format("{}", fmt::join(names, ", ")))
                              : fmt::format("no {} named '{}'; did you mean '{}'?", what, set, guess));
}

TimeHistory read_history(TomlReader& b) {
  const toml::array* rows = b.array("history");
  TimeHistory h;
  for (const auto& row : *rows) {
    const toml::array* pair = row.as_array();
    std::optional<double> t, v;
    if (pair && pair->size() == 2) {
      t = as_number((*pair)[0]);
      v = as_number((*pair)[1]);
    }
    if (!t || !v || !std::isfinite(*t) || !std::isfinite(*v))
      b.fail("history", "expected a list of [time_s, value] pairs");
    if (!h.time.empty() && !(*t > h.time.back()))
      b.fail("history", fmt::format("times must increase; {} s follows {} s", *t, h.time.back()));
    h.time.push_back(*t);
    h.value.push_back(*v);
  }
  if (h.time.empty()) b.fail("history", "needs at least one [time_s, value] pair");
  return h;
}

}  // namespace

void read_boundaries(TomlReader& root, Model& model) {
  const int dim = model.dimension();
  for (auto& b : root.tables("boundary")) {
    BoundaryCondition bc;
    bc.where = b.where();
    bc.kind = kind_of(b.choice("type", kinds, ""));
    bc.set = b.string("set");
    check_set(b, model, bc.set, on_faces(bc.kind));
    switch (bc.kind) {
      case BoundaryKind::fixed:
      case BoundaryKind::transmitting:
        break;
      case BoundaryKind::velocity: {
        std::vector<std::string> components;
        if (const toml::array* c = b.array("components")) {
          for (const auto& item : *c) {
            const auto* s = item.as_string();
            if (!s) b.fail("components", "expected a list of axis names such as [\"x\", \"y\"]");
            components.push_back(s->get());
          }
        } else {
          for (int i = 0; i < dim; ++i) components.emplace_back(1, "xyz"[i]);
        }
        const auto value = b.numbers("value");
        if (value.size() != components.size())
          b.fail("value", fmt::format("expected {} velocities (m/s), one per component, got {}",
                                      components.size(), value.size()));
        for (std::size_t k = 0; k < components.size(); ++k) {
          const std::string& c = components[k];
          const int axis = c == "x" ? 0 : c == "y" ? 1 : c == "z" ? 2 : -1;
          if (axis < 0 || axis >= dim)
            b.fail("components", fmt::format("'{}' is not an axis of a {}-D model", c, dim));
          if (bc.components[static_cast<std::size_t>(axis)])
            b.fail("components", fmt::format("'{}' given twice", c));
          bc.components[static_cast<std::size_t>(axis)] = true;
          bc.value[static_cast<std::size_t>(axis)] = value[k];
        }
        break;
      }
      case BoundaryKind::symmetry: {
        bc.normal = b.vector("normal", dim);
        const double n = std::sqrt(bc.normal[0] * bc.normal[0] + bc.normal[1] * bc.normal[1] +
                                   bc.normal[2] * bc.normal[2]);
        if (!(n > 0.0)) b.fail("normal", "must not be the zero vector");
        for (double& c : bc.normal) c /= n;
        break;
      }
      case BoundaryKind::axis:
        if (model.run.mode != GeometryMode::axisymmetric)
          b.fail("type", "an axis boundary needs [run] geometry = \"axisymmetric\"");
        break;
      case BoundaryKind::pressure:
        bc.value[0] = b.number("value");
        break;
    }
    if (b.has("history")) {
      if (bc.kind != BoundaryKind::velocity && bc.kind != BoundaryKind::pressure)
        b.fail("history", "only velocity and pressure boundaries take a history");
      bc.history = read_history(b);
    }
    b.finish();
    model.boundaries.push_back(std::move(bc));
  }
}

}  // namespace camouflet::case_detail
