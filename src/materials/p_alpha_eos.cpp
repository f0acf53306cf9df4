#include "materials/p_alpha_eos.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "materials/bracketed_root.hpp"
#include "materials/registry.hpp"

namespace camouflet {

namespace {
const char* const kPlasticDistension = "plastic_distension";
}

PAlphaEos::PAlphaEos(const PAlphaParameters& p) : prm_(p) {
  solid_sound_speed_ = std::sqrt(prm_.a1 / prm_.solid_density);
  // The pores also close elastically below p_e (that is what makes the porous
  // sound speed c_e lower than the matrix one), so the distension at which
  // crushing starts, alpha_e, lies slightly below rho_s / rho_0: the elastic
  // branch from alpha_e must pass through the stress-free state (rho_0, p = 0).
  // alpha_e = alpha_0 exp(-kappa(alpha_e) p_e); a fixed point, converged in a few steps.
  const double alpha0 = prm_.solid_density / prm_.density;
  alpha_e_ = alpha0;
  for (int k = 0; k < 50; ++k) {
    const double c = prm_.porous_sound_speed;
    const double kappa = std::max(0.0, alpha_e_ * (1.0 / (prm_.solid_density * c * c) - 1.0 / prm_.a1));
    alpha_e_ = alpha0 * std::exp(-kappa * prm_.crush_pressure);
  }
}

void PAlphaEos::register_state(MaterialPoints& pts) const {
  pts.history.add(kPlasticDistension, alpha_e_);
}

double PAlphaEos::solid_pressure(double mu, double e) const {
  const double rho_s = prm_.solid_density;
  if (mu >= 0.0)  // Wang et al. 2005, eq. 35 (compression), Autodyn's polynomial energy term
    return mu * (prm_.a1 + mu * (prm_.a2 + mu * prm_.a3)) + (prm_.b0 + prm_.b1 * mu) * rho_s * e;
  return mu * (prm_.t1 + mu * prm_.t2) + prm_.b0 * rho_s * e;  // eq. 35 (tension)
}

double PAlphaEos::crush_distension(double p) const {
  const double pe = prm_.crush_pressure, ps = prm_.compaction_pressure;
  if (p <= pe) return alpha_e_;
  if (p >= ps) return 1.0;
  return 1.0 + (alpha_e_ - 1.0) * std::pow((ps - p) / (ps - pe), prm_.compaction_exponent);
}

double PAlphaEos::crush_pressure_of(double alpha_p) const {
  const double pe = prm_.crush_pressure, ps = prm_.compaction_pressure;
  if (alpha_p >= alpha_e_) return pe;
  if (alpha_p <= 1.0) return ps;
  return ps - (ps - pe) * std::pow((alpha_p - 1.0) / (alpha_e_ - 1.0), 1.0 / prm_.compaction_exponent);
}

double PAlphaEos::elastic_compliance(double alpha_p) const {
  // Elastic pore compliance kappa = -dln(alpha)/dp, chosen so that the porous
  // bulk modulus rho c^2 has c interpolated linearly in alpha_p between c_e
  // (alpha_e) and the matrix sound speed (alpha = 1), as Autodyn does.
  if (alpha_p <= 1.0) return 0.0;
  const double w = std::min(1.0, (alpha_p - 1.0) / (alpha_e_ - 1.0));
  const double c = solid_sound_speed_ + (prm_.porous_sound_speed - solid_sound_speed_) * w;
  return std::max(0.0, alpha_p * (1.0 / (prm_.solid_density * c * c) - 1.0 / prm_.a1));
}

double PAlphaEos::elastic_distension(double p, double alpha_p) const {
  // Reversible pore deformation about the crush point of alpha_p. It goes on
  // into tension (alpha_p itself stays fixed there), so that the bulk
  // modulus, and the sound speed, are continuous through p = 0.
  return alpha_p * std::exp(-elastic_compliance(alpha_p) * (p - crush_pressure_of(alpha_p)));
}

double PAlphaEos::tension_pressure(double rho, double e, double alpha_p, double r0, long point) const {
  // The elastic residual decreases with p and is negative at p = 0: walk the
  // lower end of the bracket down until it changes sign.
  const double rho_s = prm_.solid_density;
  auto residual = [&](double p) {
    const double a = elastic_distension(p, alpha_p);
    return solid_pressure(rho * a / rho_s - 1.0, e) / a - p;
  };
  double lo = std::min(2.0 * r0, -1e3), r_lo = residual(lo);
  for (int k = 0; k < 200 && r_lo < 0.0; ++k) {
    lo *= 2.0;
    r_lo = residual(lo);
  }
  const RootResult r = bracketed_root(residual, lo, 0.0, r_lo, r0, 1e-13 * prm_.compaction_pressure);
  if (!r.converged)
    throw NumericalError(EntityKind::material_point, point, "pressure",
                         fmt::format("P-alpha tension solve did not converge (rho = {}, e = {})", rho, e));
  return r.x;
}

double PAlphaEos::elastic_pressure(double rho, double e, double alpha_p, long point) const {
  const double rho_s = prm_.solid_density;
  if (alpha_p <= 1.0) return solid_pressure(rho / rho_s - 1.0, e);
  // Carroll-Holt: p = f(rho alpha, e) / alpha (eq. 34) with the elastic alpha(p).
  auto residual = [&](double p) {
    const double a = elastic_distension(p, alpha_p);
    return solid_pressure(rho * a / rho_s - 1.0, e) / a - p;
  };
  const double a0 = elastic_distension(0.0, alpha_p);
  const double p0 = solid_pressure(rho * a0 / rho_s - 1.0, e) / a0;
  if (p0 <= 0.0) return tension_pressure(rho, e, alpha_p, p0, point);
  double hi = crush_pressure_of(alpha_p);
  double r_hi = residual(hi);
  for (int k = 0; k < 60 && r_hi > 0.0; ++k) {  // beyond the crush point (only asked for by sound speeds)
    hi *= 2.0;
    r_hi = residual(hi);
  }
  const RootResult r = bracketed_root(residual, 0.0, hi, p0, r_hi, 1e-13 * prm_.compaction_pressure);
  if (!r.converged)
    throw NumericalError(
        EntityKind::material_point, point, "pressure",
        fmt::format("P-alpha elastic pressure solve did not converge (rho = {}, e = {})", rho, e));
  return r.x;
}

PAlphaState PAlphaEos::solve(double rho, double e, double alpha_p, long point) const {
  const double rho_s = prm_.solid_density;
  PAlphaState s;
  if (alpha_p <= 1.0) {
    s.pressure = solid_pressure(rho / rho_s - 1.0, e);
    s.distension = s.plastic_distension = 1.0;
    return s;
  }
  // Elastic branch first: is the state below the crush curve of alpha_p?
  const double a0 = elastic_distension(0.0, alpha_p);
  const double p0 = solid_pressure(rho * a0 / rho_s - 1.0, e) / a0;
  s.plastic_distension = alpha_p;
  if (p0 <= 0.0) {
    s.pressure = tension_pressure(rho, e, alpha_p, p0, point);
    s.distension = elastic_distension(s.pressure, alpha_p);
    return s;
  }
  const double p_y = crush_pressure_of(alpha_p);
  const double r_y = solid_pressure(rho * alpha_p / rho_s - 1.0, e) / alpha_p - p_y;
  const double tol = 1e-13 * prm_.compaction_pressure;
  if (r_y < 0.0) {
    auto residual = [&](double p) {
      const double a = elastic_distension(p, alpha_p);
      return solid_pressure(rho * a / rho_s - 1.0, e) / a - p;
    };
    const RootResult r = bracketed_root(residual, 0.0, p_y, p0, r_y, tol);
    if (!r.converged)
      throw NumericalError(EntityKind::material_point, point, "pressure",
                           fmt::format("P-alpha elastic solve did not converge (rho = {}, e = {})", rho, e));
    s.pressure = r.x;
    s.distension = elastic_distension(r.x, alpha_p);
    return s;
  }
  // Crushing: alpha = alpha(p) on the compaction curve, p = f(rho alpha, e)/alpha.
  s.crushing = true;
  const double ps = prm_.compaction_pressure;
  const double r_s = solid_pressure(rho / rho_s - 1.0, e) - ps;
  if (r_s >= 0.0) {  // fully compacted
    s.pressure = solid_pressure(rho / rho_s - 1.0, e);
    s.distension = s.plastic_distension = 1.0;
    return s;
  }
  auto residual = [&](double p) {
    const double a = crush_distension(p);
    return solid_pressure(rho * a / rho_s - 1.0, e) / a - p;
  };
  const RootResult r = bracketed_root(residual, p_y, ps, r_y, r_s, tol);
  if (!r.converged)
    throw NumericalError(EntityKind::material_point, point, "pressure",
                         fmt::format("P-alpha compaction solve did not converge (rho = {}, e = {})", rho, e));
  s.pressure = r.x;
  s.distension = s.plastic_distension = std::min(alpha_p, crush_distension(r.x));
  return s;
}

double PAlphaEos::sound_speed(double rho, double e, const PAlphaState& st) const {
  // c^2 = dp/drho along the isentrope (de = p drho / rho^2), by a one-sided
  // difference on the branch: unloading (elastic) always; on the crush curve
  // the larger of the crush tangent and the elastic unloading one, so that the
  // time step resolves the release wave the point can carry next.
  const double h = 1e-6;
  const double p = st.pressure;
  const double drho = h * rho;
  const double p_unload = elastic_pressure(rho - drho, e - p * drho / (rho * rho), st.plastic_distension, -1);
  double c2 = (p - p_unload) / drho;
  if (st.crushing && st.plastic_distension > 1.0) {
    const double p_load = solve(rho + drho, e + p * drho / (rho * rho), st.plastic_distension).pressure;
    c2 = std::max(c2, (p_load - p) / drho);
  }
  const double floor = 0.01 * prm_.porous_sound_speed * prm_.porous_sound_speed;
  return std::sqrt(std::max(c2, floor));
}

void PAlphaEos::evaluate(MaterialPoints& pts, const MaterialContext& /*ctx*/, bool commit) const {
  const std::size_t n = pts.size();
  double* alpha_p = pts.history.column(pts.history.slot(kPlasticDistension));
  std::atomic<long> failed{-1};
  std::string failure;
#pragma omp parallel for schedule(static) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    try {
      const PAlphaState st = solve(pts.density[i], pts.specific_energy[i], alpha_p[i], static_cast<long>(i));
      pts.pressure[i] = st.pressure;
      pts.sound_speed[i] = sound_speed(pts.density[i], pts.specific_energy[i], st);
      if (commit) alpha_p[i] = st.plastic_distension;  // irreversible: never increases
    } catch (const NumericalError& err) {
      long expected = -1;
      if (failed.compare_exchange_strong(expected, static_cast<long>(i))) {
#pragma omp critical(p_alpha_failure)
        failure = err.detail();
      }
    }
  }
  if (failed.load() >= 0)
    throw NumericalError(EntityKind::material_point, failed.load(), "pressure", failure);
}

