// Energy of the subzonal pressures and the edge viscosity (fem/subzonal_pressure.hpp,
// fem/edge_viscosity.hpp) in a box of gas stirred by random node velocities.
#include <gtest/gtest.h>

#include <random>

#include "../sph/sph_test_models.hpp"
#include "common/fem_models.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

struct Stirred {
  double relative_error = 0.0, residual = 0.0, viscous = 0.0, kinetic_start = 0.0;
};

template <int D>
Stirred stir(double subzonal, ViscosityForm form, HourglassForm hg, int cycles) {
  test::use_threads(1);
  Model model;
  model.run.mode = D == 2 ? GeometryMode::plane_strain : GeometryMode::three_d;
  model.mesh.dimension = D;
  model.run.end_time = 1.0;
  model.run.max_cycles = cycles;
  model.run.cfl = 0.5;
  model.run.subzonal_pressure = subzonal;
  model.run.viscosity_form = form;
  model.run.hourglass = hg;
  add_block(model.mesh, {"gas", 0, {0, 0, 0}, {1.0, 1.0, 1.0}, {8, 8, D == 2 ? 1 : 8}});
  model.materials.push_back({"gas", test::ideal_gas("gas", 1.0, 1.4, 2.5), {}});  // p = 1, c = 1.18
  Part part;
  part.name = "gas";
  part.material = 0;
  model.parts.push_back(part);
  // A closed box: the gas is stirred, not released.
  for (int i = 0; i < D; ++i) {
    std::array<double, 3> normal{};
    normal[static_cast<std::size_t>(i)] = 1.0;
    const std::string axis = i == 0 ? "x" : i == 1 ? "y" : "z";
    model.boundaries.push_back(test::symmetry("gas." + axis + "min", normal));
    model.boundaries.push_back(test::symmetry("gas." + axis + "max", normal));
  }
  Solver<D> solver(model);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::vector<double> v(solver.velocity().size());
  for (double& x : v) x = u(rng);
  solver.set_initial_velocity(v);
  Stirred s;
  s.kinetic_start = solver.energy().kinetic;
  while (solver.cycle() < cycles) solver.step();
  s.relative_error = solver.energy().relative_error;
  s.residual = s.relative_error * solver.energy().initial_total;  // J
  s.viscous = solver.energy().viscous;
  return s;
}

}  // namespace

// The subzonal forces' work goes into the elements: the balance closes to 2.5e-5 (plane) and
// 4.8e-5 (3-D) of the total energy, where leaving that work out of the internal energy misses by
// 5.7e-4 and 2.1e-3 (measured on 6 Dec 2026). The bound, 1e-4 of the total, is 2.5 % of the
// energy the stirring starts with.
TEST(SubzonalPressure, ConservesEnergyInAStirredBox) {
  const Stirred plane = stir<2>(1.0, ViscosityForm::acceleration, HourglassForm::none, 400);
  const Stirred solid = stir<3>(1.0, ViscosityForm::acceleration, HourglassForm::none, 200);
  EXPECT_LT(std::abs(plane.relative_error), 1e-4);
  EXPECT_LT(std::abs(solid.relative_error), 1e-4);
}

// The edge forces' work heats the elements: the balance misses by a few per cent of the energy
// the edge viscosity dissipates (the time discretisation of a force that depends on the
// velocity; the scalar q in the same box misses by 5 % (plane) and 70 % (3-D) of its own), where
// heat of the wrong sign or of one half-step would miss by 100 % or more.
TEST(EdgeViscosity, ConservesEnergyInAStirredBox) {
  for (const Stirred& s : {stir<2>(0.0, ViscosityForm::edge, HourglassForm::none, 400),
                           stir<3>(0.0, ViscosityForm::edge, HourglassForm::none, 200)}) {
    EXPECT_GT(s.viscous, 0.9 * s.kinetic_start);  // it takes nearly all the stirring
    EXPECT_LT(std::abs(s.residual), 0.1 * s.viscous);
  }
}
