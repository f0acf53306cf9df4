#pragma once
// Structure-of-arrays state of every point of one material: FEM integration
// points and SPH particles alike (architecture.md, "one material code path").
// The kinematics layer (fem/ or sph/) writes density, strain rate, spin,
// artificial viscosity and characteristic length; the material update writes
// the rest. Model-specific per-point variables live in `history`, registered
// by name by the EOS / strength / damage components (style.md #5).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "core/sym_tensor.hpp"

namespace camouflet {

// Named extra per-point columns (compaction state, burn fraction, ...).
class History {
 public:
  // Registers a column (idempotent by name) and returns its slot.
  std::size_t add(const std::string& name, double initial_value);
  // Slot of a registered column; throws std::out_of_range naming it when absent.
  std::size_t slot(const std::string& name) const;
  bool contains(const std::string& name) const;
  double* column(std::size_t slot) { return columns_[slot].data(); }
  const double* column(std::size_t slot) const { return columns_[slot].data(); }
  const std::vector<std::string>& names() const { return names_; }
  void resize(std::size_t n);

 private:
  std::vector<std::string> names_;
  std::vector<double> initial_;
  std::vector<std::vector<double>> columns_;
};

struct MaterialPoints {
  std::size_t size() const { return density.size(); }
  void resize(std::size_t n);

  // --- written by the kinematics (FEM element or SPH particle) every cycle ---
  std::vector<double> density;                // kg/m^3, at the end of the step
  std::vector<double> density_previous;       // kg/m^3, at the start of the step
  std::vector<SymTensor> strain_rate;         // 1/s, D = sym(grad v) at mid-step
  std::vector<Spin> spin;                     // 1/s, W = skew(grad v)
  std::vector<double> artificial_viscosity;   // Pa, bulk viscosity q (compression positive)
  std::vector<double> characteristic_length;  // m, element size or smoothing length

  // --- state written by the material update ---
  std::vector<double> specific_energy;      // J/kg, internal energy per unit mass
  std::vector<double> pressure;             // Pa, compression positive
  std::vector<SymTensor> deviator;          // Pa, deviatoric stress s; sigma = s - p I
  std::vector<double> sound_speed;          // m/s, bulk sound speed from the EOS
  // m/s, bulk sound speed of the stiffest branch the next step can meet,
  // where the EOS knows one stiffer than sound_speed (0 otherwise): the time
  // step votes with it, the artificial viscosities and dashpots keep
  // sound_speed. The three-phase soil's release on the grains alone.
  std::vector<double> stable_sound_speed;
  std::vector<double> shear_modulus;        // Pa, current shear modulus (0 for fluids)
  std::vector<double> plastic_strain;       // effective (equivalent) plastic strain
  std::vector<double> plastic_strain_rate;  // 1/s
  std::vector<double> damage;               // 0 intact .. 1 fully damaged
  std::vector<double> temperature;          // K

  // Scratch used by the energy equation inside one update (not state).
  std::vector<double> specific_energy_start;
  std::vector<double> pressure_start;

  History history;

  // Longitudinal wave speed used by the viscosity: sqrt(c^2 + 4G/(3 rho)).
  double wave_speed(std::size_t i) const;
  // The same with the stable sound speed where it is the larger: the time step's.
  double stable_wave_speed(std::size_t i) const;
};

// Inline: the solver gathers them for every element each cycle.
// sqrt(c^2 + 4G/(3 rho)) for a bulk sound speed c at point i.
inline double longitudinal_wave_speed(const MaterialPoints& pts, std::size_t i, double c) {
  const double g = pts.density[i] > 0.0 ? 4.0 * pts.shear_modulus[i] / (3.0 * pts.density[i]) : 0.0;
  return std::sqrt(c * c + g);
}

inline double MaterialPoints::wave_speed(std::size_t i) const {
  return longitudinal_wave_speed(*this, i, sound_speed[i]);
}

inline double MaterialPoints::stable_wave_speed(std::size_t i) const {
  return longitudinal_wave_speed(*this, i, std::max(sound_speed[i], stable_sound_speed[i]));
}

}  // namespace camouflet
