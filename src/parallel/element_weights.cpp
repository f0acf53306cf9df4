#include "parallel/element_weights.hpp"

#include <cmath>
#include <string>

namespace camouflet {

double relative_cost(const Material& material) {
  // Time per element-cycle of a 21k-hex block hit at 10 m/s, one thread, on an idle 2-vCPU host,
  // medians of alternated runs (7 Dec 2026, bench/grind_time --preset): elastic 229.5 ns,
  // steel_1006_wang2005 (linear + johnson_cook) 310.9, sandy_clay_wang2005 (three_phase_soil +
  // soil_drucker_prager + its bond damage) 407.5, concrete_35mpa_wang2005 (p_alpha + rht) 1345.3.
  // Each extra is carried by the strength model its presets pair it with.
  double cost = 1.0;
  if (const StrengthModel* strength = material.strength()) {
    const std::string type = strength->type();
    if (type == "johnson_cook") cost += 0.35;
    if (type == "soil_drucker_prager") cost += 0.78;
    if (type == "rht") cost += 4.86;
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
