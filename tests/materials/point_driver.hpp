#pragma once
// A minimal one-point stepper for what the shared drive_material does not
// offer: strain steps in any direction (loading, then unloading and
// reloading) with access to the point's history between steps. The RHT paths
// use drive_material (concrete_paths.hpp).
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
};

}  // namespace camouflet::test
