#pragma once
// Small hand-built meshes and field states for the output tests: distorted
// quads and hexes carrying fields that are linear in position, which the
// isoparametric interpolation must reproduce exactly.
#include <array>
#include <vector>

#include "model/snapshot.hpp"

namespace camouflet::test {

struct SnapshotFixture {
  int dim = 2;
  std::vector<double> position, displacement, velocity, acceleration;
  std::vector<std::int64_t> connectivity;
  std::vector<double> density, pressure, plastic, damage, temperature;
  std::vector<SymTensor> stress;
  std::vector<int> material;

  // n x n elements on [0,1]^dim, interior nodes moved so no element is a parallelogram.
  static SnapshotFixture distorted(int dim, int n);
  // Nodal fields set to linear functions of the node position (see .cpp).
  void set_linear_fields(double time);
  static std::array<double, 3> velocity_at(const std::array<double, 3>& x);
  FieldSnapshot view(double time, std::int64_t cycle) const;
};

}  // namespace camouflet::test
