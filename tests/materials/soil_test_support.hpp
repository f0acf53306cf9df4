#pragma once
// Helpers for the three-phase soil tests: the sandy clay preset as Parameters
// and a 1-point driver that advances a material point under a prescribed
// strain rate through Material::update (the same path FEM and SPH use).
#include <omp.h>

#include <cmath>
#include <memory>

#include "core/parameters.hpp"
#include "materials/material.hpp"
#include "materials/registry.hpp"
#include "materials/sandy_clay_preset.hpp"
#include "materials/soil_damage.hpp"
#include "materials/soil_drucker_prager.hpp"
#include "materials/three_phase_soil_eos.hpp"

namespace camouflet::test {

// Sandy clay EOS/strength/damage blocks (Wang et al. 2005, Table 2).
inline Parameters soil_eos_block() {
  return sandy_clay_wang2005().eos;
}
inline Parameters soil_strength_block() {
  return sandy_clay_wang2005().strength;
}
inline Parameters soil_damage_block() {
  return sandy_clay_wang2005().damage;
}

inline std::shared_ptr<const ThreePhaseSoilEos> soil_eos(Parameters block = soil_eos_block()) {
  block.string("type");
  auto eos = make_three_phase_soil_eos(block);
  block.finish();
  return eos;
}

// Material from the three blocks through the registry, as a case file would
// build it (an empty block leaves that component out).
inline std::shared_ptr<const Material> soil_material(Parameters eos, Parameters strength, Parameters damage) {
  // Referencing the factories keeps their registrations linked into the test.
  (void)&make_three_phase_soil_eos;
  (void)&make_soil_drucker_prager;
  (void)&make_soil_bond_damage;
  return make_material("soil", "", {}, std::move(eos), std::move(strength), std::move(damage));
}

// Single-point drives gain nothing from threads, and on a loaded machine each
// OpenMP fork/join of Material::update can cost milliseconds: run them serially.
inline void single_point_threads() {
  omp_set_num_threads(1);
}

// One material point driven by a strain rate (density from the volumetric part).
class PointDriver {
 public:
  explicit PointDriver(std::shared_ptr<const Material> m) : material_(std::move(m)) {
    single_point_threads();
    material_->setup(pts, 1);
  }

  void step(const SymTensor& strain_rate, double dt) {
    pts.density_previous[0] = pts.density[0];
    pts.density[0] *= std::exp(-strain_rate.trace() * dt);
    pts.strain_rate[0] = strain_rate;
    pts.spin[0] = Spin{};
    pts.artificial_viscosity[0] = 0.0;
    time_ += dt;
    material_->update(pts, MaterialContext{dt, time_});
  }
  double history(const char* name) const { return pts.history.column(pts.history.slot(name))[0]; }

  MaterialPoints pts;

 private:
  std::shared_ptr<const Material> material_;
  double time_ = 0.0;
};

// Independent hand formulas of the phase laws (eqs. 13-15), absolute pressures.
struct HandSoil {
  double as = 0.58, aw = 0.38, ag = 0.04;
  double Ks = 2650.0 * 4500.0 * 4500.0, ks = 3.0;
  double Kw = 1000.0 * 1500.0 * 1500.0, kw = 7.0;
  double kg = 1.4, p0 = 1.2 * 340.0 * 340.0 / 1.4;
  double fKp = 0.56 * 165e6, E0 = 20e6;

  double vs(double p) const { return as * std::pow(1.0 + ks * (p - p0) / Ks, -1.0 / ks); }
  double vw(double p) const { return aw * std::pow(1.0 + kw * (p - p0) / Kw, -1.0 / kw); }
  double vg(double p) const { return ag * std::pow(p / p0, -1.0 / kg); }
  // Loading curve, parametrised by the pore pressure pb: returns v, sets p (absolute).
  double loading(double pb, double damage, double& p) const {
    const double vp = vw(pb) + vg(pb);
    const double dvp = (aw + ag) - vp;
    p = pb + fKp * dvp + E0 * (1.0 - damage) * dvp / vp;  // eqs. 12, 16, 17
    return vs(p) + vp;
  }
  // Pore pressure at which the loading curve reaches absolute pressure p (bisection).
  double pore_pressure_at(double p_target, double damage = 0.0) const {
    double lo = 1.0, hi = 1e12;
    for (int i = 0; i < 200; ++i) {
      const double mid = std::sqrt(lo * hi);
      double p = 0.0;
      loading(mid, damage, p);
      (p < p_target ? lo : hi) = mid;
    }
    return std::sqrt(lo * hi);
  }
};

}  // namespace camouflet::test
