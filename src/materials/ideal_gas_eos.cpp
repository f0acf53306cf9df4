// Ideal gas with constant ratio of specific heats: p = (gamma - 1) rho e,
// c^2 = gamma p / rho. Keys: density (kg/m^3, reference), gamma (> 1),
// specific_energy (J/kg, initial, default 0).
#include <algorithm>
#include <cmath>

#include "materials/registry.hpp"

namespace camouflet {

namespace {

class IdealGasEos : public EquationOfState {
 public:
  IdealGasEos(double density, double gamma, double e0) : density_(density), gamma_(gamma), e0_(e0) {}
  std::string type() const override { return "ideal_gas"; }
  double reference_density() const override { return density_; }
  double reference_specific_energy() const override { return e0_; }

  void evaluate(MaterialPoints& pts, const MaterialContext&, bool) const override {
    const std::size_t n = pts.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double e = pts.specific_energy[i];
      pts.pressure[i] = (gamma_ - 1.0) * pts.density[i] * e;
      // c^2 = dp/drho|_e + p/rho^2 dp/de = gamma (gamma - 1) e; a gas that has
      // lost all its energy has no sound speed left (not negative).
      pts.sound_speed[i] = std::sqrt(std::max(0.0, gamma_ * (gamma_ - 1.0) * e));
    }
  }

 private:
  double density_, gamma_, e0_;
};

std::shared_ptr<const EquationOfState> make_ideal_gas(Parameters& p) {
  const double density = p.positive("density");
  const double gamma = p.number("gamma");
  if (!(gamma > 1.0)) p.fail("gamma", "the ratio of specific heats must exceed 1");
  const double e0 = p.non_negative("specific_energy", 0.0);
  return std::make_shared<IdealGasEos>(density, gamma, e0);
}

}  // namespace

CAMOUFLET_REGISTER_EOS("ideal_gas", make_ideal_gas);

}  // namespace camouflet
