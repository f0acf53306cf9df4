// Polynomial equation of state, Autodyn form (Autodyn Theory Manual, "Polynomial
// EOS"; used by the seed paper for concrete, Table 3):
//   mu = rho / rho0 - 1
//   mu >= 0: p = A1 mu + A2 mu^2 + A3 mu^3 + (B0 + B1 mu) rho0 e
//   mu <  0: p = T1 mu + T2 mu^2 + B0 rho0 e
// Keys: density (kg/m^3), a1, a2, a3, t1, t2 (Pa; t1 defaults to a1 and t2 to 0
// as in Autodyn), b0, b1 (-), specific_energy (J/kg, initial, default 0).
// There is no tension cut-off here: tensile failure belongs to the strength
// and damage models.
#include <cmath>

#include "materials/registry.hpp"

namespace camouflet {

namespace {

struct PolynomialCoefficients {
  double density, a1, a2, a3, t1, t2, b0, b1, e0;
};

class PolynomialEos : public EquationOfState {
 public:
  explicit PolynomialEos(const PolynomialCoefficients& c) : c_(c) {}
  std::string type() const override { return "polynomial"; }
  double reference_density() const override { return c_.density; }
  double reference_specific_energy() const override { return c_.e0; }

  void evaluate(MaterialPoints& pts, const MaterialContext&, bool) const override {
    const std::size_t n = pts.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double rho = pts.density[i];
      const double e = pts.specific_energy[i];
      const double mu = rho / c_.density - 1.0;
      double p, dp_dmu, dp_de;
      if (mu >= 0.0) {
        p = mu * (c_.a1 + mu * (c_.a2 + mu * c_.a3)) + (c_.b0 + c_.b1 * mu) * c_.density * e;
        dp_dmu = c_.a1 + mu * (2.0 * c_.a2 + 3.0 * c_.a3 * mu) + c_.b1 * c_.density * e;
        dp_de = (c_.b0 + c_.b1 * mu) * c_.density;
      } else {
        p = mu * (c_.t1 + c_.t2 * mu) + c_.b0 * c_.density * e;
        dp_dmu = c_.t1 + 2.0 * c_.t2 * mu;
        dp_de = c_.b0 * c_.density;
      }
      pts.pressure[i] = p;
      // Isentropic c^2 = dp/drho|_e + (p / rho^2) dp/de|_rho, with dmu/drho = 1/rho0.
      double c2 = dp_dmu / c_.density + p / (rho * rho) * dp_de;
      // Where the analytic derivative is not positive (deep tension with T2 < 0)
      // the reference bulk sound speed keeps the time step bounded.
      if (!(c2 > 0.0)) c2 = c_.a1 / c_.density;
      pts.sound_speed[i] = std::sqrt(c2);
    }
  }

 private:
  PolynomialCoefficients c_;
};

std::shared_ptr<const EquationOfState> make_polynomial(Parameters& p) {
  PolynomialCoefficients c{};
  c.density = p.positive("density");
  c.a1 = p.positive("a1");
  c.a2 = p.number("a2", 0.0);
  c.a3 = p.number("a3", 0.0);
  c.t1 = p.positive("t1", c.a1);
  c.t2 = p.number("t2", 0.0);
  c.b0 = p.number("b0", 0.0);
  c.b1 = p.number("b1", 0.0);
  c.e0 = p.number("specific_energy", 0.0);
  return std::make_shared<PolynomialEos>(c);
}

}  // namespace

CAMOUFLET_REGISTER_EOS("polynomial", make_polynomial);

}  // namespace camouflet
