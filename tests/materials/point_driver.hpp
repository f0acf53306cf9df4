#pragma once
// A one-point material driver for the concrete tests: strain-controlled
// steps, and mixed steps (axial strain given, the two lateral stresses held)
// for uniaxial stress and triaxial paths. Stand-in for the shared
// material_driver of branch materials-jc until that lands.
#include <omp.h>

#include <cmath>
#include <memory>

#include "materials/material.hpp"

namespace camouflet::test {

class PointDriver {
 public:
  explicit PointDriver(std::shared_ptr<const Material> material) : material_(std::move(material)) {
    // One point: worker threads would only add barrier costs (large on a
    // loaded machine), so the driver runs the update single-threaded.
    omp_set_num_threads(1);
    material_->setup(pts_, 1);
  }

  // One step with a given (small) strain increment over dt.
  void strain_step(const SymTensor& dstrain, double dt) { advance(pts_, dstrain, dt); }

  // One step with axial (xx) strain increment `dexx`; the equal lateral
  // strains (yy = zz) are iterated (secant) until sigma_yy = sigma_lateral.
  // Returns the lateral stress misfit left (Pa).
  double axial_step(double dexx, double sigma_lateral, double dt) {
    auto misfit = [&](double lateral) {
      MaterialPoints trial = pts_;
      advance(trial, SymTensor{dexx, lateral, lateral, 0, 0, 0}, dt);
      return trial.deviator[0].yy - trial.pressure[0] - sigma_lateral;
    };
    double x0 = last_lateral_ratio_ * dexx, x1 = x0 + 1e-3 * std::abs(dexx) + 1e-12;
    double f0 = misfit(x0), f1 = misfit(x1);
    const double scale = 1e-7 * (std::abs(sigma_lateral) + std::abs(axial_stress()) + 1e4);
    for (int k = 0; k < 60 && std::abs(f1) > scale && f1 != f0; ++k) {
      const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
      x0 = x1;
      f0 = f1;
      x1 = x2;
      f1 = misfit(x1);
    }
    if (std::abs(f0) < std::abs(f1)) {
      x1 = x0;
      f1 = f0;
    }
    if (dexx != 0.0) last_lateral_ratio_ = x1 / dexx;
    advance(pts_, SymTensor{dexx, x1, x1, 0, 0, 0}, dt);
    return f1;
  }

  double axial_stress() const { return pts_.deviator[0].xx - pts_.pressure[0]; }  // Pa, tension positive
  double lateral_stress() const { return pts_.deviator[0].yy - pts_.pressure[0]; }
  double equivalent_stress() const { return von_mises(pts_.deviator[0]); }  // sqrt(3 J2)
  double pressure() const { return pts_.pressure[0]; }
  double density() const { return pts_.density[0]; }
  double time() const { return time_; }
  const MaterialPoints& points() const { return pts_; }
  MaterialPoints& points() { return pts_; }

 private:
  void advance(MaterialPoints& p, const SymTensor& dstrain, double dt) {
    p.density_previous[0] = p.density[0];
    p.density[0] = p.density[0] * std::exp(-dstrain.trace());
    p.strain_rate[0] = dstrain * (1.0 / dt);
    p.spin[0] = Spin{};
    const MaterialContext ctx{dt, time_ + dt};
    material_->update(p, ctx);
    if (&p == &pts_) time_ += dt;
  }

  std::shared_ptr<const Material> material_;
  MaterialPoints pts_;
  double time_ = 0.0;
  double last_lateral_ratio_ = -0.2;
};

}  // namespace camouflet::test
