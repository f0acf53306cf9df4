// A simply supported one-way RC slab strip (plane strain) under a short
// uniform pressure pulse: the peak mid-span
// deflection against Biggs' elastic-plastic single-degree-of-freedom estimate
// (load-mass factors of the simply supported beam under uniform load,
// resistance from the section's moment capacity), and the two rebar
// representations (steel layers sharing nodes, embedded bars) against each
// other. docs/theory/reinforcement.md, section 4.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/verification.hpp"
#include "mesh/rebar_layers.hpp"
#include "solver/rc_models.hpp"

using namespace camouflet;

namespace {

constexpr double span = 1.0;           // m, between the supports (half modelled, symmetry at mid-span)
constexpr double h = 0.1;              // m, slab thickness
constexpr double cover = 0.02;         // m, clear cover of both layers
constexpr double layer_area = 5.0e-4;  // m^2/m, steel area per metre width, each face
constexpr double p0 = 2.4e6;           // Pa, pulse magnitude
constexpr double t_d = 0.2e-3;         // s, pulse duration (rectangular, short against the period)
constexpr double support = 0.03;       // m, bottom length held vertically at the support (two nodes)
constexpr double t_end = 20e-3;        // s
// The elastic stand-in for the concrete (density of the RHT preset).
const test::ElasticConstants elastic_concrete{2314.0, 1.9e10, 1.45e10, 0.0};

struct SlabResult {
  double peak_deflection = 0.0;  // m, downwards, mid-span bottom
  double time_of_peak = 0.0;     // s
  double energy_error = 0.0;
};

Model slab_model(bool layers, bool elastic) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.mesh.dimension = 2;
  model.run.end_time = t_end;
  if (elastic)
    model.materials.push_back({"concrete", test::elastic_material(elastic_concrete), {}});
  else
    model.materials.push_back({"concrete", test::rate_free_concrete(1.0), {}});
  model.materials.push_back({"steel", test::steel_1006(), {}});
  model.parts.push_back(Part{"slab", PartKind::fem, 0, {}, {}, {}, {}, {}, {}, {}});
  model.parts.push_back(Part{"rebar", PartKind::fem, 1, {}, {}, {}, {}, {}, {}, {}});
  const double half = 0.5 * span;
  if (layers) {
    RebarWallSpec wall;
    wall.name = "slab";
    wall.concrete_part = 0;
    wall.size = {half, h, 0.0};
    wall.cells = {20, 6, 1};
    wall.layers = {{cover, layer_area, RebarFace::ymin, 1}, {cover, layer_area, RebarFace::ymax, 1}};
    add_rebar_wall(model.mesh, wall);
  } else {
    add_block(model.mesh, {"slab", 0, {0, 0, 0}, {half, h, 0}, {20, 6, 1}});
    for (double y : {cover + 0.5 * layer_area, h - cover - 0.5 * layer_area}) {
      BarSet bar;
      bar.name = y < 0.5 * h ? "bottom" : "top";
      bar.from = {0.0, y, 0.0};
      bar.to = {half, y, 0.0};
      bar.segments = 20;
      bar.area = layer_area;
      bar.material = 1;
      model.bars.push_back(bar);
    }
  }
  // Supports: the bottom nodes within `support` of the end, held vertically.
  auto& held = model.mesh.node_sets["support"];
  for (std::size_t n = 0; n < model.mesh.node_count(); ++n)
    if (model.mesh.coordinates[2 * n] <= support + 1e-9 && model.mesh.coordinates[2 * n + 1] <= 1e-9)
      held.push_back(static_cast<std::int64_t>(n));
  model.boundaries.push_back(test::velocity("support", 1, 0.0));
  model.boundaries.push_back(test::symmetry("slab.xmax", {1, 0, 0}));
  model.boundaries.push_back(
      test::pressure("slab.ymax", p0, TimeHistory{{0.0, t_d, t_d * 1.0001}, {1.0, 1.0, 0.0}}));
  return model;
}

