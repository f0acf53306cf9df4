#include "materials/material_points.hpp"

#include <cmath>
#include <stdexcept>

namespace camouflet {

std::size_t History::add(const std::string& name, double initial_value) {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return i;
  names_.push_back(name);
  initial_.push_back(initial_value);
  columns_.emplace_back(columns_.empty() ? 0 : columns_.front().size(), initial_value);
  return names_.size() - 1;
}

std::size_t History::slot(const std::string& name) const {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return i;
  throw std::out_of_range("material history field '" + name + "' is not registered");
}

bool History::contains(const std::string& name) const {
  for (const auto& n : names_)
    if (n == name) return true;
  return false;
}

void History::resize(std::size_t n) {
  for (std::size_t i = 0; i < columns_.size(); ++i) columns_[i].resize(n, initial_[i]);
}

void MaterialPoints::resize(std::size_t n) {
  density.resize(n, 0.0);
  density_previous.resize(n, 0.0);
  strain_rate.resize(n);
  spin.resize(n);
  artificial_viscosity.resize(n, 0.0);
  characteristic_length.resize(n, 0.0);
  specific_energy.resize(n, 0.0);
  pressure.resize(n, 0.0);
  deviator.resize(n);
  sound_speed.resize(n, 0.0);
  stable_sound_speed.resize(n, 0.0);
  shear_modulus.resize(n, 0.0);
  plastic_strain.resize(n, 0.0);
  plastic_strain_rate.resize(n, 0.0);
  damage.resize(n, 0.0);
  temperature.resize(n, 0.0);
  specific_energy_start.resize(n, 0.0);
  pressure_start.resize(n, 0.0);
  history.resize(n);
}

}  // namespace camouflet
