#include "materials/linear_eos.hpp"

#include <cmath>

#include "materials/registry.hpp"

namespace camouflet {

LinearEos::LinearEos(double reference_density, double bulk_modulus)
    : rho0_(reference_density), bulk_(bulk_modulus) {}

void LinearEos::evaluate(MaterialPoints& pts, const MaterialContext&, bool) const {
  // Bulk sound speed sqrt(dp/drho) = sqrt(K / rho0), constant for this law.
  const double c = std::sqrt(bulk_ / rho0_);
  const std::size_t n = pts.size();
#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
  for (std::size_t i = 0; i < n; ++i) {
    pts.pressure[i] = bulk_ * (pts.density[i] / rho0_ - 1.0);
    pts.sound_speed[i] = c;
  }
}

namespace {
std::shared_ptr<const EquationOfState> make_linear_eos(Parameters& p) {
  const double rho0 = p.positive("density");
  const double k = p.positive("bulk_modulus");
  return std::make_shared<const LinearEos>(rho0, k);
}
}  // namespace

CAMOUFLET_REGISTER_EOS("linear", make_linear_eos);

}  // namespace camouflet
