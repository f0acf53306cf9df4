#pragma once
// A plane P-pulse crossing a joined SPH zone in one elastic material:
// FEM [0, 0.4] L | SPH [0.4, 0.8] L | FEM [0.8, 1.2] L
// along the column, laterally confined (symmetry planes, or the axis and a
// roller in r-z), driven by a sin^2 velocity pulse at the near end and
// absorbed by a transmitting boundary at the far end.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "common/fem_models.hpp"
#include "coupling/joined_zone.hpp"
#include "solver/solver.hpp"

namespace camouflet::test {

struct JoinCrossing {
  double incident = 0.0;              // m/s, peak at the FEM gauge x = 0.2 L
  double reflected_fem_to_sph = 0.0;  // m/s, peak at that gauge from the interface at 0.4 L
  double reflected_sph_to_fem = 0.0;  // m/s, peak from the interface at 0.8 L
  double in_particles = 0.0;          // m/s, peak at the particle nearest 0.6 L
  double transmitted = 0.0;           // m/s, peak at the FEM gauge 1.0 L
  // Either side of each join, 0.05 L (10 cells) away from it: the join's own transmission.
  double before_fem_to_sph = 0.0;  // m/s, peak at the FEM gauge 0.35 L
  double after_fem_to_sph = 0.0;   // m/s, peak at the particle nearest 0.45 L
  double before_sph_to_fem = 0.0;  // m/s, peak at the particle nearest 0.75 L
  double after_sph_to_fem = 0.0;   // m/s, peak at the FEM gauge 0.85 L
  double energy_change = 0.0;      // relative change of E_kin + E_int + E_hg over the crossing
  double join_work = 0.0;          // J, join work booked over the crossing, over the pulse energy
};

inline TimeHistory sin2_pulse(double duration) {
  TimeHistory h;
  for (int k = 0; k <= 40; ++k) {
    const double s = k / 40.0;
    h.time.push_back(s * duration);
    h.value.push_back(std::pow(std::sin(std::numbers::pi * s), 2));
  }
  return h;
}

// Appends an SPH part "zone" of material 0 to `model` and returns the fill
// of the box [min, max] at `spacing` (m) for it: what make_joined_zone takes.
inline ParticleFillSpec zone_box(Model& model, double spacing, std::array<double, 3> min,
                                 std::array<double, 3> max) {
  Part zone;
  zone.name = "zone";
  zone.kind = PartKind::sph;
  zone.material = 0;
  model.parts.push_back(zone);
  ParticleFillSpec fill;
  fill.part = static_cast<int>(model.parts.size()) - 1;
  fill.spacing = spacing;
  fill.region.min = min;
  fill.region.max = max;
  return fill;
}

// The r-z column beside the axis (test_join_axis.cpp, test_join_erosion.cpp): `columns` cells of
// 5 mm (axis at r = 0, roller at r = columns cells), 1.2 m long, the SPH zone [0.4, 0.8] m joined,
// a sin^2 velocity pulse of 1 m/s over 0.1 m / c_p driven along z into the bottom (or down from the
// top) and absorbed by a transmitting boundary at the other end.
inline Model axis_column(int columns, const ElasticConstants& c, bool from_top = false) {
  const double cell = 5e-3, length = 1.2, width = columns * cell;
  BlockSpec block{"bar", 0, {0, 0, 0}, {width, length, 0}, {columns, static_cast<int>(length / cell), 1}};
  Model model = block_model(GeometryMode::axisymmetric, {block}, c);
  make_joined_zone(model, zone_box(model, cell, {0.0, 0.4, 0.0}, {width, 0.8, 0.0}));
  model.sph.viscosity_switch = true;  // as the plane-pulse tests of test_join.cpp
  BoundaryCondition drive = velocity(from_top ? "bar.ymax" : "bar.ymin", 1, from_top ? -1.0 : 1.0);
  drive.history = sin2_pulse(0.1 / c.p_wave_speed());
  model.boundaries.push_back(drive);
  BoundaryCondition far;
  far.kind = BoundaryKind::transmitting;
  far.set = from_top ? "bar.ymin" : "bar.ymax";
  model.boundaries.push_back(far);
  BoundaryCondition axis;
  axis.kind = BoundaryKind::axis;
  axis.set = "bar.xmin";
  model.boundaries.push_back(axis);
  model.boundaries.push_back(symmetry("bar.xmax", {1, 0, 0}));
  return model;
}

// Gives the element of `model` whose centre is `centre` (m) a part and material of its own: a copy of
// material 0 that erodes past `geometric_strain`, its part joined as the FEM parts around the zone are.
// Returns the element's index (model.mesh.element_count() when no centre matches within 1e-6 m).
inline std::size_t make_element_erode(Model& model, std::array<double, 3> centre, double geometric_strain) {
  const std::size_t npe = static_cast<std::size_t>(model.mesh.nodes_per_element);
  const std::size_t d = static_cast<std::size_t>(model.mesh.dimension);
  std::size_t found = model.mesh.element_count();
  for (std::size_t e = 0; e < model.mesh.element_count(); ++e) {
    double miss = 0.0;
    for (std::size_t i = 0; i < d; ++i) {
      double c = 0.0;
      for (std::size_t a = 0; a < npe; ++a)
        c += model.mesh.coordinates[static_cast<std::size_t>(model.mesh.connectivity[e * npe + a]) * d + i] /
             static_cast<double>(npe);
      miss = std::max(miss, std::abs(c - centre[i]));
    }
    if (miss < 1e-6) found = e;
  }
  if (found == model.mesh.element_count()) return found;
  model.materials.push_back(model.materials.front());
  model.materials.back().name = "eroding " + model.materials.front().name;
  model.erosion.resize(model.materials.size());
  model.erosion.back().geometric_strain = geometric_strain;
  Part part = model.parts[static_cast<std::size_t>(model.mesh.element_part[found])];
  part.name = "eroding";
  part.material = static_cast<int>(model.materials.size()) - 1;
  model.parts.push_back(part);
  model.mesh.element_part[found] = static_cast<int>(model.parts.size()) - 1;
  for (Join& join : model.joins) join.fem_parts.push_back(model.mesh.element_part[found]);
  return found;
}

// Lateral extent of the column: `cells` elements wide, starting at `inner` (m) from the axis or
// the x = 0 plane (inner > 0 in r-z: an annulus between two rollers, away from the axis).
struct ColumnSection {
  int cells = 4;
  double inner = 0.0;
};

// cell: element size (m); spacing: particle spacing (m).
template <int D>
JoinCrossing join_crossing(GeometryMode mode, double cell, double spacing, const sph::SphOptions& sph = {},
                           ColumnSection section = {}) {
  use_threads(1);
  const ElasticConstants c;
  const double length = 1.2, width = section.cells * cell;
  const bool axi = mode == GeometryMode::axisymmetric;
  const int along = axi ? 1 : 0;  // the column's axis: x, or z (= y) in r-z
  const int cells = static_cast<int>(std::lround(length / cell));
  BlockSpec block{"bar", 0, {0, 0, 0}, {width, width, width}, {section.cells, section.cells, section.cells}};
  block.origin[0] = section.inner;
  block.size[static_cast<std::size_t>(along)] = length;
  block.cells[static_cast<std::size_t>(along)] = cells;
  Model model = block_model(mode, {block}, c);
  ParticleFillSpec fill =
      zone_box(model, spacing, {section.inner, 0, 0}, {section.inner + width, width, width});
  fill.region.min[static_cast<std::size_t>(along)] = 0.4;
  fill.region.max[static_cast<std::size_t>(along)] = 0.8;
  make_joined_zone(model, fill);
  model.sph = sph;

  const double c_p = c.p_wave_speed(), duration = 0.1 / c_p;
  const std::string axes = "xyz";
  auto face = [&](int axis, bool max) {
    return "bar." + std::string(1, axes[static_cast<std::size_t>(axis)]) + (max ? "max" : "min");
  };
  BoundaryCondition drive = velocity(face(along, false), along, 1.0);
  drive.history = sin2_pulse(duration);
  model.boundaries.push_back(drive);
  BoundaryCondition far;
  far.kind = BoundaryKind::transmitting;
  far.set = face(along, true);
  model.boundaries.push_back(far);
  for (int axis = 0; axis < D; ++axis) {
    if (axis == along) continue;
    std::array<double, 3> normal{};
    normal[static_cast<std::size_t>(axis)] = 1.0;
    if (axi && axis == 0 && section.inner == 0.0) {
      BoundaryCondition a;
      a.kind = BoundaryKind::axis;
      a.set = face(0, false);
      model.boundaries.push_back(a);
    } else {
      model.boundaries.push_back(symmetry(face(axis, false), normal));
    }
    model.boundaries.push_back(symmetry(face(axis, true), normal));
  }
  model.run.end_time = 1.6 * length / c_p;

  Solver<D> solver(model);
  auto nearest_node = [&](double s) {
    std::size_t best = 0;
    double best_d = 1e300;
    for (std::size_t n = 0; n < solver.node_count(); ++n) {
      if (solver.node_mass()[n] <= 0.0) continue;
      double d2 = 0.0;
      for (int i = 0; i < D; ++i) {
        const double target = i == along ? s : (i == 0 ? section.inner : 0.0) + 0.5 * width;
        d2 += std::pow(solver.position()[n * D + static_cast<std::size_t>(i)] - target, 2);
      }
      if (d2 < best_d) best_d = d2, best = n;
    }
    return best;
  };
  const std::size_t g_in = nearest_node(0.2), g_out = nearest_node(1.0);
  const std::size_t g_before = nearest_node(0.35), g_after = nearest_node(0.85);
  const auto& pa = solver.particles()->particles();
  auto nearest_particle = [&](double s) {
    std::size_t best_i = 0;
    double best = 1e300;
    for (std::size_t i = 0; i < pa.real; ++i) {
      double d2 = 0.0;
      for (int k = 0; k < D; ++k)
        d2 +=
            std::pow(pa.position[i][k] - (k == along ? s : (k == 0 ? section.inner : 0.0) + 0.5 * width), 2);
      if (d2 < best) best = d2, best_i = i;
    }
    return best_i;
  };
  const std::size_t g_sph = nearest_particle(0.6), g_sph_in = nearest_particle(0.45),
                    g_sph_out = nearest_particle(0.75);

  JoinCrossing r;
  double e_start = 0.0, w_start = 0.0;
  const double t_start = 0.15 / c_p, t_stop = 1.1 / c_p;
  const double scale_t = 1.0 / c_p;  // t in units of the time to cross 1 m
  while (solver.time() < model.run.end_time) {
    solver.limit_next_step(model.run.end_time - solver.time());
    solver.step();
    const double t = solver.time() / scale_t;
    const double v_in = std::abs(solver.velocity()[g_in * D + static_cast<std::size_t>(along)]);
    const double v_out = std::abs(solver.velocity()[g_out * D + static_cast<std::size_t>(along)]);
    const double v_sph = std::abs(pa.velocity[g_sph][along]);
    if (t < 0.35)
      r.incident = std::max(r.incident, v_in);
    else if (t < 1.0)
      r.reflected_fem_to_sph = std::max(r.reflected_fem_to_sph, v_in);
    else if (t > 1.2)
      r.reflected_sph_to_fem = std::max(r.reflected_sph_to_fem, v_in);
    r.in_particles = std::max(r.in_particles, v_sph);
    auto node_v = [&](std::size_t n) {
      return std::abs(solver.velocity()[n * D + static_cast<std::size_t>(along)]);
    };
    r.before_fem_to_sph = std::max(r.before_fem_to_sph, node_v(g_before));
    r.after_sph_to_fem = std::max(r.after_sph_to_fem, node_v(g_after));
    r.after_fem_to_sph = std::max(r.after_fem_to_sph, std::abs(pa.velocity[g_sph_in][along]));
    r.before_sph_to_fem = std::max(r.before_sph_to_fem, std::abs(pa.velocity[g_sph_out][along]));
    r.transmitted = std::max(r.transmitted, v_out);
    const EnergyBalance& e = solver.energy();
    const double total = e.kinetic + e.internal + e.hourglass;
    if (e_start == 0.0 && solver.time() >= t_start) e_start = total, w_start = e.boundary_work;
    if (std::getenv("JOIN_DEBUG") && solver.cycle() % 50 == 0)
      std::printf(
          "t %.3f kin %.5g int %.5g hg %.5g visc %.5g sph_kin %.5g sph_int %.5g join %.5g face %.5g\n", t,
          e.kinetic, e.internal, e.hourglass, e.viscous, solver.particles()->kinetic_energy(),
          solver.particles()->internal_energy(), solver.energy_split().join, solver.energy_split().join_face);
    if (r.energy_change == 0.0 && solver.time() >= t_stop) {
      r.energy_change = (total - e_start) / e_start;
      r.join_work = (e.boundary_work - w_start) / e_start;
    }
  }
  return r;
}

}  // namespace camouflet::test
