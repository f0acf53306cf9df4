#include "materials/material_points_state.hpp"

#include <stdexcept>

namespace camouflet {

void visit_state(StateVisitor& v, MaterialPoints& p) {
  visit(v, "density", p.density);
  visit(v, "density_previous", p.density_previous);
  visit(v, "strain_rate", p.strain_rate);
  visit(v, "spin", p.spin);
  visit(v, "artificial_viscosity", p.artificial_viscosity);
  visit(v, "characteristic_length", p.characteristic_length);
  visit(v, "specific_energy", p.specific_energy);
  visit(v, "pressure", p.pressure);
  visit(v, "deviator", p.deviator);
  visit(v, "sound_speed", p.sound_speed);
  visit(v, "stable_sound_speed", p.stable_sound_speed);
  visit(v, "shear_modulus", p.shear_modulus);
  visit(v, "plastic_strain", p.plastic_strain);
  visit(v, "plastic_strain_rate", p.plastic_strain_rate);
  visit(v, "damage", p.damage);
  visit(v, "temperature", p.temperature);
  visit(v, "specific_energy_start", p.specific_energy_start);
  visit(v, "pressure_start", p.pressure_start);
  // History columns are owned by the History (sized with the batch): fill them in place.
  const std::size_t n = p.size();
  for (const std::string& name : p.history.names()) {
    double* column = p.history.column(p.history.slot(name));
    const std::string full = v.qualified("history." + name);
    v.array(full, StateType::f64, 1, n, column, [column, n, full](std::size_t count) -> void* {
      if (count != n)
        throw std::runtime_error("checkpoint: history column '" + full + "' has " + std::to_string(count) +
                                 " points, the model " + std::to_string(n));
      return column;
    });
  }
}

}  // namespace camouflet
