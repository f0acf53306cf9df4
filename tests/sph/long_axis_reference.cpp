// The axis treatment of r-z SPH against a model that has no axis: a small TNT
// charge buried in the seismic sandy clay, all SPH at one spacing, once in r-z
// and once in 3-D as a quarter model (symmetry planes x = 0 and y = 0), the
// same free ground z = 0 and the same free outer faces (r-z: a cylinder of
// radius R; 3-D: the square x, y <= R, whose corners are farther out than the
// cylinder: the comparison stops before their echo reaches the axis). The soil
// particles that start 2.5 to 6 charge radii below the charge centre, in the
// first three r-z columns, are compared with the 3-D particles at the same
// distance from the axis (fitted as u_z = A + B r^2, u_r = C r + E r^3 over the
// 3-D particles with r < 3.5 dx: both fields are smooth and even / odd in r).
//
// The target (the near-field convergence work): axial and radial displacement
// of each of the first three columns within 5 % of the 3-D run. At 1 ms the
// axial motion meets it; the radial motion does not (docs/theory/sph.md, "The
// first columns next to the axis"), and its test is disabled until the axis
// treatment meets it. The buried cases' first column runs ahead later (5-10
// ms), beyond this quick comparison.
//
// One run of either model is not a measurement: the detonation's push into the
// damaged soil amplifies round-off, and a change of the CFL number by 1e-4 (or
// another build's SIMD width) moves a column's displacement by up to 5 %. So
// each model is run at five CFL numbers within 2e-4 of 0.5, and the ensemble
// means are compared; the spread is recorded beside them.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "boundary/mirror_planes.hpp"
#include "common/verification.hpp"
#include "materials/registry.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

constexpr double kSpacing = 0.02;       // m
constexpr double kChargeRadius = 0.06;  // m: 1.44 kg of TNT, 3 particles across its radius
constexpr double kDepth = 0.3;          // m, charge centre below the ground
constexpr double kRadius = 0.4;         // m, soil extent from the axis
constexpr double kBottom = 0.7;         // m, soil bottom below the ground
constexpr double kEnd = 1.0e-3;         // s

constexpr int kProfileBins = 10;  // the profile's bins: initial distance from the axis, one spacing each

struct ColumnMotion {
  double uz[3] = {}, ur[3] = {};  // m, at r = 0.5, 1.5, 2.5 spacings
  // Means over the particles in each bin [k dx, (k+1) dx) of the initial distance from the axis
  // (r-z: the columns themselves): the axial displacement (m) and the hoop strain u_r / r0.
  double profile_uz[kProfileBins] = {}, profile_hoop[kProfileBins] = {};
  double energy_error = 0.0;
};

// The charge (a sphere; in 3-D its quarter x, y >= 0) and the soil around it.
template <int D>
Model buried_charge_model() {
  Model model;
  model.run.mode = D == 2 ? GeometryMode::axisymmetric : GeometryMode::three_d;
  const int z = D - 1;
  ParticleFillSpec charge;
  charge.region.shape = ParticleRegion::Shape::sphere;
  charge.region.centre[z] = -kDepth;
  charge.region.radius = kChargeRadius;
  charge.spacing = kSpacing;
  if constexpr (D == 3)
    for (int a = 0; a < 2; ++a) {  // leave out x < 0 and y < 0: the mirror planes stand for them
      ParticleRegion half;
      half.min = {-1.0, -1.0, -1.0};
      half.max = {1.0, 1.0, 1.0};
      half.max[a] = 0.0;
      charge.exclude.push_back(half);
    }
  std::array<double, 3> lo{}, hi{};
  lo[z] = -kBottom;
  for (int a = 0; a < D - 1; ++a) hi[a] = kRadius;
  ParticleFillSpec soil = test::box_fill(lo, hi, kSpacing);
  soil.exclude.push_back(charge.region);
  test::add_sph_part(model, "tnt",
                     make_material("tnt", "tnt_wang2005", {}, Parameters{}, Parameters{}, Parameters{}),
                     charge);
  test::add_sph_part(
      model, "soil",
      make_material("soil", "sandy_clay_wang2005_seismic", {}, Parameters{}, Parameters{}, Parameters{}),
      soil);
  DetonationPoint point;
  point.position[z] = -kDepth;
  model.detonations.push_back(point);
  return model;
}