SlabResult load_slab(bool layers, bool elastic) {
  test::use_threads(1);
  const Model model = slab_model(layers, elastic);
  Solver<2> solver(model);
  // Mid-span bottom node.
  std::size_t mid = 0;
  for (std::size_t n = 0; n < solver.node_count(); ++n)
    if (std::abs(solver.position()[2 * n] - 0.5 * span) < 1e-9 &&
        std::abs(solver.position()[2 * n + 1]) < 1e-9)
      mid = n;
  SlabResult r;
  while (solver.time() < t_end) {
    solver.step();
    const double w = -solver.displacement()[2 * mid + 1];
    if (w > r.peak_deflection) {
      r.peak_deflection = w;
      r.time_of_peak = solver.time();
    }
    if (std::getenv("RC_DEBUG") && solver.cycle() % 200 == 0) {
      double top = 0.0;
      for (std::size_t n = 0; n < solver.node_count(); ++n)
        if (std::abs(solver.position()[2 * n] - 0.5 * span) < 1e-3 && solver.position()[2 * n + 1] > 0.09)
          top = -solver.displacement()[2 * n + 1];
      double eps_bar = 0.0;
      for (std::size_t s = 0; s < solver.bars().segment_count(); ++s)
        eps_bar = std::max(eps_bar, solver.bars().plastic_strain(s));
      std::printf(
          "t %.3f ms w_bottom %.3f mm w_top %.3f mm vy %.3f bar eps_p %.4f E: kin %.4g int %.4g W %.4g\n",
          solver.time() * 1e3, w * 1e3, top * 1e3, solver.velocity()[2 * mid + 1], eps_bar,
          solver.energy().kinetic, solver.energy().internal, solver.energy().boundary_work);
    }
    if (solver.time() > r.time_of_peak + 2e-3 && r.peak_deflection > 0.0) break;  // past the peak
  }
  r.energy_error = solver.energy().relative_error;
  std::printf("%s: peak mid-span deflection %.4g mm at %.3g ms (%lld cycles), energy error %.2g\n",
              layers ? "steel layers" : "embedded bars", r.peak_deflection * 1e3, r.time_of_peak * 1e3,
              static_cast<long long>(solver.cycle()), r.energy_error);
  return r;
}

// Biggs (1964) SDOF of the simply supported strip per metre width under the
// uniform pulse: K_LM M y'' + R(y) = p(t) L, R elastic-perfectly plastic with
// K = 384 E I_avg / (5 L^3) and R_m = 8 M_p / L; K_LM = 0.78 elastic, 0.66
// plastic (Biggs, Table 5.1). docs/theory/reinforcement.md, section 4.
double sdof_peak_deflection(double e_concrete, double flow_stress, bool elastic = false) {
  const double rho = 2314.0;  // kg/m^3, the preset's initial (porous) density
  const double mass = rho * h * span;
  const double d = h - cover - 0.5 * layer_area;               // effective depth
  const double a = layer_area * flow_stress / (0.85 * 35e6);   // compression block depth
  const double mp = layer_area * flow_stress * (d - 0.5 * a);  // N m/m
  const double rm = 8.0 * mp / span;                           // N/m
  // Cracked transformed section (tension steel), averaged with the gross one.
  const double n = 200e9 / e_concrete;
  const double kd =
      (-n * layer_area + std::sqrt(std::pow(n * layer_area, 2) + 2.0 * n * layer_area * d)) / 1.0;
  const double i_cr = std::pow(kd, 3) / 3.0 + n * layer_area * std::pow(d - kd, 2);
  const double i_avg = 0.5 * (std::pow(h, 3) / 12.0 + i_cr);
  // Elastic stand-in: the uncracked transformed section (both layers), with
  // the plane-strain modulus E / (1 - nu^2) of the concrete.
  const double nu = (3.0 * elastic_concrete.bulk_modulus - 2.0 * elastic_concrete.shear_modulus) /
                    (2.0 * (3.0 * elastic_concrete.bulk_modulus + elastic_concrete.shear_modulus));
  const double e_plane = e_concrete / (1.0 - nu * nu);
  const double i_uncracked =
      std::pow(h, 3) / 12.0 + 2.0 * (200e9 / e_plane - 1.0) * layer_area * std::pow(0.5 * h - cover, 2);
  const double k = elastic ? 384.0 * e_plane * i_uncracked / (5.0 * std::pow(span, 3))
                           : 384.0 * e_concrete * i_avg / (5.0 * std::pow(span, 3));
  const double ye = rm / k;
  double y = 0.0, v = 0.0, t = 0.0, y_max = 0.0, y_plastic = 0.0;
  const double dt = 1e-7;
  while (t < 0.05) {
    const double load = t < t_d ? p0 * span : 0.0;
    double r = k * (y - y_plastic);
    if (!elastic && r > rm) {
      y_plastic = y - ye;
      r = rm;
    }
    const double klm = y_plastic > 0.0 ? 0.66 : 0.78;
    v += (load - r) / (klm * mass) * dt;
    y += v * dt;
    t += dt;
    y_max = std::max(y_max, y);
    if (v < 0.0) break;
  }
  std::printf("SDOF: M_p %.4g N m/m, R_m %.4g N/m, K %.4g N/m^2, y_e %.3g mm, peak %.4g mm\n", mp, rm, k,
              ye * 1e3, y_max * 1e3);
  return y_max;
}

}  // namespace

