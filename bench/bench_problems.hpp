#pragma once
// The standard problems of the whole-run benchmark, built in code
// so that `camouflet_bench` and the thread-consistency tests run the same
// models. Each builder takes the requested size (elements or particles) and
// scales its resolution to it; the full sizes are the issue's.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

#include "materials/elastic_strength.hpp"
#include "materials/linear_eos.hpp"
#include "materials/registry.hpp"
#include "materials/sandy_clay_preset.hpp"
#include "mesh/block_generator.hpp"
#include "mesh/particle_fill.hpp"
#include "model/model.hpp"
#include "sph/sph_options.hpp"

namespace camouflet::bench {

// --- 1. 3-D SPH Taylor bar (Wilkins & Guinan 1973 geometry as used by SPH codes) ---
struct TaylorBar {
  double radius = 3.8e-3;     // m
  double length = 25.4e-3;    // m
  double speed = 190.0;       // m/s, towards the wall z = 0
  double density = 8960.0;    // kg/m^3, copper
  double sound_speed = 3940;  // m/s, linear EOS: K = rho c0^2
  double shear_modulus = 46e9;
  double yield_stress = 0.3e9;
  // Simple-cubic spacing 0.25 mm gives pi R^2 L / s^3 = 73,746 particles.
  double spacing_for(long particles) const {
    const double volume = std::numbers::pi * radius * radius * length;
    return std::cbrt(volume / static_cast<double>(std::max(particles, 8L)));
  }
};
constexpr long taylor_bar_full_size = 73746;

// smoothing_factor 1.05: support 2h = 2.1 spacings holds the 32 nearest
// simple-cubic neighbours (shells at 1, sqrt 2, sqrt 3, 2 spacings), i.e. ~30.
inline sph::SphOptions taylor_bar_options() {
  sph::SphOptions o;
  o.smoothing_factor = 1.05;
  return o;
}

inline Model taylor_bar_model(long particles) {
  const TaylorBar bar;
  Model model;
  model.run.mode = GeometryMode::three_d;
  model.run.end_time = 1.0;
  Parameters eos, strength;
  eos.set_string("type", "linear");
  eos.set_number("density", bar.density);
  eos.set_number("bulk_modulus", bar.density * bar.sound_speed * bar.sound_speed);
  strength.set_string("type", "von_mises");
  strength.set_number("shear_modulus", bar.shear_modulus);
  strength.set_number("yield_stress", bar.yield_stress);
  model.materials.push_back({"copper", make_material("copper", "", {}, eos, strength, Parameters{}), {}});
  Part part;
  part.name = "bar";
  part.kind = PartKind::sph;
  part.material = 0;
  part.initial_velocity = {0.0, 0.0, -bar.speed};
  model.parts.push_back(part);
  ParticleFillSpec spec;
  spec.part = 0;
  spec.region.shape = ParticleRegion::Shape::cylinder;
  spec.region.centre = {0.0, 0.0, 0.0};
  spec.region.axis = {0.0, 0.0, 1.0};
  spec.region.radius = bar.radius;
  spec.region.length = bar.length;
  spec.spacing = bar.spacing_for(particles);
  fill_particles(model.particles, spec, model.run.mode);
  return model;
}

// --- 2. 3-D hex8 elastic-plastic impact: a steel cube at 100 m/s onto a fixed face ---
constexpr long hex_impact_full_size = 45L * 45 * 45;

inline Model hex_impact_model(long elements) {
  const int n = std::max(2, static_cast<int>(std::lround(std::cbrt(static_cast<double>(elements)))));
  Model model;
  model.run.mode = GeometryMode::three_d;
  model.run.end_time = 1.0;
  model.mesh.dimension = 3;
  add_block(model.mesh, {"cube", 0, {0, 0, 0}, {0.045, 0.045, 0.045}, {n, n, n}});
  auto eos = std::make_shared<const LinearEos>(7850.0, 160e9);
  auto strength = std::make_shared<const VonMisesStrength>(80e9, 0.5e9);
  model.materials.push_back({"steel", std::make_shared<const Material>("steel", eos, strength), {}});
  Part part;
  part.name = "cube";
  part.material = 0;
  part.initial_velocity = {0.0, 0.0, -100.0};  // yields at the fixed face: rho c v ~ 4.7 GPa > Y
  model.parts.push_back(part);
  BoundaryCondition fixed;
  fixed.kind = BoundaryKind::fixed;
  fixed.set = "cube.zmin";
  model.boundaries.push_back(fixed);
  return model;
}

// --- 2b. 3-D hex8 Sedov blast in ideal gas: LULESH's problem (Karlin et al., LLNL-TR-641973) ---
// One octant, edge 1.125 with 45^3 elements at full size, symmetry planes x = y = z = 0, ideal
// gas gamma = 1.4 at rho = 1, all of the blast's energy in the corner element (LULESH's
// 3.948746e7 at 45^3, scaled with the element volume for other sizes), the rest cold. The same
// mesh, material and load as LULESH, so that its grind time compares with ours element for
// element (our hex8 carries hourglass control and the full material driver; LULESH's too).
constexpr long sedov_full_size = 45L * 45 * 45;

inline Model sedov_hex_model(long elements) {
  const int n = std::max(2, static_cast<int>(std::lround(std::cbrt(static_cast<double>(elements)))));
  const double edge = 1.125, cell = edge / n;
  const double blast_energy = 3.948746e7 * std::pow(45.0 / n, 3) * std::pow(edge / 45.0, 3);  // J
  Model model;
  model.run.mode = GeometryMode::three_d;
  model.run.end_time = 1.0;
  model.mesh.dimension = 3;
  const auto gas = [](const char* name, double specific_energy) {
    Parameters eos;
    eos.set_string("type", "ideal_gas");
    eos.set_number("density", 1.0);
    eos.set_number("gamma", 1.4);
    eos.set_number("specific_energy", specific_energy);
    return NamedMaterial{name, make_material(name, "", {}, eos, Parameters{}, Parameters{}), {}};
  };
  model.materials.push_back(gas("hot", blast_energy / (cell * cell * cell)));  // rho = 1: per kg = per m^3
  model.materials.push_back(gas("cold", 1e-6));
  // The corner element, and the rest of the cube as three slabs and the remaining column.
  add_block(model.mesh, {"hot", 0, {0, 0, 0}, {cell, cell, cell}, {1, 1, 1}});
  add_block(model.mesh, {"cold_x", 1, {cell, 0, 0}, {edge - cell, edge, edge}, {n - 1, n, n}});
  add_block(model.mesh, {"cold_y", 1, {0, cell, 0}, {cell, edge - cell, edge}, {1, n - 1, n}});
  add_block(model.mesh, {"cold_z", 1, {0, 0, cell}, {cell, cell, edge - cell}, {1, 1, n - 1}});
  for (const char* name : {"hot", "cold_x", "cold_y", "cold_z"}) {
    Part part;
    part.name = name;
    part.material = std::string(name) == "hot" ? 0 : 1;
    model.parts.push_back(part);
  }
  const std::pair<const char*, int> faces[] = {{"hot.xmin", 0},    {"hot.ymin", 1},    {"hot.zmin", 2},
                                               {"cold_x.ymin", 1}, {"cold_x.zmin", 2}, {"cold_y.xmin", 0},
                                               {"cold_y.zmin", 2}, {"cold_z.xmin", 0}, {"cold_z.ymin", 1}};
  for (const auto& [face, axis] : faces) {
    BoundaryCondition sym;
    sym.kind = BoundaryKind::symmetry;
    sym.set = face;
    sym.normal[static_cast<std::size_t>(axis)] = 1.0;
    model.boundaries.push_back(sym);
  }
  return model;
}

// --- 3. 2-D axisymmetric soil (Wang et al. 2005 sandy clay) under a surface pressure ---
constexpr long soil_full_size = 100000;

inline Model soil_axisymmetric_model(long elements) {
  // r x z = 1 m x 2 m, n x 2n cells: 100k elements -> 224 x 448.
  const int n = std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(elements) / 2.0))));
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  model.run.end_time = 1.0;
  model.mesh.dimension = 2;
  add_block(model.mesh, {"soil", 0, {0, -2.0, 0}, {1.0, 2.0, 0.0}, {n, 2 * n, 1}});
  const MaterialPreset p = sandy_clay_wang2005();
  model.materials.push_back({"soil", make_material("soil", "", {}, p.eos, p.strength, p.damage), {}});
  Part part;
  part.name = "soil";
  part.material = 0;
  model.parts.push_back(part);
  BoundaryCondition axis;
  axis.kind = BoundaryKind::axis;
  axis.set = "soil.xmin";
  model.boundaries.push_back(axis);
  BoundaryCondition load;  // 20 MPa on the free surface: a compaction wave into the soil
  load.kind = BoundaryKind::pressure;
  load.set = "soil.ymax";
  load.value[0] = 20e6;
  model.boundaries.push_back(load);
  BoundaryCondition fixed;
  fixed.kind = BoundaryKind::fixed;
  fixed.set = "soil.ymin";
  model.boundaries.push_back(fixed);
  return model;
}

}  // namespace camouflet::bench