// Least squares of y = a f(r) + b g(r).
std::pair<double, double> fit2(const std::vector<double>& f, const std::vector<double>& g,
                               const std::vector<double>& y) {
  double ff = 0, fg = 0, gg = 0, fy = 0, gy = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    ff += f[k] * f[k], fg += f[k] * g[k], gg += g[k] * g[k], fy += f[k] * y[k], gy += g[k] * y[k];
  }
  const double det = ff * gg - fg * fg;
  return {(fy * gg - gy * fg) / det, (gy * ff - fy * fg) / det};
}

// The r-z hoop term of a run: the point term, or [sph] smoothed_hoop with its band next to the axis.
struct HoopTerm {
  bool smoothed = false;
  double width = 0.0;  // [sph] smoothed_hoop_width, smoothing lengths
  bool viscous = false;  // [sph] viscosity_hoop
};

template <int D>
ColumnMotion run_column_motion(double cfl, const HoopTerm& hoop) {
  const Model model = buried_charge_model<D>();
  SphOptions options;
  options.viscosity_alpha = 0.2;  // as the generated buried cases
  options.smoothed_hoop = hoop.smoothed;
  options.smoothed_hoop_width = hoop.width;
  options.viscosity_hoop = hoop.viscous;
  std::vector<MirrorPlane> planes = axis_mirror_planes(model.run.mode);  // r-z: the axis
  if constexpr (D == 3) planes = {{0, 0.0, PlaneKind::symmetry}, {1, 0.0, PlaneKind::symmetry}};
  SphSystem<D> sph(model, options, planes);
  const double e0 = sph.kinetic_energy() + sph.internal_energy();
  double dt_last = 0.0;
  const long cycles = test::run_leapfrog_until(sph, kEnd, cfl, &dt_last);
  const double e_end = test::synchronised_kinetic_energy(sph, dt_last) + sph.internal_energy();
  ColumnMotion out;
  out.energy_error = e_end / e0 - 1.0;
  const auto& p = sph.particles();
  const int z = D - 1;
  std::vector<double> r, uz, ur;
  int in_bin[kProfileBins] = {};
  for (std::size_t i = 0; i < sph.size(); ++i) {
    if (p.part[i] != 1) continue;  // soil
    const Vec<D> x0 = p.position[i] - p.displacement[i];
    const double below = -kDepth - x0[z];
    if (below < 2.5 * kChargeRadius || below > 6.0 * kChargeRadius) continue;
    const double r0 = D == 2 ? x0[0] : std::hypot(x0[0], x0[1]);
    const double u_r =
        D == 2 ? p.displacement[i][0] : (p.displacement[i][0] * x0[0] + p.displacement[i][1] * x0[1]) / r0;
    if (const int bin = static_cast<int>(r0 / kSpacing); bin < kProfileBins) {
      out.profile_uz[bin] += p.displacement[i][z];
      out.profile_hoop[bin] += u_r / r0;
      ++in_bin[bin];
    }
    if (r0 > 3.5 * kSpacing) continue;
    r.push_back(r0), uz.push_back(p.displacement[i][z]), ur.push_back(u_r);
  }
  for (int bin = 0; bin < kProfileBins; ++bin) {
    out.profile_uz[bin] /= in_bin[bin];
    out.profile_hoop[bin] /= in_bin[bin];
  }
  std::vector<double> one(r.size(), 1.0), r2(r.size()), r3(r.size());
  for (std::size_t k = 0; k < r.size(); ++k) r2[k] = r[k] * r[k], r3[k] = r2[k] * r[k];
  if constexpr (D == 2) {
    // Column means: the r-z particles lie on the columns themselves.
    for (int c = 0; c < 3; ++c) {
      double su = 0, sr = 0;
      int n = 0;
      for (std::size_t k = 0; k < r.size(); ++k)
        if (std::abs(r[k] - (c + 0.5) * kSpacing) < 0.25 * kSpacing) su += uz[k], sr += ur[k], ++n;
      out.uz[c] = su / n;
      out.ur[c] = sr / n;
    }
  } else {
    // The 3-D particles' mean over the same depth range, fitted in r.
    const auto [a, b] = fit2(one, r2, uz);
    const auto [c1, e3] = fit2(r, r3, ur);
    for (int c = 0; c < 3; ++c) {
      const double rc = (c + 0.5) * kSpacing;
      out.uz[c] = a + b * rc * rc;
      out.ur[c] = c1 * rc + e3 * rc * rc * rc;
    }
  }
  std::printf(
      "%s: %zu particles, %ld cycles, energy %+.3f %%; columns r = 0.5/1.5/2.5 dx: u_z %.4f %.4f %.4f m, "
      "u_r %.4f %.4f %.4f m\n",
      D == 2 ? "r-z" : "3-D quarter", sph.size(), cycles, 100.0 * out.energy_error, out.uz[0], out.uz[1],
      out.uz[2], out.ur[0], out.ur[1], out.ur[2]);
  return out;
}

}  // namespace

