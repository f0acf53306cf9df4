// Embedded bars under a prescribed homogeneous stretch of their host:
// every host node moves with v = L x (L the velocity gradient), so the
// bar's strain is known exactly and an elastic steel bar in uniaxial stress
// must carry sigma = E eps (Young's modulus, not the constrained modulus),
// along a diagonal in 3-D, along x in plane strain, and as a ring (hoop
// strain v_r / r) in axisymmetric mode. docs/theory/reinforcement.md, section 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/verification.hpp"
#include "solver/rc_models.hpp"

using namespace camouflet;

namespace {

constexpr double rate = 1.0;            // 1/s, stretch rate
constexpr double target_strain = 1e-3;  // below the steel's yield strain (~1.6e-3)

// Young's modulus of the steel preset from its bulk and shear moduli.
double steel_young() {
  MaterialPoints pts;
  test::steel_1006()->setup(pts, 1);
  const double k = pts.density[0] * pts.sound_speed[0] * pts.sound_speed[0], g = pts.shear_modulus[0];
  return 9.0 * k * g / (3.0 * k + g);
}

template <int D>
void stretch(GeometryMode mode, std::array<double, 3> direction, BarOrientation orientation,
             const std::string& name) {
  test::use_threads(1);
  Model model;
  model.run.mode = mode;
  model.mesh.dimension = D;
  model.run.end_time = 1.0;
  test::ElasticConstants soft{2000.0, 1e8, 5e7, 0.0};
  model.materials.push_back({"host", test::elastic_material(soft, "host"), {}});
  model.materials.push_back({"steel", test::steel_1006(), {}});
  model.parts.push_back(Part{"host", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  const double r0 = mode == GeometryMode::axisymmetric ? 1.0 : 0.0;
  add_block(model.mesh, {"host", 0, {r0, 0, 0}, {0.1, 0.1, 0.1}, {4, 4, 4}});
  // Prescribed homogeneous stretch along n: every node moves with
  // v = rate (X . n) n (X its initial position), an affine field.
  for (std::size_t n = 0; n < model.mesh.node_count(); ++n) {
    const std::string set = fmt::format("node{}", n);
    model.mesh.node_sets[set] = {static_cast<std::int64_t>(n)};
    double proj = 0.0;
    for (int i = 0; i < D; ++i)
      proj += model.mesh.coordinates[n * D + static_cast<std::size_t>(i)] *
              direction[static_cast<std::size_t>(i)];
    BoundaryCondition bc;
    bc.kind = BoundaryKind::velocity;
    bc.set = set;
    for (int i = 0; i < D; ++i) {
      bc.components[static_cast<std::size_t>(i)] = true;
      bc.value[static_cast<std::size_t>(i)] = rate * proj * direction[static_cast<std::size_t>(i)];
    }
    model.boundaries.push_back(bc);
  }
  BarSet bar;
  bar.name = "bar";
  bar.segments = 3;
  bar.area = 1e-4;
  bar.material = 1;
  bar.orientation = orientation;
  for (int i = 0; i < D; ++i) {
    bar.from[static_cast<std::size_t>(i)] = (i == 0 ? r0 : 0.0) + 0.02;
    bar.to[static_cast<std::size_t>(i)] =
        bar.from[static_cast<std::size_t>(i)] + 0.06 * direction[static_cast<std::size_t>(i)];
  }
  model.bars.push_back(bar);
  Solver<D> solver(model);
  double strain = 0.0;
  while (strain < target_strain) {
    solver.step();
    strain = solver.bars().axial_strain(1);
  }
  const double e = steel_young();
  test::verify({"Embedded bar, " + name + ": elastic axial stress",
                "E eps (uniaxial stress, Young's modulus)", e * strain, solver.bars().axial_stress(1), 0.01,
                true, "Pa"});
}

}  // namespace

TEST(EmbeddedBars, UniaxialStressAlongXPlaneStrain) {
  stretch<2>(GeometryMode::plane_strain, {1, 0, 0}, BarOrientation::along, "plane strain, along x");
}

TEST(EmbeddedBars, UniaxialStressAlongADiagonal3d) {
  const double c = 1.0 / std::sqrt(3.0);
  stretch<3>(GeometryMode::three_d, {c, c, c}, BarOrientation::along, "3-D, diagonal");
}

TEST(EmbeddedBars, RingInHoopAxisymmetric) {
  stretch<2>(GeometryMode::axisymmetric, {1, 0, 0}, BarOrientation::hoop,
             "axisymmetric ring (hoop strain v_r/r)");
}
