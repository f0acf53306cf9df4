// A reinforced-concrete tie pulled apart:
// once the concrete has cracked through, the section at the crack carries
// only the steel, so its force must equal the steel area times the
// Johnson-Cook flow stress at the steel's plastic strain, plastic strain rate
// and temperature. Both rebar representations: thin steel layers sharing
// nodes with the concrete (3-D), and embedded bar elements (plane strain and
// 3-D). docs/theory/reinforcement.md, section 5.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "common/verification.hpp"
#include "mesh/rebar_layers.hpp"
#include "solver/rc_models.hpp"

using namespace camouflet;

namespace {

constexpr double length = 0.19;    // m, along x
constexpr double crack_x0 = 0.09;  // m, the measured crack column spans [0.09, 0.10]
constexpr double thickness = 0.1;  // m, along y
constexpr double depth = 0.1;      // m, along z (3-D, embedded bars)
// A steel layer is a plate: where it yields over a short length (the crack)
// its wide neighbours hold its lateral contraction, and it flows in plane
// strain at 2/sqrt(3) Y. The layer tie is therefore a narrow slice, a strip
// of one bar's worth of layer, and the weak (cracking) zone is three
// columns long.
constexpr double layer_depth = 0.005;  // m, along z (3-D, steel layers)
constexpr double cover = 0.03;         // m
constexpr double layer_area = 1.0e-3;  // m^2/m, steel area per unit width of each layer
constexpr double pull = 1.0;           // m/s, right end
constexpr double ramp = 50e-6;         // s
constexpr double target_plastic_strain = 0.005;

struct TieResult {
  double section_force = 0.0;   // N (per metre of depth in plane strain)
  double steel_expected = 0.0;  // N, A_s Y_JC
  double concrete_force = 0.0;  // N, the concrete's share of the section force
  double plastic_strain = 0.0;  // of the steel at the crack
  double area_ratio = 0.0;      // current / initial steel area at the crack
  double energy_error = 0.0;
};

template <int D>
Model tie_model(bool layers) {
  Model model;
  model.run.mode = D == 3 ? GeometryMode::three_d : GeometryMode::plane_strain;
  model.mesh.dimension = D;
  model.run.end_time = 1.0;
  if (std::getenv("RC_ELASTIC")) {
    model.materials.push_back({"concrete", test::elastic_material({2300.0, 2e10, 1.5e10, 0.0}), {}});
    model.materials.push_back({"seed", test::elastic_material({2300.0, 2e10, 1.5e10, 0.0}), {}});
  } else {
    model.materials.push_back({"concrete", test::rate_free_concrete(1.0), {}});
    model.materials.push_back({"seed", test::rate_free_concrete(0.5), {}});
    // Cracked-through concrete is eroded, so the crack carries nothing but steel.
    model.erosion = {{0.0, 0.99}, {0.0, 0.99}};
  }
  model.materials.push_back({"steel", test::steel_1006(), {}});
  model.parts.push_back(Part{"left", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"seed", PartKind::fem, 1, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"right", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"rebar", PartKind::fem, 2, {}, {}, {}, {}, {}, {}, {}});
  // The weak seed spans three columns, [0.08, 0.11]; the crack is measured
  // in its middle column, [0.09, 0.10], whose steel neighbours yield too, so
  // the layer there can contract freely.
  const double xs[3] = {0.0, crack_x0 - 0.01, crack_x0 + 0.02};
  const double widths[3] = {crack_x0 - 0.01, 0.03, length - crack_x0 - 0.02};
  const int cells[3] = {D == 3 ? 3 : 8, 3, D == 3 ? 3 : 8};
  const char* names[3] = {"left", "seed", "right"};
  for (int k = 0; k < 3; ++k) {
    if (layers) {
      RebarWallSpec wall;
      wall.name = names[k];
      wall.concrete_part = k;
      wall.origin = {xs[k], 0.0, 0.0};
      wall.size = {widths[k], thickness, layer_depth};
      wall.cells = {cells[k], 6, 1};
      wall.layers = {{cover, layer_area, RebarFace::ymin, 3}, {cover, layer_area, RebarFace::ymax, 3}};
      add_rebar_wall(model.mesh, wall);
    } else {
      add_block(
          model.mesh,
          {names[k], k, {xs[k], 0.0, 0.0}, {widths[k], thickness, depth}, {cells[k], D == 3 ? 6 : 10, 1}});
    }
    model.boundaries.push_back(test::symmetry(std::string(names[k]) + ".ymin", {0, 1, 0}));
    if (D == 3) model.boundaries.push_back(test::symmetry(std::string(names[k]) + ".zmin", {0, 0, 1}));
  }
  model.boundaries.push_back(test::symmetry("left.xmin", {1, 0, 0}));
  model.boundaries.push_back(test::ramped_velocity("right.xmax", 0, pull, ramp));
  if (!layers) {
    // The same steel area as the layers: per metre of depth in plane strain,
    // four bars of a quarter each in 3-D.
    std::vector<std::array<double, 2>> lines;  // (y, z)
    for (double y : {cover, thickness - cover})
      if (D == 2)
        lines.push_back({y, 0.0});
      else
        for (double z : {0.25 * depth, 0.75 * depth}) lines.push_back({y, z});
    const double area = D == 2 ? layer_area : layer_area * depth / 2.0;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      BarSet bar;
      bar.name = fmt::format("bar{}", k);
      bar.from = {0.0, lines[k][0], lines[k][1]};
      bar.to = {length, lines[k][0], lines[k][1]};
      bar.segments = 19;
      bar.area = area;
      bar.material = 2;
      model.bars.push_back(bar);
    }
  }
  return model;
}