// Ensemble means of each model's column motion over CFL numbers within 2e-4 of 0.5, with the
// spread (largest minus smallest over the mean) of each column's displacements.
struct Ensemble {
  ColumnMotion mean;
  double uz_spread[3] = {}, ur_spread[3] = {};
  double worst_energy_error = 0.0;
};

template <int D>
Ensemble ensemble(const HoopTerm& hoop = {}) {
  const double cfls[] = {0.4998, 0.4999, 0.5, 0.5001, 0.5002};
  Ensemble e;
  double uz_min[3], uz_max[3], ur_min[3], ur_max[3];
  for (int c = 0; c < 3; ++c) uz_min[c] = ur_min[c] = 1e30, uz_max[c] = ur_max[c] = -1e30;
  for (const double cfl : cfls) {
    const ColumnMotion m = run_column_motion<D>(cfl, hoop);
    e.worst_energy_error = std::max(e.worst_energy_error, std::abs(m.energy_error));
    for (int c = 0; c < 3; ++c) {
      e.mean.uz[c] += m.uz[c] / std::size(cfls);
      e.mean.ur[c] += m.ur[c] / std::size(cfls);
    }
    for (int bin = 0; bin < kProfileBins; ++bin) {
      e.mean.profile_uz[bin] += m.profile_uz[bin] / std::size(cfls);
      e.mean.profile_hoop[bin] += m.profile_hoop[bin] / std::size(cfls);
    }
    for (int c = 0; c < 3; ++c) {
      uz_min[c] = std::min(uz_min[c], m.uz[c]), uz_max[c] = std::max(uz_max[c], m.uz[c]);
      ur_min[c] = std::min(ur_min[c], m.ur[c]), ur_max[c] = std::max(ur_max[c], m.ur[c]);
    }
  }
  for (int c = 0; c < 3; ++c) {
    e.uz_spread[c] = (uz_max[c] - uz_min[c]) / std::abs(e.mean.uz[c]);
    e.ur_spread[c] = (ur_max[c] - ur_min[c]) / std::abs(e.mean.ur[c]);
  }
  return e;
}

// Both ensembles once, shared by the tests below (about 3 min on one core).
const std::pair<Ensemble, Ensemble>& runs() {
  static const std::pair<Ensemble, Ensemble> both{ensemble<2>(), ensemble<3>()};
  return both;
}

// The r-z ensemble with [sph] smoothed_hoop (a few seconds more: r-z is 700 particles).
const Ensemble& smoothed_runs() {
  static const Ensemble rz{ensemble<2>({true, 0.0})};
  return rz;
}

// The r-z ensemble with the smoothed hoop term, its band of h/2 and the viscosity's hoop term
// ([sph] smoothed_hoop_width = 0.5, viscosity_hoop = true).
const Ensemble& band_runs() {
  static const Ensemble rz{ensemble<2>({true, 0.5, true})};
  return rz;
}

