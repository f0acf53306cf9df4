#pragma once
// Free vibration of a simply supported elastic strip in plane strain, meshed
// with one-point quads as the buried box's walls are (100 mm walls,
// 2 cells through the thickness in `coarse`, 4 in `default`). Its first
// bending mode exercises exactly what the hourglass control of those walls
// decides: the bending of an element layer is the hourglass mode of its
// quads, so the frequency measures how much bending stiffness each form and
// coefficient gives back (docs/buried-structure.md, "Hourglass form in the
// structure"). Used by test_wall_bending.cpp (quick) and long_wall_bending.cpp.
#include <cmath>
#include <numbers>
#include <vector>

#include "common/fem_models.hpp"
#include "solver/solver.hpp"

namespace camouflet::test {

struct StripSpec {
  double length = 1.0;     // m, span between the supports
  double thickness = 0.1;  // m
  int cells_through = 2;   // square cells: length / thickness * cells_through along the span
  HourglassControl hourglass{HourglassForm::stiffness, 0.1};
  double periods = 3.0;     // of the beam-theory first mode, simulated
  double amplitude = 0.01;  // m/s, initial mid-span velocity
};

// The strip's elastic constants: nu = 0.2 as concrete, c_p = 1414 m/s.
inline ElasticConstants strip_material() {
  return {};
}

// Timoshenko first bending frequency (rad/s) of a simply supported beam, plane
// strain (E' = E / (1 - nu^2)), shear coefficient 5/6: the lower root of
// (kGA k^2 - rho A w^2)(E'I k^2 + kGA - rho I w^2) = (kGA k)^2, k = pi / L.
// For L/t = 10 it lies 1.6 % below Euler-Bernoulli's (pi/L)^2 sqrt(E'I / rho A).
inline double timoshenko_first_frequency(const StripSpec& s, const ElasticConstants& c) {
  const double G = c.shear_modulus;
  const double E = 9.0 * c.bulk_modulus * G / (3.0 * c.bulk_modulus + G);
  const double nu = (3.0 * c.bulk_modulus - 2.0 * G) / (2.0 * (3.0 * c.bulk_modulus + G));
  const double Ep = E / (1.0 - nu * nu);
  const double A = s.thickness, I = std::pow(s.thickness, 3) / 12.0, rho = c.density;
  const double kGA = 5.0 / 6.0 * G * A, k = std::numbers::pi / s.length;
  // a w^4 - b w^2 + d = 0 in w^2.
  const double a = rho * A * rho * I;
  const double b = rho * A * (Ep * I * k * k + kGA) + kGA * k * k * rho * I;
  const double d = kGA * k * k * (Ep * I * k * k + kGA) - kGA * kGA * k * k;
  const double w2 = (b - std::sqrt(b * b - 4.0 * a * d)) / (2.0 * a);
  return std::sqrt(w2);
}

inline double euler_bernoulli_first_frequency(const StripSpec& s, const ElasticConstants& c) {
  const double G = c.shear_modulus;
  const double E = 9.0 * c.bulk_modulus * G / (3.0 * c.bulk_modulus + G);
  const double nu = (3.0 * c.bulk_modulus - 2.0 * G) / (2.0 * (3.0 * c.bulk_modulus + G));
  const double k = std::numbers::pi / s.length;
  return k * k * std::sqrt(E / (1.0 - nu * nu) * s.thickness * s.thickness / 12.0 / c.density);
}

struct StripVibration {
  double period = 0.0;            // s, mean of the measured full periods
  double reference_period = 0.0;  // s, Timoshenko
  int crossings = 0;              // zero crossings of the mid-span velocity seen
  double decay = 0.0;             // last / first velocity peak magnitude
};

// The strip x in [0, L], y in [-t/2, t/2]; the end faces held vertically
// (v_y = 0 on every node of x = 0 and x = L, u_x free: the simple support of
// plane elasticity whose modes are sin(k x)); initial velocity v_y =
// amplitude sin(pi x / L), the first mode's shape. The period comes from the
// zero crossings of the mid-span, mid-thickness node's v_y (linear interpolation).
template <int D = 2>
StripVibration vibrate_strip(const StripSpec& s) {
  use_threads(1);
  const ElasticConstants c = strip_material();
  const int along = static_cast<int>(std::lround(s.length / s.thickness * s.cells_through));
  // 3-D: one hex across a width of one cell, held between two symmetry planes
  // (plane strain), thickness along z.
  const double cell = s.thickness / s.cells_through;
  const BlockSpec block = D == 2 ? BlockSpec{"strip",
                                             0,
                                             {0.0, -0.5 * s.thickness, 0.0},
                                             {s.length, s.thickness, 0.0},
                                             {along, s.cells_through, 1}}
                                 : BlockSpec{"strip",
                                             0,
                                             {0.0, 0.0, -0.5 * s.thickness},
                                             {s.length, cell, s.thickness},
                                             {along, 1, s.cells_through}};
  Model model = block_model(D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d, {block}, c);
  model.mesh.nodes_per_element = D == 2 ? 4 : 8;
  model.boundaries.push_back(velocity("strip.xmin", D - 1, 0.0));
  model.boundaries.push_back(velocity("strip.xmax", D - 1, 0.0));
  if (D == 3) {
    model.boundaries.push_back(symmetry("strip.ymin", {0, 1, 0}));
    model.boundaries.push_back(symmetry("strip.ymax", {0, 1, 0}));
  }
  model.run.hourglass = s.hourglass.form;
  model.run.hourglass_coefficient = s.hourglass.coefficient;
  const double omega = timoshenko_first_frequency(s, c);
  StripVibration out;
  out.reference_period = 2.0 * std::numbers::pi / omega;
  model.run.end_time = s.periods * out.reference_period;

  Solver<D> solver(model);
  const auto& x0 = model.mesh.coordinates;
  std::vector<double>& v = solver.velocity();
  std::size_t probe = 0;
  double best = 1e30;
  for (std::size_t n = 0; n < solver.node_count(); ++n) {
    const double x = x0[D * n], y = x0[D * n + D - 1];
    v[D * n + D - 1] = s.amplitude * std::sin(std::numbers::pi * x / s.length);
    const double d = std::hypot(x - 0.5 * s.length, y);
    if (d < best) best = d, probe = n;
  }
  // A zero crossing counts once the velocity has swung to 30 % of the
  // amplitude on the other side (hysteresis: high-frequency ripple about
  // zero does not add crossings); its time is that of the last sign change.
  std::vector<double> crossings;
  double previous_v = solver.velocity()[D * probe + D - 1], previous_t = solver.time();
  double last_zero = 0.0, sign = 1.0;
  double first_peak = 0.0, last_peak = 0.0, peak = 0.0;
  while (solver.time() < model.run.end_time) {
    solver.step();
    const double vy = solver.velocity()[D * probe + D - 1], t = solver.time();
    peak = std::max(peak, std::abs(vy));
    if ((previous_v > 0.0) != (vy > 0.0))
      last_zero = previous_t + (t - previous_t) * previous_v / (previous_v - vy);
    if (sign * vy < -0.3 * s.amplitude) {
      crossings.push_back(last_zero);
      sign = -sign;
      if (first_peak == 0.0) first_peak = peak;
      last_peak = peak;
      peak = 0.0;
    }
    previous_v = vy;
    previous_t = t;
  }
  out.crossings = static_cast<int>(crossings.size());
  // Zero crossings are half a period apart: the mean over all of them.
  if (crossings.size() >= 3)
    out.period = 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  out.decay = first_peak > 0.0 ? last_peak / first_peak : 0.0;
  return out;
}

}  // namespace camouflet::test
