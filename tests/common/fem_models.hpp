#pragma once
// Small models built in code for the FEM and solver tests (no case reader):
// one elastic or elastic-plastic material, blocks from the block generator,
// boundary conditions by set name.
#include <omp.h>

#include <memory>
#include <string>

#include "materials/elastic_strength.hpp"
#include "materials/linear_eos.hpp"
#include "mesh/block_generator.hpp"
#include "model/model.hpp"

namespace camouflet::test {

// The verification problems are small: one thread avoids team start-up
// costs (the shared material loops have no size threshold).
inline void use_threads(int n) {
  omp_set_num_threads(n);
}

struct ElasticConstants {
  double density = 2000.0;       // kg/m^3
  double bulk_modulus = 2.0e9;   // Pa
  double shear_modulus = 1.5e9;  // Pa
  double yield_stress = 0.0;     // Pa; 0 = elastic
  double p_wave_speed() const { return std::sqrt((bulk_modulus + 4.0 * shear_modulus / 3.0) / density); }
  double bulk_wave_speed() const { return std::sqrt(bulk_modulus / density); }
  double lame_lambda() const { return bulk_modulus - 2.0 * shear_modulus / 3.0; }
};

inline std::shared_ptr<const Material> elastic_material(const ElasticConstants& c,
                                                        const std::string& name = "solid") {
  auto eos = std::make_shared<const LinearEos>(c.density, c.bulk_modulus);
  std::shared_ptr<const StrengthModel> strength;
  if (c.yield_stress > 0.0)
    strength = std::make_shared<const VonMisesStrength>(c.shear_modulus, c.yield_stress);
  else
    strength = std::make_shared<const ElasticStrength>(c.shear_modulus);
  return std::make_shared<const Material>(name, eos, strength);
}

// A model of one part made of the given blocks (all of part 0).
inline Model block_model(GeometryMode mode, const std::vector<BlockSpec>& blocks, const ElasticConstants& c) {
  Model model;
  model.run.mode = mode;
  model.mesh.dimension = dimension_of(mode);
  for (const auto& b : blocks) add_block(model.mesh, b);
  model.materials.push_back({"solid", elastic_material(c), {}});
  Part part;
  part.name = blocks.front().name;
  part.material = 0;
  model.parts.push_back(part);
  return model;
}

// An empty model of `mode` that runs `cycles` cycles at the fixed step `dt` (s; the end time far
// off) without hourglass control: the viscosity tests' set-up, their material and mesh to add.
inline Model fixed_step_model(GeometryMode mode, double dt, std::int64_t cycles) {
  Model model;
  model.run.mode = mode;
  model.mesh.dimension = dimension_of(mode);
  model.run.end_time = 1.0;
  model.run.max_cycles = cycles;
  model.run.initial_dt = model.run.max_dt = dt;
  model.run.hourglass = HourglassForm::none;
  return model;
}

inline BoundaryCondition symmetry(const std::string& set, std::array<double, 3> normal) {
  BoundaryCondition bc;
  bc.kind = BoundaryKind::symmetry;
  bc.set = set;
  bc.normal = normal;
  return bc;
}

inline BoundaryCondition velocity(const std::string& set, int component, double value) {
  BoundaryCondition bc;
  bc.kind = BoundaryKind::velocity;
  bc.set = set;
  bc.components[static_cast<std::size_t>(component)] = true;
  bc.value[static_cast<std::size_t>(component)] = value;
  return bc;
}

// A velocity ramped from 0 to `value` over `ramp` seconds, then held.
inline BoundaryCondition ramped_velocity(const std::string& set, int component, double value, double ramp) {
  BoundaryCondition bc = velocity(set, component, value);
  bc.history = TimeHistory{{0.0, ramp}, {0.0, 1.0}};
  return bc;
}

inline BoundaryCondition pressure(const std::string& face_set, double p,
                                  std::optional<TimeHistory> history = {}) {
  BoundaryCondition bc;
  bc.kind = BoundaryKind::pressure;
  bc.set = face_set;
  bc.value[0] = p;
  bc.history = std::move(history);
  return bc;
}

// The erosion tests' bar (plane strain, 0.1 m x 0.01 m, 20 x 2 quads):
// parts left | seed | right, the seed the middle 0.01 m column (2 elements)
// of material "seed", the rest of material "steel"; symmetric about y = 0
// and x = 0, its right end pulled along x at 10 m/s, ramped up over 20 us.
// The caller sets the erosion criteria and the run.
inline Model seeded_pulled_bar(std::shared_ptr<const Material> steel, std::shared_ptr<const Material> seed) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  model.materials.push_back({"steel", std::move(steel), {}});
  model.materials.push_back({"seed", std::move(seed), {}});
  model.parts.push_back(Part{"left", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"seed", PartKind::fem, 1, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"right", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  add_block(model.mesh, {"left", 0, {0, 0, 0}, {0.045, 0.01, 0}, {9, 2, 1}});
  add_block(model.mesh, {"seed", 1, {0.045, 0, 0}, {0.01, 0.01, 0}, {1, 2, 1}});
  add_block(model.mesh, {"right", 2, {0.055, 0, 0}, {0.045, 0.01, 0}, {9, 2, 1}});
  for (const char* s : {"left.ymin", "seed.ymin", "right.ymin"})
    model.boundaries.push_back(symmetry(s, {0, 1, 0}));
  model.boundaries.push_back(symmetry("left.xmin", {1, 0, 0}));
  model.boundaries.push_back(ramped_velocity("right.xmax", 0, 10.0, 20e-6));
  return model;
}

}  // namespace camouflet::test
