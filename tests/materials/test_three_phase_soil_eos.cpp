// Three-phase soil EOS (Wang et al. 2005, eqs. 11-17): hydrostatic loading,
// hand-derived initial stiffness, high-pressure limit, Tait water limit,
// unloading rule and sound speed.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/verification.hpp"
#include "soil_test_support.hpp"

namespace camouflet::test {
namespace {

// Evaluates the EOS at each density on fresh points (predictor: history untouched).
std::vector<double> pressures_at(const EquationOfState& eos, const std::vector<double>& densities,
                                 std::vector<double>* sound_speeds = nullptr) {
  Material m("soil", std::shared_ptr<const EquationOfState>(&eos, [](const EquationOfState*) {}));
  MaterialPoints pts;
  m.setup(pts, densities.size());
  pts.density = densities;
  eos.evaluate(pts, MaterialContext{}, false);
  if (sound_speeds) *sound_speeds = pts.sound_speed;
  return pts.pressure;
}

TEST(ThreePhaseSoilEos, ReferenceDensityOfSandyClay) {
  const auto eos = soil_eos();
  verify({"Sandy clay reference density from the volume fractions",
          "0.58*2650 + 0.38*1000 + 0.04*1.2 (Table 2)", 1917.048, eos->reference_density(), 1e-9, true,
          "kg/m^3"});
  verify({"Sandy clay reference density vs Table 1", "rho0 ~ 1920 kg/m^3 (Wang et al. 2005, Table 1)", 1920.0,
          eos->reference_density(), 0.005, true, "kg/m^3"});
}

TEST(ThreePhaseSoilEos, InitialTangentBulkModulusMatchesHandDerivation) {
  const auto eos = soil_eos();
  const HandSoil h;
  // Hand derivation (docs/theory/three-phase-soil.md, "Initial stiffness").
  const double fluid = 1.0 / (h.aw / h.Kw + h.ag / (h.kg * h.p0));
  const double pore = fluid + h.fKp + h.E0 / (h.aw + h.ag);
  const double k_hand = 1.0 / (h.as / h.Ks + 1.0 / pore);
  EXPECT_NEAR(k_hand, 143.27e6, 0.01e6);
  const double rho0 = eos->reference_density();
  const double strain = 1e-7;
  std::vector<double> c;
  const auto p = pressures_at(*eos, {rho0 * (1.0 + strain)}, &c);
  verify({"Three-phase soil: initial tangent bulk modulus, finite difference of p(rho)",
          "hand derivation 1/(a_s/K_s + 1/(K_f + f K_p + E0/a_p))", k_hand, p[0] / strain, 0.01, true, "Pa"});
  verify({"Three-phase soil: initial tangent bulk modulus from the loading sound speed", "hand derivation",
          k_hand, rho0 * (1.0 + strain) * c[0] * c[0], 0.01, true, "Pa"});
}

TEST(ThreePhaseSoilEos, HydrostaticLoadingIsMonotoneAndMatchesTheExplicitCurve) {
  const auto eos = soil_eos();
  Material m("soil", eos);
  MaterialPoints pts;
  m.setup(pts, 1);
  const double rho0 = eos->reference_density();
  // Committed loading from 1 atm to beyond 10 GPa (rho ~ 2650 kg/m^3).
  const int steps = 3000;
  const double rho_end = 1.45 * rho0;
  double previous = pts.pressure[0];
  bool monotone = true;
  for (int k = 1; k <= steps; ++k) {
    pts.density_previous[0] = pts.density[0];
    pts.density[0] = rho0 * std::pow(rho_end / rho0, static_cast<double>(k) / steps);
    eos->evaluate(pts, MaterialContext{}, true);
    monotone = monotone && pts.pressure[0] > previous;
    previous = pts.pressure[0];
  }
  record_check("Three-phase soil: hydrostatic p(rho) from 1 atm to 10 GPa", "strictly increasing",
               monotone ? "strictly increasing over 3000 steps" : "not monotone", monotone);
  EXPECT_TRUE(monotone);
  EXPECT_GT(previous, 10e9);

  // The root solve against the explicit parametric curve (pore pressure -> v, p).
  const HandSoil h;
  std::vector<double> densities, expected;
  for (double pb : {2e5, 1e6, 1e7, 1e8, 1e9, 1e10}) {
    double p_abs = 0.0;
    const double v = h.loading(pb, 0.0, p_abs);
    densities.push_back(rho0 / v);
    expected.push_back(p_abs - h.p0);
  }
  const auto p = pressures_at(*eos, densities);
  double worst = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    worst = std::max(worst, std::abs(p[k] - expected[k]) / expected[k]);
  verify({"Three-phase soil: loading curve by root solve vs explicit parametric curve (0.1 MPa - 10 GPa)",
          "eqs. 11-17 tabulated in the pore pressure", 0.0, worst, 1e-8, false, "relative"});
}

TEST(ThreePhaseSoilEos, HighPressureApproachesWaterSolidMixture) {
  const auto eos = soil_eos();
  const HandSoil h;
  const double mass = h.as * 2650.0 + h.aw * 1000.0 + h.ag * 1.2;  // kg per m^3 of initial volume
  for (double p_gauge : {1e9, 1e10}) {
    const double p = p_gauge + h.p0;
    // Water-solid mixture with the air voids closed: volumes add at equal pressure.
    const double v_mix = h.vw(p) + h.vs(p);
    const double rho_mix = mass / v_mix;
    std::vector<double> c;
    const auto model = pressures_at(*eos, {rho_mix}, &c);
    verify({fmt::format("Three-phase soil at {:.0f} GPa: pressure at the water-solid mixture density",
                        p_gauge / 1e9),
            "water + grains at equal pressure (air voids closed)", p_gauge, model[0], 0.05, true, "Pa"});
    // Wood's law: the mixture compliance is the volume-weighted phase compliance.
    const double wood = v_mix / (h.vw(p) / (h.Kw + h.kw * (p - h.p0)) + h.vs(p) / (h.Ks + h.ks * (p - h.p0)));
    verify({fmt::format("Three-phase soil at {:.0f} GPa: tangent bulk modulus", p_gauge / 1e9),
            "Wood's law for water + grains", wood, rho_mix * c[0] * c[0], 0.05, true, "Pa"});
  }
  // At low pressure the air and skeleton dominate: far from the mixture (the check above is meaningful).
  const double p_low = 1e6 + h.p0;
  const auto low = pressures_at(*eos, {mass / (h.vw(p_low) + h.vs(p_low))});
  const bool far = low[0] > 10.0 * 1e6;
  record_check("Three-phase soil at 1 MPa: mixture limit not yet reached", "air voids open below ~5 MPa",
               fmt::format("model p = {:.3g} Pa at the mixture density of 1 MPa", low[0]), far);
  EXPECT_TRUE(far);
}

TEST(ThreePhaseSoilEos, WaterOnlyReproducesTait) {
  Parameters block = soil_eos_block();
  block.set_number("solid_fraction", 0.0);
  block.set_number("water_fraction", 1.0);
  block.set_number("air_fraction", 0.0);
  block.set_number("friction_coefficient", 0.0);
  block.set_number("bond_modulus", 0.0);
  const auto eos = soil_eos(block);
  EXPECT_DOUBLE_EQ(eos->reference_density(), 1000.0);
  const double K = 1000.0 * 1500.0 * 1500.0;
  std::vector<double> densities, expected;
  for (double r : {1.0001, 1.01, 1.1, 1.3, 1.6, 2.0}) {
    densities.push_back(1000.0 * r);
    expected.push_back(K / 7.0 * (std::pow(r, 7.0) - 1.0));  // eq. 13
  }
  const auto p = pressures_at(*eos, densities);
  double worst = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    worst = std::max(worst, std::abs(p[k] - expected[k]) / expected[k]);
  verify({"Three-phase soil with water only: p(rho) vs Tait (eq. 13), rho/rho0 = 1.0001-2",
          "p = rho0 c0^2/k ((rho/rho0)^k - 1)", 0.0, worst, 1e-9, false, "relative"});
}

// Loads to 100 MPa, then unloads: water and grains expand elastically from the
// maximum compaction, the compacted air voids and the skeleton stay (theory
// section, "Unloading").
TEST(ThreePhaseSoilEos, UnloadingFrom100MPaFollowsTheWaterSolidRule) {
  const auto eos = soil_eos();
  const HandSoil h;
  const double rho0 = eos->reference_density();
  Material m("soil", eos);
  MaterialPoints pts;
  m.setup(pts, 1);
  const double pb_max = h.pore_pressure_at(100e6 + h.p0);
  double p_max = 0.0;
  const double v_min = h.loading(pb_max, 0.0, p_max);
  for (int k = 1; k <= 200; ++k) {
    pts.density[0] = rho0 / (1.0 - (1.0 - v_min) * k / 200.0);
    eos->evaluate(pts, MaterialContext{}, true);
  }
  verify({"Three-phase soil: loading to 100 MPa", "explicit loading curve", 100e6, pts.pressure[0], 1e-8,
          true, "Pa"});

  // The rule: v(p) = v_min + [v_w(p_b) - v_w(p_b,max)] + [v_s(p) - v_s(p_max)],
  // p_b = max(p_b,max + p - p_max, 0): the pore water cavitates at zero absolute pressure.
  auto v_rule = [&](double p) {
    return v_min + (h.vw(std::max(pb_max + p - p_max, 0.0)) - h.vw(pb_max)) + (h.vs(p) - h.vs(p_max));
  };
  double worst = 0.0;
  for (double p_gauge : {80e6, 50e6, 20e6, 5e6, 1e6}) {
    pts.density[0] = rho0 / v_rule(p_gauge + h.p0);
    eos->evaluate(pts, MaterialContext{}, true);
    worst = std::max(worst, std::abs(pts.pressure[0] - p_gauge) / p_gauge);
  }
  verify({"Three-phase soil: unloading path from 100 MPa", "water-solid elastic unloading rule", 0.0, worst,
          1e-7, false, "relative"});

  // Residual compaction where the unloading branch reaches zero (gauge) pressure.
  const double v_residual = v_rule(h.p0);
  double lo = v_min, hi = 1.0;  // find p = 0 on the model by bisection in volume
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    pts.density[0] = rho0 / mid;
    eos->evaluate(pts, MaterialContext{}, false);
    (pts.pressure[0] > 0.0 ? lo : hi) = mid;
  }
  verify({"Three-phase soil: residual volumetric compaction after unloading from 100 MPa",
          "1 - v(p=0) of the unloading rule", 1.0 - v_residual, 1.0 - lo, 1e-6, true, ""});
  EXPECT_GT(1.0 - v_residual, 0.03);  // the compacted air voids (4 %) stay mostly closed