// Single runs at main d47382d, 2 Dec 2026, 1 ms: u_z r-z / 3-D = 0.954, 0.984, 1.048 in columns
// 1-3; u_r r-z / 3-D = 0.869, 0.704, 0.813. On another machine the same code gave 1.017, 0.944
// (a 5.6 % miss), 1.056: the round-off spread, hence the ensembles.
TEST(SphAxisReference, AxialMotionOfTheFirstColumnsAsInThreeDimensions) {
  const auto& [rz, ref] = runs();
  // The reference itself: it conserves energy, and its charge drove the soil below it down and out.
  EXPECT_LT(ref.worst_energy_error, 0.01);
  EXPECT_LT(ref.mean.uz[0], 0.0);
  EXPECT_GT(ref.mean.ur[2], 0.0);
  for (int c = 0; c < 3; ++c) {
    std::printf(
        "column %d: mean u_z r-z / 3-D = %.3f (spread %.3f / %.3f), mean u_r r-z / 3-D = %.3f "
        "(spread %.3f / %.3f)\n",
        c + 1, rz.mean.uz[c] / ref.mean.uz[c], rz.uz_spread[c], ref.uz_spread[c],
        rz.mean.ur[c] / ref.mean.ur[c], rz.ur_spread[c], ref.ur_spread[c]);
    test::verify({fmt::format("Buried 1.4 kg TNT, SPH at 0.02 m, 1 ms: axial displacement of r-z column {} "
                              "(2.5-6 charge radii below the charge), mean of 5 runs at CFL 0.5 +- 2e-4",
                              c + 1),
                  "the same problem in 3-D (quarter model, no axis), mean of 5 runs, within 5 %",
                  ref.mean.uz[c], rz.mean.uz[c], 0.05, true, "m"});
    test::record_observation(
        fmt::format("Buried 1.4 kg TNT, SPH at 0.02 m, 1 ms: spread of the axial displacement of column {} "
                    "over the 5 runs (r-z; 3-D)",
                    c + 1),
        "below the 5 % of the comparison",
        fmt::format("{:.3f}; {:.3f} of the mean", rz.uz_spread[c], ref.uz_spread[c]),
        rz.uz_spread[c] < 0.05 && ref.uz_spread[c] < 0.05);
  }
}

// The radial motion misses the target today (mean u_r r-z / 3-D 0.832 / 0.657 / 0.767 in columns
// 1-3, 6 Dec 2026, with the artificial stress's hoop term): enable with the axis treatment that
// meets it.
TEST(SphAxisReference, DISABLED_RadialMotionOfTheFirstColumnsAsInThreeDimensions) {
  const auto& [rz, ref] = runs();
  for (int c = 0; c < 3; ++c)
    test::verify({fmt::format("Buried 1.4 kg TNT, SPH at 0.02 m, 1 ms: radial displacement of r-z column {}, "
                              "mean of 5 runs",
                              c + 1),
                  "the same problem in 3-D (quarter model, no axis), mean of 5 runs, within 5 %",
                  ref.mean.ur[c], rz.mean.ur[c], 0.05, true, "m"});
}

// The profile out to ten spacings from the axis, recorded: where the r-z soil moves as the 3-D
// soil does and where it lags (docs/theory/sph.md, "Where the lag is"). At 6 Dec 2026 the first
// column's hoop strain agreed, the second to sixth lagged by up to a third, and from about six
// spacings on the two agreed within 10 %.
TEST(SphAxisReference, ProfileOfTheFirstTenSpacingsRecorded) {
  const auto& [rz, ref] = runs();
  for (int bin = 0; bin < kProfileBins; ++bin) {
    const double hoop = rz.mean.profile_hoop[bin] / ref.mean.profile_hoop[bin];
    const double axial = rz.mean.profile_uz[bin] / ref.mean.profile_uz[bin];
    std::printf("r %d-%d dx: u_r / r0 r-z %.3f 3-D %.3f (%.3f); u_z r-z %.4f 3-D %.4f m (%.3f)\n", bin, bin + 1,
                rz.mean.profile_hoop[bin], ref.mean.profile_hoop[bin], hoop, rz.mean.profile_uz[bin],
                ref.mean.profile_uz[bin], axial);
    test::record_observation(
        fmt::format("Buried 1.4 kg TNT, SPH at 0.02 m, 1 ms: soil {}-{} spacings from the axis (2.5-6 charge "
                    "radii below the charge), mean of 5 runs: r-z / 3-D of the hoop strain u_r / r0; of u_z",
                    bin, bin + 1),
        "1 within 5 % (the same problem in 3-D, quarter model, no axis)",
        fmt::format("{:.3f}; {:.3f}", hoop, axial), std::abs(hoop - 1.0) < 0.05 && std::abs(axial - 1.0) < 0.05);
  }
}

