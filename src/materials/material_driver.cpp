#include "materials/material_driver.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>
#include <stdexcept>

#include "core/error.hpp"

namespace camouflet {

LoadPath parse_load_path(const std::string& name) {
  std::string n = name;
  std::replace(n.begin(), n.end(), '-', '_');
  for (LoadPath p : {LoadPath::uniaxial_strain, LoadPath::uniaxial_stress, LoadPath::hydrostatic,
                     LoadPath::triaxial, LoadPath::simple_shear})
    if (n == to_string(p)) return p;
  throw std::invalid_argument(fmt::format(
      "unknown load path '{}'; known: uniaxial_strain, uniaxial_stress, hydrostatic, triaxial, simple_shear",
      name));
}

const char* to_string(LoadPath path) {
  switch (path) {
    case LoadPath::uniaxial_strain:
      return "uniaxial_strain";
    case LoadPath::uniaxial_stress:
      return "uniaxial_stress";
    case LoadPath::hydrostatic:
      return "hydrostatic";
    case LoadPath::triaxial:
      return "triaxial";
    case LoadPath::simple_shear:
      return "simple_shear";
  }
  return "?";
}

namespace {

// One material point and the strain it has accumulated.
class PointDriver {
 public:
  PointDriver(const Material& material, const DriverSpec& spec) : material_(material), spec_(spec) {
    material_.setup(pts_, 1);
    pts_.characteristic_length[0] = spec.characteristic_length;
    const std::array<double, 3> origin{};
    material_.eos().place(pts_, std::span<const std::array<double, 3>>(&origin, 1), spec.detonations);
    density0_ = pts_.density[0];
    record();
  }

  const std::vector<DriverRow>& rows() const { return rows_; }
  const MaterialPoints& points() const { return pts_; }

  // Advances `pts` by one step of strain rate d and spin w (both 1/s).
  void advance(MaterialPoints& pts, const SymTensor& d, const Spin& w, double dt) const {
    pts.density_previous[0] = pts.density[0];
    pts.density[0] = pts.density[0] * std::exp(-d.trace() * dt);
    pts.strain_rate[0] = d;
    pts.spin[0] = w;
    pts.artificial_viscosity[0] = 0.0;
    material_.update(pts, MaterialContext{dt, time_ + dt});
  }

  // Strain-controlled step: commits it and records a row.
  void step(const SymTensor& d, const Spin& w, double dt, double axial_rate) {
    advance(pts_, d, w, dt);
    commit(dt, axial_rate);
  }

  // Step whose rate is d(x) with the scalar x solved so that response(pts) =
  // target; x_guess is the first guess. Returns the converged x.
  double held_step(const std::function<SymTensor(double)>& d_of,
                   const std::function<double(double)>& axial_rate_of,
                   const std::function<double(const MaterialPoints&)>& response, double target,
                   double x_guess, double dt, const char* what) {
    auto residual = [&](double x, MaterialPoints& trial) {
      trial = pts_;
      advance(trial, d_of(x), Spin{}, dt);
      return response(trial) - target;
    };
    MaterialPoints trial;
    // Secant iteration; the response is smooth and nearly linear in the rate
    // over one step, so it converges in a few iterations.
    double x0 = x_guess;
    double r0 = residual(x0, trial);
    double scale = std::max({std::abs(target), stress_scale(trial), 1.0});
    if (std::abs(r0) <= spec_.stress_tolerance * scale) return finish_held(trial, dt, axial_rate_of(x0), x0);
    double x1 = x0 + 1.0e-3 * (std::abs(x0) + std::abs(axial_rate_of(x0)) + 1.0e-30);
    double r1 = residual(x1, trial);
    for (int it = 0; it < 100; ++it) {
      scale = std::max({std::abs(target), stress_scale(trial), 1.0});
      if (std::abs(r1) <= spec_.stress_tolerance * scale)
        return finish_held(trial, dt, axial_rate_of(x1), x1);
      if (r1 == r0) break;
      const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
      x0 = x1;
      r0 = r1;
      x1 = x2;
      r1 = residual(x1, trial);
    }
    throw NumericalError(EntityKind::material_point, 0, what,
                         fmt::format("material '{}': the {} could not be held at {:.6g} Pa at t = {:.6g} s "
                                     "(residual {:.3g} Pa)",
                                     material_.name(), what, target, time_, r1));
  }

