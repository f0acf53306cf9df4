#pragma once
// A Taylor cylinder impact in axisymmetric quad4 FEM: a
// rod of radius R and length L at velocity V against a rigid, frictionless
// wall (symmetry plane z = 0; the rod cannot rebound from it, which changes
// the final shape by the elastic spring-back only), axis boundary at r = 0.
// The final length is the axis node at the rear face; the foot diameter is
// twice the largest radius of the impact face. Both are time averages over
// the last part of the run, when the plastic deformation has stopped and only
// the elastic ringing remains. docs/theory/explosive-and-steel.md §5.2.
#include <cstdio>
#include <string>

#include "common/fem_models.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/registry.hpp"
#include "solver/solver.hpp"

namespace camouflet::test {

struct TaylorSpec {
  std::string preset;         // material preset
  double radius = 0.0;        // m
  double length = 0.0;        // m
  double velocity = 0.0;      // m/s
  int radial_cells = 8;       // cells across the radius (square cells along the rod)
  double end_time = 0.0;      // s
  double average_from = 0.0;  // s, start of the time average of the final shape
};

struct TaylorResult {
  double final_length = 0.0;      // m
  double foot_diameter = 0.0;     // m
  double kinetic_fraction = 0.0;  // kinetic energy at the end / initial
  double energy_error = 0.0;      // relative energy balance error at the end
  double max_plastic_strain = 0.0;
  double max_damage = 0.0;  // Johnson-Cook failure of the preset (1 = failed)
  // The hottest element of the final field (the snapshot the output writes),
  // and the temperature the plastic work at that element predicts,
  // T0 + chi w_p / C_v with w_p = sum sigma_eq d(eps_p) / rho integrated here
  // from the stress and plastic strain of every cycle (Taylor-Quinney).
  double peak_temperature = 0.0;            // K
  double peak_temperature_from_work = 0.0;  // K
  double room_temperature = 0.0;            // K
  std::int64_t cycles = 0;
};

inline TaylorResult run_taylor_bar(const TaylorSpec& spec) {
  use_threads(1);
  const int nz = static_cast<int>(std::lround(spec.radial_cells * spec.length / spec.radius));
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  model.mesh.dimension = 2;
  add_block(model.mesh, {"rod", 0, {0, 0, 0}, {spec.radius, spec.length, 0}, {spec.radial_cells, nz, 1}});
  model.materials.push_back(
      {"rod", make_material("rod", spec.preset, {}, Parameters{}, Parameters{}, Parameters{}), {}});
  Part part;
  part.name = "rod";
  part.material = 0;
  part.initial_velocity = {0.0, -spec.velocity, 0.0};
  model.parts.push_back(part);
  BoundaryCondition axis;
  axis.kind = BoundaryKind::axis;
  axis.set = "rod.xmin";
  model.boundaries.push_back(axis);
  model.boundaries.push_back(symmetry("rod.ymin", {0, 1, 0}));
  model.run.end_time = spec.end_time;

  Solver<2> solver(model);
  // The axis node of the rear face and the nodes of the impact face.
  const auto& x = solver.position();
  std::size_t rear = 0;
  for (std::size_t n = 0; n < solver.node_count(); ++n)
    if (x[2 * n] < 1e-12 && x[2 * n + 1] > x[2 * rear + 1]) rear = n;
  std::vector<std::size_t> face;
  for (std::size_t n = 0; n < solver.node_count(); ++n)
    if (x[2 * n + 1] < 1e-12) face.push_back(n);

  TaylorResult r;
  double weight = 0.0;
  const auto* jc = dynamic_cast<const JohnsonCookStrength*>(model.materials[0].material->strength());
  const MaterialPoints& pts = solver.batches()[0];
  std::vector<double> plastic_work(pts.size(), 0.0), plastic_before = pts.plastic_strain;  // J/kg, -
  while (solver.time() < spec.end_time) {
    solver.limit_next_step(spec.end_time - solver.time());
    solver.step();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      plastic_work[i] += von_mises(pts.deviator[i]) * (pts.plastic_strain[i] - plastic_before[i]) / pts.density[i];
      plastic_before[i] = pts.plastic_strain[i];
    }
    if (solver.time() > spec.average_from) {
      const double dt = solver.time_step_limit().dt;
      double foot = 0.0;
      for (std::size_t n : face) foot = std::max(foot, x[2 * n]);
      r.final_length += x[2 * rear + 1] * dt;
      r.foot_diameter += 2.0 * foot * dt;
      weight += dt;
    }
  }
  r.final_length /= weight;
  r.foot_diameter /= weight;
  r.kinetic_fraction = solver.energy().kinetic / solver.energy().initial_total;
  r.energy_error = solver.energy().relative_error;
  for (double e : solver.batches()[0].plastic_strain)
    r.max_plastic_strain = std::max(r.max_plastic_strain, e);
  for (double d : solver.batches()[0].damage) r.max_damage = std::max(r.max_damage, d);
  const FieldSnapshot fields = solver.snapshot();
  std::size_t hottest = 0;
  for (std::size_t e = 0; e < fields.element_temperature.size(); ++e)
    if (fields.element_temperature[e] > fields.element_temperature[hottest]) hottest = e;
  r.peak_temperature = fields.element_temperature[hottest];
  if (jc) {
    const JohnsonCookParameters& p = jc->parameters();
    r.room_temperature = p.room_temperature;
    r.peak_temperature_from_work = p.room_temperature + p.taylor_quinney * plastic_work[hottest] / p.specific_heat;
  }
  r.cycles = solver.cycle();
  std::printf(
      "Taylor %s, V = %.0f m/s, %d cells across: L = %.3f mm (L/L0 = %.4f), foot D = %.3f mm, "
      "max eps_p = %.3f, max damage %.3f, peak T = %.1f K (from the plastic work %.1f K), KE left %.2e, "
      "energy error %.2e, %lld cycles\n",
      spec.preset.c_str(), spec.velocity, spec.radial_cells, r.final_length * 1e3,
      r.final_length / spec.length, r.foot_diameter * 1e3, r.max_plastic_strain, r.max_damage,
      r.peak_temperature, r.peak_temperature_from_work, r.kinetic_fraction, r.energy_error, static_cast<long long>(r.cycles));
  return r;
}

}  // namespace camouflet::test
