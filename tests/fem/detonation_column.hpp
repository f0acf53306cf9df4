#pragma once
// The 1-D planar detonation column of the FEM burn tests: an explosive strip
// `length` long, one plane-strain element across, rollers on the long sides
// and a rigid wall at x = 0, lit there at t = 0, CFL 0.5.
#include <memory>
#include <string>

#include "common/fem_models.hpp"

namespace camouflet::test {

inline Model detonation_column_model(const std::string& name, std::shared_ptr<const Material> explosive,
                                     double length, int cells) {
  const double dx = length / cells;
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.run.cfl = 0.5;
  model.mesh.dimension = 2;
  BlockSpec block;
  block.name = name;
  block.size = {length, dx, 0.0};
  block.cells = {cells, 1, 1};
  add_block(model.mesh, block);
  model.materials.push_back({name, std::move(explosive), {}});
  Part part;
  part.name = name;
  part.material = 0;
  model.parts.push_back(part);
  model.boundaries.push_back(symmetry(name + ".ymin", {0.0, 1.0, 0.0}));
  model.boundaries.push_back(symmetry(name + ".ymax", {0.0, 1.0, 0.0}));
  model.boundaries.push_back(symmetry(name + ".xmin", {1.0, 0.0, 0.0}));
  model.detonations.push_back(DetonationPoint{{0.0, 0.5 * dx, 0.0}, 0.0});
  return model;
}

}  // namespace camouflet::test