  double time() const { return time_; }
  double axial_strain() const { return axial_strain_; }

 private:
  static double stress_scale(const MaterialPoints& p) {
    const SymTensor& s = p.deviator[0];
    return std::max({std::abs(p.pressure[0]), std::abs(s.xx), std::abs(s.yy), std::abs(s.zz), std::abs(s.xy),
                     std::abs(s.yz), std::abs(s.zx)});
  }
  double finish_held(const MaterialPoints& trial, double dt, double axial_rate, double x) {
    pts_ = trial;
    commit(dt, axial_rate);
    return x;
  }
  void commit(double dt, double axial_rate) {
    time_ += dt;
    axial_strain_ += axial_rate * dt;
    record();
  }
  void record() {
    DriverRow r;
    r.time = time_;
    r.axial_strain = axial_strain_;
    r.volumetric_strain = -std::log(pts_.density[0] / density0_);
    r.pressure = pts_.pressure[0];
    r.stress = pts_.deviator[0] - SymTensor::isotropic(pts_.pressure[0]);
    r.sqrt_j2 = std::sqrt(j2(pts_.deviator[0]));
    r.density = pts_.density[0];
    r.specific_energy = pts_.specific_energy[0];
    r.plastic_strain = pts_.plastic_strain[0];
    r.damage = pts_.damage[0];
    r.temperature = pts_.temperature[0];
    rows_.push_back(r);
  }

  const Material& material_;
  const DriverSpec& spec_;
  MaterialPoints pts_;
  double density0_ = 0.0;
  double time_ = 0.0;
  double axial_strain_ = 0.0;
  std::vector<DriverRow> rows_;
};

// A one-point batch gains nothing from threads, and on a busy machine each
// parallel region of Material::update costs far more than the point itself:
// the driver runs single-threaded and restores the caller's setting.
class SingleThreaded {
 public:
  SingleThreaded() : saved_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~SingleThreaded() { omp_set_num_threads(saved_); }
  SingleThreaded(const SingleThreaded&) = delete;
  SingleThreaded& operator=(const SingleThreaded&) = delete;

