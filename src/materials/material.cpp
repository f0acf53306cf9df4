#include "materials/material.hpp"

#include <stdexcept>
#include <vector>

namespace camouflet {

Material::Material(std::string name, std::shared_ptr<const EquationOfState> eos,
                   std::shared_ptr<const StrengthModel> strength, std::shared_ptr<const DamageModel> damage)
    : name_(std::move(name)),
      eos_(std::move(eos)),
      strength_(std::move(strength)),
      damage_(std::move(damage)) {
  if (!eos_) throw std::invalid_argument("material '" + name_ + "' has no equation of state");
}

void Material::setup(MaterialPoints& pts, std::size_t n) const {
  eos_->register_state(pts);
  if (strength_) strength_->register_state(pts);
  if (damage_) damage_->register_state(pts);
  pts.resize(n);
  const double rho0 = eos_->reference_density();
  const double e0 = eos_->reference_specific_energy();
  for (std::size_t i = 0; i < n; ++i) {
    pts.density[i] = rho0;
    pts.density_previous[i] = rho0;
    pts.specific_energy[i] = e0;
    pts.temperature[i] = 300.0;
  }
  const MaterialContext ctx{};
  eos_->evaluate(pts, ctx, false);
  if (strength_) strength_->initialise(pts);
}

void Material::update(MaterialPoints& pts, const MaterialContext& ctx) const {
  const std::size_t n = pts.size();
  const double dt = ctx.dt;
  // Per point, kept from the predictor for the corrector and the last
  // correction: the specific volume change dv and the predictor's deviatoric
  // work (two divisions each, computed once instead of in every pass).
  // Thread-local scratch: no allocation once it has grown to the batch.
  thread_local std::vector<double> volume_change, deviatoric_work;
  volume_change.resize(n);
  deviatoric_work.resize(n);
  double* const dv_of = volume_change.data();
  double* const work_of = deviatoric_work.data();

  // Objective stress rate (Jaumann) and the first half of the deviatoric work,
  // then the energy predictor: e* = e_n - (p_n + q) dv + s_n:D dt / rho.
#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
  for (std::size_t i = 0; i < n; ++i) {
    pts.deviator[i] += jaumann_increment(pts.deviator[i], pts.spin[i], dt);
    const double rho = pts.density[i];
    const double rho_mid = 0.5 * (rho + pts.density_previous[i]);
    const double dv = 1.0 / rho - 1.0 / pts.density_previous[i];  // m^3/kg
    const double dev_work = dt * contract(pts.deviator[i], pts.strain_rate[i]) / rho_mid;
    dv_of[i] = dv;
    work_of[i] = dev_work;
    pts.specific_energy_start[i] = pts.specific_energy[i];
    pts.pressure_start[i] = pts.pressure[i];
    pts.specific_energy[i] += -(pts.pressure[i] + pts.artificial_viscosity[i]) * dv + dev_work;
  }
  eos_->evaluate(pts, ctx, false);

  // Corrector: trapezoidal p dv with the predicted pressure; the deviatoric
  // work is completed after the strength update below. Half the predictor's
  // work is 0.5 dt s:D / rho_mid to the last bit (halving is exact short of
  // subnormal numbers).
#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
  for (std::size_t i = 0; i < n; ++i) {
    const double p_avg = 0.5 * (pts.pressure_start[i] + pts.pressure[i]);
    pts.specific_energy[i] =
        pts.specific_energy_start[i] - (p_avg + pts.artificial_viscosity[i]) * dv_of[i] + 0.5 * work_of[i];
  }
  eos_->evaluate(pts, ctx, true);
  // The pressure the strength and damage models leave may differ from the
  // EOS's (RHT caps the tensile pressure at the spall strength and scales it
  // with damage). The p dv work must use the pressure that acts, or energy
  // appears that no force supplied: keep the EOS value to correct for it below.
  std::vector<double>& eos_pressure = pts.pressure_start;  // p_start is no longer needed
  eos_pressure.assign(pts.pressure.begin(), pts.pressure.end());

  // Trapezoidal p dv with the acting end pressure: e -= (p - p_eos) dv / 2.
  const auto acting_pressure_correction = [&](std::size_t i) {
    pts.specific_energy[i] -= 0.5 * (pts.pressure[i] - eos_pressure[i]) * dv_of[i];
  };
  if (strength_) {
    strength_->update(pts, ctx);
    // The second half of the deviatoric work; without a damage model nothing
    // runs between it and the pressure correction, so both go in one pass.
    const bool correct_here = !damage_;
#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
    for (std::size_t i = 0; i < n; ++i) {
      const double rho_mid = 0.5 * (pts.density[i] + pts.density_previous[i]);
      pts.specific_energy[i] += 0.5 * dt * contract(pts.deviator[i], pts.strain_rate[i]) / rho_mid;
      if (correct_here) acting_pressure_correction(i);
    }
    if (correct_here) return;
  } else {
#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
    for (std::size_t i = 0; i < n; ++i) pts.deviator[i] = SymTensor{};
  }
  if (damage_) damage_->update(pts, ctx);

#pragma omp parallel for schedule(static) if (n > 2048)  // small batches: one thread
  for (std::size_t i = 0; i < n; ++i) acting_pressure_correction(i);
}

}  // namespace camouflet
