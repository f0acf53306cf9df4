#include "materials/programmed_burn.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camouflet {

double lighting_time(const std::array<double, 3>& position, const std::vector<DetonationPoint>& detonations,
                     double detonation_velocity) {
  double t = std::numeric_limits<double>::infinity();
  for (const DetonationPoint& d : detonations) {
    const double dx = position[0] - d.position[0];
    const double dy = position[1] - d.position[1];
    const double dz = position[2] - d.position[2];
    t = std::min(t, d.time + std::sqrt(dx * dx + dy * dy + dz * dz) / detonation_velocity);
  }
  return t;
}

double burn_fraction(double time, double lighting_time, double detonation_velocity, double burn_width_factor,
                     double characteristic_length) {
  if (!(time >= lighting_time)) return 0.0;  // also when never lit (infinite lighting time)
  const double width = burn_width_factor * characteristic_length;
  if (!(width > 0.0)) return 1.0;
  return std::min(1.0, (time - lighting_time) * detonation_velocity / width);
}

double volume_burn_fraction(double relative_volume, double cj_relative_volume) {
  if (!(relative_volume < 1.0)) return 0.0;
  return std::min(1.0, (1.0 - relative_volume) / (1.0 - cj_relative_volume));
}

}  // namespace camouflet