TEST(RcSlab, RhtConcreteAgainstBiggsSdof) {
  const SlabResult layered = std::getenv("RC_SLAB_EMBEDDED_ONLY") ? SlabResult{} : load_slab(true, false);
  const SlabResult embedded = load_slab(false, false);
  // Concrete modulus from the preset's elastic constants; steel flow stress
  // from Johnson-Cook at 1 % plastic strain and 10 /s (a representative
  // state of the yielded bottom steel; docs/theory/reinforcement.md).
  const auto concrete = test::rate_free_concrete(1.0);
  MaterialPoints pts;
  concrete->setup(pts, 1);
  const double bulk = pts.density[0] * pts.sound_speed[0] * pts.sound_speed[0], shear = pts.shear_modulus[0];
  const double e_concrete = 9.0 * bulk * shear / (3.0 * bulk + shear);
  const auto steel = test::steel_1006();
  const double flow = johnson_cook_yield(test::johnson_cook_of(*steel), 0.01, 10.0, 300.0);
  const double sdof = sdof_peak_deflection(e_concrete, flow);
  test::verify({"RC slab strip under a short pulse, steel layers: peak mid-span deflection",
                "Biggs elastic-plastic SDOF (docs/theory/reinforcement.md), +-30 %", sdof,
                layered.peak_deflection, 0.30, true, "m"});
  test::verify({"RC slab strip under a short pulse, embedded bars: peak mid-span deflection",
                "Biggs elastic-plastic SDOF (docs/theory/reinforcement.md), +-30 %", sdof,
                embedded.peak_deflection, 0.30, true, "m"});
  test::verify({"RC slab strip under a short pulse: embedded bars vs steel layers", "layer result, +-10 %",
                layered.peak_deflection, embedded.peak_deflection, 0.10, true, "m"});
}

// The same strip with an elastic stand-in for the concrete: the rebar
// representations in bending against each other, and the elastic SDOF
// (K_LM = 0.78, uncracked transformed section) for the peak deflection.
TEST(RcSlab, ElasticConcreteAgainstSdofAndBetweenRebarModels) {
  const SlabResult layered = std::getenv("RC_SLAB_EMBEDDED_ONLY") ? SlabResult{} : load_slab(true, true);
  const SlabResult embedded = load_slab(false, true);
  const double k = elastic_concrete.bulk_modulus, g = elastic_concrete.shear_modulus;
  const double sdof = sdof_peak_deflection(9.0 * k * g / (3.0 * k + g), 0.0, true);
  test::verify(
      {"RC slab strip (elastic concrete) under a short pulse, steel layers: peak mid-span deflection",
       "Biggs elastic SDOF, K_LM = 0.78 (docs/theory/reinforcement.md), +-30 %", sdof,
       layered.peak_deflection, 0.30, true, "m"});
  test::verify(
      {"RC slab strip (elastic concrete) under a short pulse, embedded bars: peak mid-span deflection",
       "Biggs elastic SDOF, K_LM = 0.78 (docs/theory/reinforcement.md), +-30 %", sdof,
       embedded.peak_deflection, 0.30, true, "m"});
  test::verify({"RC slab strip (elastic concrete) under a short pulse: embedded bars vs steel layers",
                "layer result, +-10 %", layered.peak_deflection, embedded.peak_deflection, 0.10, true, "m"});
  EXPECT_LT(layered.energy_error, 0.01);
  EXPECT_LT(embedded.energy_error, 0.01);
}