// Records an r-z ensemble's profile and first three columns against the 3-D ensemble, each as
// "Buried 1.4 kg TNT, SPH at 0.02 m, 1 ms, r-z with <variant>: ...".
void record_against_reference(const Ensemble& rz, const std::string& variant) {
  const auto& ref = runs().second;
  EXPECT_LT(rz.worst_energy_error, 0.01);
  for (int bin = 0; bin < kProfileBins; ++bin) {
    const double hoop = rz.mean.profile_hoop[bin] / ref.mean.profile_hoop[bin];
    const double axial = rz.mean.profile_uz[bin] / ref.mean.profile_uz[bin];
    std::printf("%s, r %d-%d dx: u_r / r0 r-z / 3-D %.3f; u_z %.3f\n", variant.c_str(), bin, bin + 1, hoop, axial);
    test::record_observation(
        fmt::format("Buried 1.4 kg TNT, SPH at 0.02 m, 1 ms, r-z with {}: soil {}-{} spacings from the axis, mean of 5 "
                    "runs: r-z / 3-D of the hoop strain u_r / r0; of u_z",
                    variant, bin, bin + 1),
        "1 within 5 % (the same problem in 3-D, quarter model, no axis)",
        fmt::format("{:.3f}; {:.3f}", hoop, axial), std::abs(hoop - 1.0) < 0.05 && std::abs(axial - 1.0) < 0.05);
  }
  for (int c = 0; c < 3; ++c)
    test::record_observation(
        fmt::format("Buried 1.4 kg TNT, SPH at 0.02 m, 1 ms, r-z with {}: column {}, mean of 5 runs: r-z / 3-D of u_r; "
                    "of u_z",
                    variant, c + 1),
        "1 within 5 % (the same problem in 3-D, quarter model, no axis)",
        fmt::format("{:.3f}; {:.3f}", rz.mean.ur[c] / ref.mean.ur[c], rz.mean.uz[c] / ref.mean.uz[c]),
        std::abs(rz.mean.ur[c] / ref.mean.ur[c] - 1.0) < 0.05 && std::abs(rz.mean.uz[c] / ref.mean.uz[c] - 1.0) < 0.05);
}

// The r-z model with the smoothed hoop term and its conjugate hoop rate ([sph] smoothed_hoop,
// docs/theory/sph.md, "The hoop term smoothed as the ring sum is"), recorded against the same 3-D
// ensemble. At 6 Dec 2026 (ensemble means, 1 ms): hoop strain r-z / 3-D 0.87 0.98 1.14 1.01 0.99
// 0.96 1.01 0.99 0.99 1.02 in the ten bins (the point hoop term: 0.74 0.68 0.78 0.81 0.82 0.85 0.93
// 0.96 0.97 0.98), u_z 1.07 1.12 1.00 1.02 0.98 1.00 1.01 1.01 1.00 1.00; columns 1-3 u_r 0.99 0.96
// 1.11, u_z 1.10 1.09 1.00. Recorded, not asserted: the option is off by default (the axial lead of
// the first two columns, and the coarse buried case stops when a charge particle crosses the axis).
TEST(SphAxisReference, SmoothedHoopProfileRecorded) {
  record_against_reference(smoothed_runs(), "the smoothed hoop term");
}

// The r-z model with the smoothed hoop term, its band of h/2 next to the axis and the viscosity's
// hoop term (docs/theory/sph.md, "The band next to the axis"), recorded against the same 3-D
// ensemble. At 6 Dec 2026 (ensemble means, 1 ms): hoop strain r-z / 3-D 1.88 1.14 1.15 1.06 1.02
// 0.98 0.98 0.94 0.99 1.00, u_z 1.03 1.01 0.99 1.00 0.98 1.00 1.01 1.01 1.03 1.04; columns 1-3 u_r
// 2.08 1.18 1.13, u_z 1.05 1.01 0.98. The axial motion agrees out to ten spacings; the first
// column is thrown sideways twice as far as in 3-D (its u_r is 4 mm there).
TEST(SphAxisReference, SmoothedHoopBandProfileRecorded) {
  record_against_reference(band_runs(), "the smoothed hoop term, its band of h/2 and the viscosity's hoop term");
}