 private:
  int saved_;
};

double lateral_stress(const MaterialPoints& p) {
  return 0.5 * (p.deviator[0].yy + p.deviator[0].zz) - p.pressure[0];
}

// Hydrostatic compression to `target` pressure (Pa) at |rate|: the strain
// increment per step is estimated from the loading stiffness, measured by a
// trial compression of 1e-6 (the reported rho c^2 may be a stiffer release
// branch: the soil reports the stiffness its next release can meet); the last
// step is solved so that the pressure lands on the target exactly.
void compress_to_pressure(PointDriver& driver, double target, double rate, int steps) {
  const MaterialPoints& p = driver.points();
  const double r = -std::abs(rate);
  auto d_of = [](double x) { return SymTensor::isotropic(x); };
  constexpr double probe_strain = 1e-6;
  MaterialPoints probe = p;
  driver.advance(probe, d_of(r), Spin{}, probe_strain / 3.0 / std::abs(rate));
  double bulk = (probe.pressure[0] - p.pressure[0]) / probe_strain;
  if (!(bulk > 0.0)) bulk = p.density[0] * p.sound_speed[0] * p.sound_speed[0];
  if (!(bulk > 0.0))
    throw std::invalid_argument(
        "hydrostatic loading to a pressure needs a material with a positive sound speed");
  const double strain_estimate = (target - p.pressure[0]) / bulk;
  const double dt = strain_estimate / steps / std::abs(rate);
  auto axial_of = [](double x) { return x; };
  auto pressure_of = [](const MaterialPoints& q) { return q.pressure[0]; };
  for (long k = 0; k < 100L * steps; ++k) {
    MaterialPoints trial = p;
    driver.advance(trial, d_of(r), Spin{}, dt);
    if (trial.pressure[0] >= target) {
      driver.held_step(d_of, axial_of, pressure_of, target, r, dt, "pressure");
      return;
    }
    driver.step(d_of(r), Spin{}, dt, r);
  }
  throw NumericalError(
      EntityKind::material_point, 0, "pressure",
      fmt::format("hydrostatic loading did not reach {:.6g} Pa in {} steps", target, 100L * steps));
}

// Axial rate `rate` for `steps` steps of dt with the lateral stress held at `target`.
void axial_with_lateral_stress(PointDriver& driver, double rate, double dt, int steps, double target) {
  double lateral = -0.3 * rate;  // elastic first guess (Poisson ratio 0.3); then the last step's value
  auto d_of = [rate](double x) { return SymTensor{rate, x, x, 0.0, 0.0, 0.0}; };
  auto axial_of = [rate](double) { return rate; };
  for (int k = 0; k < steps; ++k)
    lateral = driver.held_step(d_of, axial_of, lateral_stress, target, lateral, dt, "lateral stress");
}

}  // namespace

std::vector<DriverRow> drive_material(const Material& material, const DriverSpec& spec) {
  if (spec.steps < 1) throw std::invalid_argument("the driver needs at least one step");
  if (spec.strain_rate == 0.0 || !std::isfinite(spec.strain_rate))
    throw std::invalid_argument("the strain rate must be finite and non-zero");
  const SingleThreaded single_threaded;
  PointDriver driver(material, spec);
  const double rate = spec.strain_rate;
  const bool to_pressure = spec.path == LoadPath::hydrostatic && spec.final_pressure > 0.0;
  double dt = 0.0;
  if (!to_pressure) {
    dt = spec.final_strain / rate / spec.steps;
    if (!(dt > 0.0))
      throw std::invalid_argument(fmt::format("final strain {} and strain rate {} /s must have the same sign",
                                              spec.final_strain, rate));
  }
  switch (spec.path) {
    case LoadPath::uniaxial_strain:
      for (int k = 0; k < spec.steps; ++k) driver.step(SymTensor{rate, 0, 0, 0, 0, 0}, Spin{}, dt, rate);
      break;
    case LoadPath::hydrostatic:
      if (to_pressure) {
        compress_to_pressure(driver, spec.final_pressure, rate, spec.steps);
      } else {
        for (int k = 0; k < spec.steps; ++k) driver.step(SymTensor::isotropic(rate), Spin{}, dt, rate);
      }
      break;
    case LoadPath::uniaxial_stress:
      axial_with_lateral_stress(driver, rate, dt, spec.steps, 0.0);
      break;
    case LoadPath::triaxial:
      if (spec.confining_pressure < 0.0)
        throw std::invalid_argument("the confining pressure must not be negative");
      if (spec.confining_pressure > 0.0)
        compress_to_pressure(driver, spec.confining_pressure, rate, spec.steps);
      axial_with_lateral_stress(driver, rate, dt, spec.steps, -spec.confining_pressure);
      break;
    case LoadPath::simple_shear:
      // v_x = gamma_dot y: L_xy = gamma_dot, so D_xy = W_xy = gamma_dot / 2.
      for (int k = 0; k < spec.steps; ++k)
        driver.step(SymTensor{0, 0, 0, 0.5 * rate, 0, 0}, Spin{0.5 * rate, 0, 0}, dt, rate);
      break;
  }
  return driver.rows();
}

void write_driver_csv(std::ostream& out, const std::vector<DriverRow>& rows) {
  out << "time_s,axial_strain,volumetric_strain,sigma_xx_pa,sigma_yy_pa,sigma_zz_pa,sigma_xy_pa,sigma_yz_pa,"
         "sigma_zx_pa,pressure_pa,sqrt_j2_pa,density_kg_m3,specific_energy_j_kg,plastic_strain,damage,"
         "temperature_k\n";
  for (const DriverRow& r : rows)
    fmt::print(out,
               "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},"
               "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n",
               r.time, r.axial_strain, r.volumetric_strain, r.stress.xx, r.stress.yy, r.stress.zz,
               r.stress.xy, r.stress.yz, r.stress.zx, r.pressure, r.sqrt_j2, r.density, r.specific_energy,
               r.plastic_strain, r.damage, r.temperature);
}

}  // namespace camouflet
