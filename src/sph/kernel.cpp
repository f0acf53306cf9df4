#include "sph/kernel.hpp"

#include <stdexcept>

namespace camouflet::sph {

KernelKind kernel_from_name(const std::string& name) {
  if (name == "cubic_spline") return KernelKind::cubic_spline;
  if (name == "wendland_c2") return KernelKind::wendland_c2;
  throw std::invalid_argument("unknown SPH kernel '" + name + "' (cubic_spline, wendland_c2)");
}

const char* to_string(KernelKind kind) {
  return kind == KernelKind::cubic_spline ? "cubic_spline" : "wendland_c2";
}

}  // namespace camouflet::sph
