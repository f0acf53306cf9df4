// Patch tests of the one-point elements:
// a uniform velocity gradient imposed on every node of a distorted mesh gives
// the same stress in every element, in plane strain, axisymmetric and 3-D.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "fem/shape.hpp"
#include "solver/solver.hpp"

using namespace camouflet;
using camouflet::test::ElasticConstants;

namespace {

// Moves every node not on the block boundary by up to `fraction` of the cell size.
void distort_interior(FemMesh& mesh, double lo, double hi, double cell, double fraction) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-fraction * cell, fraction * cell);
  const std::size_t d = static_cast<std::size_t>(mesh.dimension);
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    bool interior = true;
    for (std::size_t i = 0; i < d; ++i) {
      const double x = mesh.coordinates[n * d + i];
      interior = interior && x > lo + 1e-9 && x < hi - 1e-9;
    }
    if (interior)
      for (std::size_t i = 0; i < d; ++i) mesh.coordinates[n * d + i] += u(rng);
  }
}

// Prescribes v = L x (x at t = 0) on every node through one velocity condition per node.
void impose_linear_velocity(Model& model, const double (&L)[3][3]) {
  const std::size_t d = static_cast<std::size_t>(model.mesh.dimension);
  for (std::size_t n = 0; n < model.mesh.node_count(); ++n) {
    const std::string set = "node" + std::to_string(n);
    model.mesh.node_sets[set] = {static_cast<std::int64_t>(n)};
    BoundaryCondition bc;
    bc.kind = BoundaryKind::velocity;
    bc.set = set;
    for (std::size_t i = 0; i < d; ++i) {
      bc.components[i] = true;
      for (std::size_t j = 0; j < d; ++j) bc.value[i] += L[i][j] * model.mesh.coordinates[n * d + j];
    }
    model.boundaries.push_back(bc);
  }
}

template <int D>
double largest_stress_deviation(const Solver<D>& solver) {
  const auto& stress = solver.elements().stress;
  const SymTensor ref = stress.front();
  const double scale = std::sqrt(contract(ref, ref));
  double worst = 0.0;
  for (const auto& s : stress) {
    const SymTensor diff = s - ref;
    worst = std::max(worst, std::sqrt(contract(diff, diff)) / scale);
  }
  return worst;
}

template <int D>
void run_patch(Model& model, const std::string& problem) {
  test::use_threads(1);
  model.run.end_time = 1.0;
  model.run.hourglass = HourglassForm::viscous;
  Solver<D> solver(model);
  for (int k = 0; k < 5; ++k) solver.step();
  const double deviation = largest_stress_deviation(solver);
  test::verify({problem + ": spread of element stress after 5 cycles", "uniform stress (exact)", 0.0,
                deviation, 1e-10, false, "relative"});
  // The stress is the one the strain rate asks for (not just uniform zero).
  const SymTensor s = solver.elements().stress.front();
  EXPECT_GT(std::sqrt(contract(s, s)), 1e3);
}

}  // namespace

TEST(PatchTest, DistortedQuadsPlaneStrain) {
  ElasticConstants c;
  Model model =
      test::block_model(GeometryMode::plane_strain, {{"patch", 0, {0, 0, 0}, {1, 1, 0}, {4, 4, 1}}}, c);
  distort_interior(model.mesh, 0.0, 1.0, 0.25, 0.2);
  const double L[3][3] = {{10.0, 3.0, 0}, {-2.0, -4.0, 0}, {0, 0, 0}};
  impose_linear_velocity(model, L);
  run_patch<2>(model, "Patch test, plane-strain quad4");
}

TEST(PatchTest, DistortedQuadsAxisymmetric) {
  ElasticConstants c;
  Model model =
      test::block_model(GeometryMode::axisymmetric, {{"patch", 0, {0.5, 0, 0}, {1, 1, 0}, {4, 4, 1}}}, c);
  distort_interior(model.mesh, 0.0, 1.5, 0.25, 0.2);
  // v_r = a r (uniform hoop rate a), v_z = b z + c r.
  const double L[3][3] = {{10.0, 0, 0}, {3.0, -4.0, 0}, {0, 0, 0}};
  impose_linear_velocity(model, L);
  run_patch<2>(model, "Patch test, axisymmetric quad4");
}

TEST(PatchTest, DistortedHexes) {
  ElasticConstants c;
  Model model = test::block_model(GeometryMode::three_d, {{"patch", 0, {0, 0, 0}, {1, 1, 1}, {3, 3, 3}}}, c);
  distort_interior(model.mesh, 0.0, 1.0, 1.0 / 3.0, 0.2);
  const double L[3][3] = {{10.0, 3.0, -1.0}, {-2.0, -4.0, 2.0}, {5.0, 1.0, 6.0}};
  impose_linear_velocity(model, L);
  run_patch<3>(model, "Patch test, hex8");
}

TEST(HexGeometry, UniformGradientsReproduceLinearFieldsAndVolume) {
  // A distorted hexahedron: sum_a x_ja b_ia = delta_ij, sum_a b_ia = 0, and the
  // volume equals 2x2x2 Gauss quadrature of det J (exact for the trilinear map).
  double x[3][8] = {{0, 1.1, 1.0, -0.1, 0.05, 1.2, 0.9, 0.0},
                    {0, 0.1, 1.2, 0.9, -0.05, 0.0, 1.1, 1.0},
                    {0, -0.1, 0.05, 0.1, 1.0, 1.1, 0.95, 1.2}};
  double b[3][8];
  const double volume = Shape<3>::gradients(x, b);
  for (int i = 0; i < 3; ++i) {
    double sum = 0.0;
    for (int a = 0; a < 8; ++a) sum += b[i][a];
    EXPECT_NEAR(sum, 0.0, 1e-13);
    for (int j = 0; j < 3; ++j) {
      double s = 0.0;
      for (int a = 0; a < 8; ++a) s += x[j][a] * b[i][a];
      EXPECT_NEAR(s, i == j ? 1.0 : 0.0, 1e-13);
    }
  }
  const double xi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  double exact = 0.0;
  for (int p = 0; p < 8; ++p) {
    double J[3][3] = {};
    for (int a = 0; a < 8; ++a) {
      const double s = xi[p][0] * g, t = xi[p][1] * g, u = xi[p][2] * g;
      const double dN[3] = {xi[a][0] * (1 + xi[a][1] * t) * (1 + xi[a][2] * u) / 8,
                            xi[a][1] * (1 + xi[a][0] * s) * (1 + xi[a][2] * u) / 8,
                            xi[a][2] * (1 + xi[a][0] * s) * (1 + xi[a][1] * t) / 8};
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) J[i][k] += x[i][a] * dN[k];
    }
    exact += J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
             J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
             J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  }
  test::verify({"Hex8 volume of a distorted element", "2x2x2 Gauss quadrature of det J (exact)", exact,
                volume, 1e-12, true, "m^3"});
}
