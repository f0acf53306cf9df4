// Bad input: a detonation point outside every explosive part is an
// InputError naming the point's key (model/detonation_check.hpp).
#include <gtest/gtest.h>

#include "common/fem_models.hpp"
#include "materials/registry.hpp"
#include "mesh/block_generator.hpp"
#include "model/detonation_check.hpp"

using namespace camouflet;

namespace {

std::shared_ptr<const Material> preset(const std::string& name) {
  return make_material(name, name, {}, Parameters{}, Parameters{}, Parameters{});
}

// A TNT block [0, 0.1] x [0, 0.02] (x [0, 0.02] in 3-D) beside a steel block [0.1, 0.2] x ...
Model charge_and_plate(int dimension) {
  Model model;
  model.run.mode = dimension == 2 ? GeometryMode::axisymmetric : GeometryMode::three_d;
  model.mesh.dimension = dimension;
  model.mesh.nodes_per_element = dimension == 2 ? 4 : 8;
  model.materials.push_back({"tnt", preset("tnt_wang2005"), {}});
  model.materials.push_back({"steel", preset("steel_1006_wang2005"), {}});
  for (int p = 0; p < 2; ++p) {
    Part part;
    part.name = p == 0 ? "charge" : "plate";
    part.material = p;
    model.parts.push_back(part);
    BlockSpec b;
    b.name = part.name;
    b.part = p;
    b.origin = {0.1 * p, 0.0, 0.0};
    b.size = {0.1, 0.02, 0.02};
    b.cells = {5, 2, 2};
    add_block(model.mesh, b);
  }
  return model;
}

void add_detonation(Model& model, std::array<double, 3> x) {
  model.detonations.push_back({x, 0.0});
  model.detonation_where.push_back(
      SourceLocation{"case.toml", 40 + static_cast<int>(model.detonations.size()), 1, "detonation.points"});
}

}  // namespace

TEST(DetonationCheck, PointInChargeOrOnItsSurfacePasses) {
  for (int d : {2, 3}) {
    Model model = charge_and_plate(d);
    add_detonation(model, {0.05, 0.01, d == 3 ? 0.01 : 0.0});  // inside
    add_detonation(model, {0.0, 0.01, 0.0});                   // on the charge's surface (the axis in 2-D)
    EXPECT_NO_THROW(check_detonation_points(model)) << d << "-D";
  }
}

TEST(DetonationCheck, PointOutsideEveryChargeNamesItsKey) {
  for (int d : {2, 3}) {
    Model model = charge_and_plate(d);
    add_detonation(model, {0.05, 0.01, 0.0});
    add_detonation(model, {0.15, 0.01, d == 3 ? 0.01 : 0.0});  // in the steel plate
    try {
      check_detonation_points(model);
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 42);
      EXPECT_EQ(e.where().key, "detonation.points");
      EXPECT_NE(std::string(e.what()).find("charge"), std::string::npos) << e.what();
    }
  }
  // No explosive at all.
  Model model = charge_and_plate(2);
  model.parts[0].material = 1;
  add_detonation(model, {0.05, 0.01, 0.0});
  EXPECT_THROW(check_detonation_points(model), InputError);
}
