#pragma once
// A Taylor cylinder impact in axisymmetric quad4 FEM (issue 4, item 5): a
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
  while (solver.time() < spec.end_time) {
    solver.limit_next_step(spec.end_time - solver.time());
    solver.step();
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
  r.cycles = solver.cycle();
  std::printf(
      "Taylor %s, V = %.0f m/s, %d cells across: L = %.3f mm (L/L0 = %.4f), foot D = %.3f mm, "
      "max eps_p = %.3f, max damage %.3f, KE left %.2e, energy error %.2e, %lld cycles\n",
      spec.preset.c_str(), spec.velocity, spec.radial_cells, r.final_length * 1e3,
      r.final_length / spec.length, r.foot_diameter * 1e3, r.max_plastic_strain, r.max_damage,
      r.kinetic_fraction, r.energy_error, static_cast<long long>(r.cycles));
  return r;
}

}  // namespace camouflet::test