std::shared_ptr<const EquationOfState> make_p_alpha_eos(Parameters& b) {
  PAlphaParameters p;
  p.density = b.positive("density");
  p.solid_density = b.positive("solid_density");
  if (!(p.solid_density > p.density))
    b.fail("solid_density",
           fmt::format("must exceed the porous density {} kg/m^3, got {}", p.density, p.solid_density));
  p.crush_pressure = b.positive("crush_pressure");
  p.compaction_pressure = b.positive("compaction_pressure");
  if (!(p.compaction_pressure > p.crush_pressure))
    b.fail("compaction_pressure", fmt::format("must exceed crush_pressure ({} Pa), got {}", p.crush_pressure,
                                              p.compaction_pressure));
  p.compaction_exponent = b.positive("compaction_exponent");
  // Same keys as the plain polynomial EOS (polynomial_eos.cpp): t1 defaults
  // to a1 and t2 to 0, as in Autodyn.
  p.a1 = b.positive("a1");
  p.a2 = b.number("a2");
  p.a3 = b.number("a3");
  p.t1 = b.positive("t1", p.a1);
  p.t2 = b.number("t2", 0.0);
  p.b0 = b.non_negative("b0", 0.0);
  p.b1 = b.non_negative("b1", 0.0);
  p.porous_sound_speed = b.positive("porous_sound_speed");
  const double c_solid = std::sqrt(p.a1 / p.solid_density);
  if (p.porous_sound_speed > c_solid)
    b.fail("porous_sound_speed",
           fmt::format("must not exceed the matrix sound speed sqrt(a1/solid_density) = {:.1f} m/s, got {}",
                       c_solid, p.porous_sound_speed));
  return std::make_shared<PAlphaEos>(p);
}

CAMOUFLET_REGISTER_EOS("p_alpha", make_p_alpha_eos);

}  // namespace camouflet
