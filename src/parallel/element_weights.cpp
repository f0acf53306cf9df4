#include "parallel/element_weights.hpp"

#include <cmath>
#include <string>

namespace camouflet {

double relative_cost(const Material& material) {
  // CPU time per element-cycle of a 21k-hex block hit at 10 m/s, one thread, medians of three
  // alternated runs (058815e, 7 Dec 2026, beside a build): elastic 234 ns, steel_1006_wang2005
  // (linear + johnson_cook) 270, sandy_clay_wang2005 (three_phase_soil + soil_drucker_prager +
  // its bond damage) 387, concrete_35mpa_wang2005 (p_alpha + rht) 1343. Each extra is carried by
  // the strength model its presets pair it with.
  double cost = 1.0;
  if (const StrengthModel* strength = material.strength()) {
    const std::string type = strength->type();
    if (type == "johnson_cook") cost += 0.15;
    if (type == "soil_drucker_prager") cost += 0.65;
    if (type == "rht") cost += 4.7;
  }
  return cost;
}

std::vector<int> element_weights(const Model& model) {
  std::vector<int> per_part(model.parts.size(), 10);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const int m = model.parts[p].material;
    if (m >= 0 && static_cast<std::size_t>(m) < model.materials.size())
      per_part[p] = static_cast<int>(std::lround(10.0 * relative_cost(*model.materials[static_cast<std::size_t>(m)].material)));
  }
  std::vector<int> weights(model.mesh.element_count());
  for (std::size_t e = 0; e < weights.size(); ++e) weights[e] = per_part[static_cast<std::size_t>(model.mesh.element_part[e])];
  return weights;
}

}  // namespace camouflet