template <int D>
TieResult pull_tie(bool layers) {
  test::use_threads(1);
  const Model model = tie_model<D>(layers);
  Solver<D> solver(model);
  const auto& jc = test::johnson_cook_of(*model.materials[2].material);
  constexpr int N = FemElements<D>::nodes;
  // The crack column: elements whose centre lies in the seed's x range.
  std::vector<std::size_t> column;
  for (std::size_t e = 0; e < solver.elements().size(); ++e) {
    double xc = 0.0;
    for (int a = 0; a < N; ++a)
      xc += solver.position()[static_cast<std::size_t>(solver.elements().connectivity[e * N + a] * D)] / N;
    if (xc > crack_x0 && xc < crack_x0 + 0.01) column.push_back(e);
  }
  std::vector<std::size_t> crack_segments;
  for (std::size_t s = 0; s < solver.bars().segment_count(); ++s)
    if (s % 19 == 9) crack_segments.push_back(s);  // segment 10 of each bar spans the seed column
  const double steel_area = 2.0 * layer_area * (D == 3 ? (layers ? layer_depth : depth) : 1.0);
  TieResult r;
  while (solver.time() < 3e-3) {
    solver.step();
    double section = 0.0, concrete = 0.0, yield = 0.0, eps = 0.0, area = 0.0;
    int steel_points = 0;
    for (std::size_t e : column) {
      const double f = test::element_axial_force(solver, e);
      section += f;
      const int m = solver.elements().material[e];
      if (m != 2) {
        concrete += f;
        continue;
      }
      const MaterialPoints& pts = solver.batches()[2];
      const std::size_t p = solver.elements().point[e];
      const double a = test::element_cross_section(solver, e);
      yield +=
          johnson_cook_yield(jc, pts.plastic_strain[p], pts.plastic_strain_rate[p], pts.temperature[p]) * a;
      area += a;
      eps += pts.plastic_strain[p];
      ++steel_points;
    }
    for (std::size_t s : crack_segments) {
      section += solver.bars().axial_force(s);
      yield += johnson_cook_yield(jc, solver.bars().plastic_strain(s), solver.bars().plastic_strain_rate(s),
                                  solver.bars().temperature(s)) *
               solver.bars().axial_force(s) / solver.bars().axial_stress(s);  // x its current area
      area += solver.bars().axial_force(s) / solver.bars().axial_stress(s);
      eps += solver.bars().plastic_strain(s);
      ++steel_points;
    }
    r = {section, yield, concrete, eps / steel_points, area / steel_area, solver.energy().relative_error};
    if (r.plastic_strain >= target_plastic_strain && std::abs(concrete) < 0.01 * std::abs(section)) break;
  }
  const auto& en = solver.energy();
  std::printf("energy: kin %.4g int %.4g hg %.4g visc %.4g eroded %.4g W %.4g E0 %.4g\n", en.kinetic,
              en.internal, en.hourglass, en.viscous, en.eroded, en.boundary_work, en.initial_total);
  double dmin = 1.0, dmax = 0.0;
  for (std::size_t e : column)
    if (solver.elements().material[e] != 2) {
      const auto m = static_cast<std::size_t>(solver.elements().material[e]);
      const double d = solver.batches()[m].damage[solver.elements().point[e]];
      dmin = std::min(dmin, d);
      dmax = std::max(dmax, d);
    }
  for (std::size_t e : column)
    if (std::getenv("RC_DEBUG")) {
      const auto& st = solver.elements().stress[e];
      std::printf("  e %zu mat %d sxx %.4g syy %.4g szz %.4g sxy %.3g\n", e, solver.elements().material[e],
                  st.xx, st.yy, st.zz, st.xy);
    }
  std::printf("crack concrete damage %.4f .. %.4f, eroded %zu\n", dmin, dmax, solver.eroded_count());
  std::printf(
      "t = %.3g ms: section force %.5g N, A_s Y_JC %.5g N, concrete %.4g N, eps_p %.4f, area ratio %.4f, "
      "energy error %.2g\n",
      solver.time() * 1e3, r.section_force, r.steel_expected, r.concrete_force, r.plastic_strain,
      r.area_ratio, r.energy_error);
  return r;
}

void check(const TieResult& r, const std::string& name) {
  EXPECT_GE(r.plastic_strain, target_plastic_strain) << name << ": the steel never reached the target strain";
  // The modelled steel area is the rebar area (less the Poisson and plastic contraction).
  EXPECT_GT(r.area_ratio, 1.0 - 3.0 * r.plastic_strain - 0.01) << name;
  EXPECT_LE(r.area_ratio, 1.0) << name;
  test::verify({"RC tie in tension, " + name + ": force at the crack after the concrete failed",
                "steel area x Johnson-Cook flow stress (Steel 1006, Wang et al. 2005 Table 4)",
                r.steel_expected, r.section_force, 0.03, true, "N"});
  test::verify({"RC tie in tension, " + name + ": energy balance (with eroded concrete)",
                "closed (relative error)", 0.0, r.energy_error, 0.01, false, "-"});
}

}  // namespace

TEST(RcTension, SteelLayersSharingNodes3d) {
  check(pull_tie<3>(true), "steel layers sharing nodes (3-D)");
}

TEST(RcTension, EmbeddedBarsPlaneStrain) {
  check(pull_tie<2>(false), "embedded bars (plane strain)");
}

TEST(RcTension, EmbeddedBars3d) {
  check(pull_tie<3>(false), "embedded bars (3-D)");
}