  // Reloading follows the same branch, then continues on the loading curve.
  pts.density[0] = rho0 / v_rule(50e6 + h.p0);
  eos->evaluate(pts, MaterialContext{}, true);
  EXPECT_NEAR(pts.pressure[0], 50e6, 50.0);
  double p_beyond = 0.0;
  const double v_beyond = h.loading(h.pore_pressure_at(150e6 + h.p0), 0.0, p_beyond);
  pts.density[0] = rho0 / v_beyond;
  eos->evaluate(pts, MaterialContext{}, true);
  verify({"Three-phase soil: reloading past the maximum compaction", "loading curve at 150 MPa", 150e6,
          pts.pressure[0], 1e-8, true, "Pa"});

  // Far expansion: tension cut-off at -k/(3 alpha) (intact bonds).
  pts.density[0] = rho0 * 0.9;
  eos->evaluate(pts, MaterialContext{}, true);
  verify({"Three-phase soil: tension cut-off", "-(1 - D) p_t, p_t = k/(3 alpha)", -0.2e6 / 0.75,
          pts.pressure[0], 1e-12, true, "Pa"});
}

// The sound speed is the tangent dp/drho of the branch the point is on (the
// viscosities and dashpots use it); the stable sound speed, which the time
// step takes, is the stiffest tangent the release from the point can meet:
// never below the local tangent anywhere on the branch from the maximum
// compaction down to the tension cut-off, equal to it on the stretch where
// the pore water has cavitated (grains alone), and no stiffer than that.
// Finite differences along the whole branch.
TEST(ThreePhaseSoilEos, SoundSpeedIsTheBranchTangentAndTheStableOneBoundsTheRelease) {
  const auto eos = soil_eos();
  const double rho0 = eos->reference_density();
  Material m("soil", eos);
  MaterialPoints pts;
  m.setup(pts, 1);
  pts.density[0] = 1.05 * rho0;  // loading to ~ tens of MPa
  eos->evaluate(pts, MaterialContext{}, true);
  const double rho_max = pts.density[0];
  const double c_release = pts.stable_sound_speed[0];  // at the maximum, after the commit
  double c_stable = 0.0;
  auto probe = [&](double rho, double& p, double& c) {
    pts.density[0] = rho;
    eos->evaluate(pts, MaterialContext{}, false);
    p = pts.pressure[0];
    c = pts.sound_speed[0];
    c_stable = pts.stable_sound_speed[0];
  };
  double p1, p2, c1, c2;
  const double d = 1e-7 * rho_max;
  probe(rho_max * 1.01, p1, c1);  // loading
  probe(rho_max * 1.01 + d, p2, c2);
  verify({"Three-phase soil: loading sound speed", "c^2 = dp/drho (finite difference)", (p2 - p1) / d,
          c1 * c1, 1e-4, true, "m^2/s^2"});
  probe(rho_max * 0.9999, p1, c1);  // unloading, the water-solid stretch
  probe(rho_max * 0.9999 + d, p2, c2);
  verify({"Three-phase soil: unloading sound speed", "c^2 = dp/drho (finite difference)", (p2 - p1) / d,
          c1 * c1, 1e-4, true, "m^2/s^2"});

  // Walk the release branch from rho_max to the cut-off.
  double worst_under = 0.0, stiffest = 0.0, cavitated_error = 0.0;
  int cavitated = 0, water = 0;
  for (int k = 1; k <= 10000; ++k) {
    const double rho = rho_max * (1.0 - 2e-6 * k);
    probe(rho - d, p1, c1);
    probe(rho, p2, c2);
    if (p1 <= -0.2e6 / 0.75 * (1.0 - 1e-9)) break;  // the cut-off (intact bonds)
    const double tangent = (p2 - p1) / d;
    const double stable2 = c_stable * c_stable;
    worst_under = std::max(worst_under, tangent / stable2 - 1.0);
    stiffest = std::max(stiffest, tangent);
    // The grains-only stretch: the tangent is the stable one, within the FD error.
    if (std::abs(tangent / stable2 - 1.0) < 1e-3) {
      ++cavitated;
      cavitated_error = std::max(cavitated_error, std::abs(tangent / stable2 - 1.0));
    } else {
      ++water;
    }
  }
  EXPECT_GT(cavitated, 5) << "the release must reach the cavitated stretch";
  EXPECT_GT(water, 5) << "the release must start on the water-solid stretch";
  verify({"Three-phase soil: release from 5 % compression, stable c^2 against dp/drho along the branch",
          "never below the local tangent (finite differences)", 0.0, std::max(worst_under, 0.0), 1e-4, false,
          "relative"});
  verify({"Three-phase soil: release from 5 % compression, stable c^2 on the cavitated stretch",
          "dp/drho of the grains alone (finite differences)", 0.0, cavitated_error, 1e-4, false, "relative"});
  verify({"Three-phase soil: release from 5 % compression, stable c^2 at the maximum compaction",
          "the stiffest dp/drho of the release branch (grains alone at the cut-off, where the expanded "
          "volume raises c^2 = K v / rho0 by about 1 %)",
          stiffest, c_release * c_release, 0.02, true, "m^2/s^2"});
}

// Preset `sandy_clay_wang2005_seismic` (theory section 12): K_p solved from the
// section 5 derivation so that the small-strain P-wave speed
// sqrt((K0 + 4G/3)/rho0) is Table 1's seismic velocity.
TEST(ThreePhaseSoilEos, SeismicPresetHasTheTable1SeismicVelocity) {
  const MaterialPreset p = sandy_clay_wang2005_seismic();
  const auto material = soil_material(p.eos, p.strength, p.damage);
  PointDriver point(material);
  // At v = 1 the point reports the (stiffer) unloading branch; the seismic
  // velocity is the loading tangent, taken just inside compression.
  MaterialPoints& pts = point.pts;
  pts.density[0] *= 1.0 + 1e-9;
  material->eos().evaluate(pts, MaterialContext{}, false);
  verify({"Sandy clay, seismic calibration: small-strain P-wave speed of the EOS + shear modulus",
          "Table 1 seismic velocity", 1400.0, pts.wave_speed(0), 1e-6, true, "m/s"});
  Parameters eos = p.eos;
  verify({"Sandy clay, seismic calibration: friction modulus K_p", "hand value (theory section 12)", 6.760e9,
          eos.number("friction_modulus"), 1e-3, true, "Pa"});
}

}  // namespace
}  // namespace camouflet::test
