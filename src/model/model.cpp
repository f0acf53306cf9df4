#include "model/model.hpp"

#include <algorithm>

namespace camouflet {

const char* to_string(GeometryMode mode) {
  switch (mode) {
    case GeometryMode::plane_strain: return "plane_strain";
    case GeometryMode::axisymmetric: return "axisymmetric";
    case GeometryMode::three_d: return "3d";
  }
  return "?";
}

double TimeHistory::at(double t) const {
  if (time.empty()) return 1.0;
  if (t <= time.front()) return value.front();
  if (t >= time.back()) return value.back();
  const auto it = std::upper_bound(time.begin(), time.end(), t);
  const std::size_t j = static_cast<std::size_t>(it - time.begin());
  const double w = (t - time[j - 1]) / (time[j] - time[j - 1]);
  return (1.0 - w) * value[j - 1] + w * value[j];
}

}  // namespace camouflet
