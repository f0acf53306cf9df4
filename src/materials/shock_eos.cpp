// Shock (Mie-Grueneisen) equation of state with a linear shock-velocity fit
// Us = c0 + s up, referenced to the principal Hugoniot (Autodyn "Shock" EOS;
// LS-DYNA *EOS_GRUNEISEN; Meyers, "Dynamic Behavior of Materials", 1994, ch. 4):
//   eta = 1 - rho0 / rho = mu / (1 + mu),   mu = rho / rho0 - 1
//   compression: p = p_H + Gamma rho0 (e - e_H),
//                p_H = rho0 c0^2 eta / (1 - s eta)^2 = rho0 c0^2 mu (1 + mu) / (1 - (s - 1) mu)^2,
//                e_H = p_H eta / (2 rho0)        (Rankine-Hugoniot energy from p = 0, e = 0)
//   tension:     p = rho0 c0^2 mu + Gamma rho0 e  (LS-DYNA's form)
// with Gamma rho = (gamma0 + a mu) rho0: a = 0 is the usual Gamma rho = const,
// a != 0 LS-DYNA's first-order volume correction.
// Keys: density (kg/m^3), c0 (m/s), s, gamma0, a (default 0), specific_energy
// (J/kg, initial, default 0). Compression beyond the Hugoniot's limit
// eta = 1/s is a NumericalError naming the point.
#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"
#include "materials/registry.hpp"

namespace camouflet {

namespace {

struct ShockParameters {
  double density, c0, s, gamma0, a, e0;
};

class ShockEos : public EquationOfState {
 public:
  explicit ShockEos(const ShockParameters& p) : p_(p) {}
  std::string type() const override { return "shock"; }
  double reference_density() const override { return p_.density; }
  double reference_specific_energy() const override { return p_.e0; }

  void evaluate(MaterialPoints& pts, const MaterialContext&, bool) const override {
    const std::size_t n = pts.size();
    const double rho0 = p_.density;
    const double k0 = rho0 * p_.c0 * p_.c0;  // Pa, bulk modulus at the reference state
    long failed = -1;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double rho = pts.density[i];
      const double e = pts.specific_energy[i];
      const double mu = rho / rho0 - 1.0;
      const double gamma_rho0 = (p_.gamma0 + p_.a * mu) * rho0;  // Gamma rho, Pa kg/J
      double p, dp_dmu;
      if (mu >= 0.0) {
        const double eta = mu / (1.0 + mu);
        const double denom = 1.0 - p_.s * eta;
        if (!(denom > 0.0)) {
#pragma omp atomic write
          failed = static_cast<long>(i);
          continue;
        }
        const double p_h = k0 * eta / (denom * denom);
        const double e_h = p_h * eta / (2.0 * rho0);
        const double dph_deta = k0 * (1.0 + p_.s * eta) / (denom * denom * denom);
        const double deh_deta = (dph_deta * eta + p_h) / (2.0 * rho0);
        const double deta_dmu = 1.0 / ((1.0 + mu) * (1.0 + mu));
        p = p_h + gamma_rho0 * (e - e_h);
        dp_dmu = (dph_deta - gamma_rho0 * deh_deta) * deta_dmu + p_.a * rho0 * (e - e_h);
      } else {
        p = k0 * mu + gamma_rho0 * e;
        dp_dmu = k0 + p_.a * rho0 * e;
      }
      pts.pressure[i] = p;
      // Isentropic c^2 = dp/drho|_e + (p / rho^2) dp/de|_rho.
      double c2 = dp_dmu / rho0 + p / (rho * rho) * gamma_rho0;
      if (!(c2 > 0.0)) c2 = p_.c0 * p_.c0;  // deep tension: keep the time step bounded
      pts.sound_speed[i] = std::sqrt(c2);
    }
    if (failed >= 0)
      throw NumericalError(
          EntityKind::material_point, failed, "density",
          fmt::format("density {:.6g} kg/m^3 is beyond the shock EOS limit rho0 s / (s - 1) = "
                      "{:.6g} kg/m^3",
                      pts.density[static_cast<std::size_t>(failed)],
                      p_.s > 1.0 ? p_.density * p_.s / (p_.s - 1.0) : INFINITY));
  }

 private:
  ShockParameters p_;
};

std::shared_ptr<const EquationOfState> make_shock(Parameters& params) {
  ShockParameters p{};
  p.density = params.positive("density");
  p.c0 = params.positive("c0");
  p.s = params.number("s");
  if (p.s < 0.0) params.fail("s", "the Us-up slope must not be negative");
  p.gamma0 = params.number("gamma0");
  if (p.gamma0 < 0.0) params.fail("gamma0", "the Grueneisen coefficient must not be negative");
  p.a = params.number("a", 0.0);
  p.e0 = params.number("specific_energy", 0.0);
  return std::make_shared<ShockEos>(p);
}

}  // namespace

CAMOUFLET_REGISTER_EOS("shock", make_shock);

}  // namespace camouflet
