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
//
// A longer problem (kLonger; docs/theory/sph.md, "A longer reference") gives both models a
// cylinder 0.6 m x 1 m, samples them at 1 and 5 ms with gauges at 0, 45 and 90 degrees from the
// charge and the cavity's radius in those sectors, and compares ten-run ensembles; its 3-D runs are
// stored in a file (written run by run by a disabled test: they take hours).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <omp.h>
#include <numbers>
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

// The soil's extent and the comparison's times. The 1 ms problem is the first reference: a square
// 3-D domain, compared before the echo of its corners reaches the axis. The longer one gives both
// models the same free outer surface, a cylinder (3-D: a quarter cylinder), so that every echo
// reaches both alike and the comparison holds at any time.
struct Problem {
  double radius = 0.4;          // m, soil extent from the axis
  double bottom = 0.7;          // m, soil bottom below the ground
  bool quarter_cylinder = false;  // 3-D soil: the quarter cylinder r <= radius (else the square)
  std::vector<double> times{1.0e-3};  // s, when the motion is sampled (the last: the end)
  int runs = 5;                 // ensemble size (CFL numbers in equal steps over 0.5 +- 2e-4)
};
const Problem kFirst{};
const Problem kLonger{0.6, 1.0, true, {1.0e-3, 5.0e-3}, 10};

constexpr int kProfileBins = 10;  // the profile's bins: initial distance from the axis, one spacing each

// Gauges in the soil at kGaugeDistance from the charge centre, at 0, 45 and 90 degrees from the
// downward axis: the mean over the soil that starts within 1.5 spacings of the gauge's ring (r-z:
// its point in the meridian plane), weighted by mass (r-z ring masses), of the displacement and
// velocity along the direction away from the charge centre.
constexpr double kGaugeDistance = 0.25;  // m
constexpr double kGaugeAngles[3] = {0.0, 45.0, 90.0};  // degrees from the downward axis
constexpr double kCavitySector = 22.5;  // degrees: the cavity's sectors are kGaugeAngles +- this

struct ColumnMotion {
  double uz[3] = {}, ur[3] = {};  // m, at r = 0.5, 1.5, 2.5 spacings
  // Means over the particles in each bin [k dx, (k+1) dx) of the initial distance from the axis
  // (r-z: the columns themselves): the axial displacement (m) and the hoop strain u_r / r0.
  double profile_uz[kProfileBins] = {}, profile_hoop[kProfileBins] = {};
  // The gauges (m; peak m/s over the run so far) and the cavity's radius in each gauge's sector:
  // the distance from the charge centre within which 90 % of the sector's explosive mass lies (m).
  double gauge_u[3] = {}, gauge_peak_v[3] = {}, cavity[3] = {};
  double energy_error = 0.0;
};

// The charge (a sphere; in 3-D its quarter x, y >= 0) and the soil around it.
template <int D>
Model buried_charge_model(const Problem& problem) {
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
  lo[z] = -problem.bottom;
  for (int a = 0; a < D - 1; ++a) hi[a] = problem.radius;
  ParticleFillSpec soil = test::box_fill(lo, hi, kSpacing);
  if (D == 3 && problem.quarter_cylinder) {
    // The lattice of the box (its bounds at -radius and -bottom keep the cells at (i + 1/2) dx from
    // the mirror planes), its quarter x, y >= 0.
    soil.region.shape = ParticleRegion::Shape::cylinder;
    soil.region.centre = {0.0, 0.0, -problem.bottom};
    soil.region.axis = {0.0, 0.0, 1.0};
    soil.region.radius = problem.radius;
    soil.region.length = problem.bottom;
    soil.exclude = charge.exclude;
  }
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

// The r-z hoop term of a run: the point term, or [sph] smoothed_hoop with its band next to the axis;
// and the two settings the disabled instruments below may change (the tests keep these).
struct HoopTerm {
  bool smoothed = false;
  double width = 0.0;  // [sph] smoothed_hoop_width, smoothing lengths
  bool viscous = false;  // [sph] viscosity_hoop
  double viscosity_alpha = 0.2;  // as the generated buried cases
  bool artificial_stress = true;
  std::string dump{};  // not empty: each sampled state's particles go to files named from this prefix
};

// The soil's gauge rings: for each gauge the particles that start within 1.5 spacings of its ring.
template <int D>
std::array<std::vector<std::size_t>, 3> gauge_particles(const SphSystem<D>& sph) {
  std::array<std::vector<std::size_t>, 3> members;
  const auto& p = sph.particles();
  const int z = D - 1;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    if (p.part[i] != 1) continue;
    const Vec<D> x0 = p.position[i] - p.displacement[i];
    const double r0 = D == 2 ? x0[0] : std::hypot(x0[0], x0[1]);
    for (int g = 0; g < 3; ++g) {
      const double angle = kGaugeAngles[g] * std::numbers::pi / 180.0;
      const double rg = kGaugeDistance * std::sin(angle), zg = -kDepth - kGaugeDistance * std::cos(angle);
      if (std::hypot(r0 - rg, x0[z] - zg) < 1.5 * kSpacing) members[static_cast<std::size_t>(g)].push_back(i);
    }
  }
  return members;
}

// A vector's component along the direction from the charge centre to the meridian point (r, z).
template <int D>
double away_from_charge(const Vec<D>& x, const Vec<D>& u) {
  if constexpr (D == 2) {
    const double dr = x[0], dz = x[1] + kDepth, n = std::hypot(dr, dz);
    return (u[0] * dr + u[1] * dz) / n;
  } else {
    const double dz = x[2] + kDepth, n = std::sqrt(x[0] * x[0] + x[1] * x[1] + dz * dz);
    return (u[0] * x[0] + u[1] * x[1] + u[2] * dz) / n;
  }
}

// The gauges' mass-weighted means of a per-particle vector (displacement or velocity) along the
// direction away from the charge, each particle's direction from its initial place.
template <int D>
std::array<double, 3> gauge_means(const SphSystem<D>& sph, const std::array<std::vector<std::size_t>, 3>& members,
                                  const std::vector<Vec<D>>& field) {
  const auto& p = sph.particles();
  std::array<double, 3> out{};
  for (std::size_t g = 0; g < 3; ++g) {
    double sum = 0.0, mass = 0.0;
    for (const std::size_t i : members[g]) {
      sum += p.mass[i] * away_from_charge<D>(p.position[i] - p.displacement[i], field[i]);
      mass += p.mass[i];
    }
    out[g] = sum / mass;
  }
  return out;
}

// The columns, the profile, the gauges' displacements and the cavity of the state reached.
template <int D>
void sample(const SphSystem<D>& sph, const std::array<std::vector<std::size_t>, 3>& gauges, ColumnMotion& out) {
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
  const std::array<double, 3> u = gauge_means(sph, gauges, p.displacement);
  for (int g = 0; g < 3; ++g) out.gauge_u[g] = u[static_cast<std::size_t>(g)];
  // The cavity: the explosive's mass by distance from the charge centre, sector by sector.
  for (int g = 0; g < 3; ++g) {
    std::vector<std::pair<double, double>> by_distance;  // (distance, mass)
    double total = 0.0;
    for (std::size_t i = 0; i < sph.size(); ++i) {
      if (p.part[i] != 0) continue;  // the explosive
      const double rr = D == 2 ? p.position[i][0] : std::hypot(p.position[i][0], p.position[i][1]);
      const double dz = -(p.position[i][z] + kDepth);  // downwards from the centre
      const double angle = std::atan2(rr, dz) * 180.0 / std::numbers::pi;
      if (std::abs(angle - kGaugeAngles[g]) > kCavitySector) continue;
      by_distance.push_back({std::hypot(rr, dz), p.mass[i]});
      total += p.mass[i];
    }
    std::sort(by_distance.begin(), by_distance.end());
    double held = 0.0;
    for (const auto& [distance, mass] : by_distance) {
      held += mass;
      out.cavity[g] = distance;
      if (held >= 0.9 * total) break;
    }
  }
}

// One run of the problem in r-z (D = 2) or 3-D at the given CFL number: the motion at each of
// the problem's times.
template <int D>
std::vector<ColumnMotion> run_column_motion(const Problem& problem, double cfl, const HoopTerm& hoop,
                                            int threads = 1) {
  const Model model = buried_charge_model<D>(problem);
  SphOptions options;
  options.viscosity_alpha = hoop.viscosity_alpha;
  options.smoothed_hoop = hoop.smoothed;
  options.smoothed_hoop_width = hoop.width;
  options.viscosity_hoop = hoop.viscous;
  options.artificial_stress = hoop.artificial_stress;
  std::vector<MirrorPlane> planes = axis_mirror_planes(model.run.mode);  // r-z: the axis
  if constexpr (D == 3) planes = {{0, 0.0, PlaneKind::symmetry}, {1, 0.0, PlaneKind::symmetry}};
  SphSystem<D> sph(model, options, planes);
  const auto gauges = gauge_particles(sph);
  const double e0 = sph.kinetic_energy() + sph.internal_energy();
  std::vector<ColumnMotion> out;
  double peak[3] = {};
  const auto track_peaks = [&] {
    const std::array<double, 3> v = gauge_means(sph, gauges, sph.particles().velocity);
    for (int g = 0; g < 3; ++g) peak[g] = std::max(peak[g], v[static_cast<std::size_t>(g)]);
  };
  omp_set_num_threads(threads);
  test::LeapfrogClock clock;  // landing on each sampling time
  for (const double until : problem.times) {
    test::advance_leapfrog(sph, clock, until, cfl, track_peaks);
    ColumnMotion m;
    sample(sph, gauges, m);
    if (!hoop.dump.empty()) {
      // For plots of a sweep: every particle of the sampled state, one line each: part, position,
      // initial position (m), density (kg/m^3), smoothing length (m).
      std::ofstream f(fmt::format("{}_{}d_{:.0f}us_{:.5f}.txt", hoop.dump, D, 1e6 * until, cfl));
      const auto& p = sph.particles();
      for (std::size_t i = 0; i < sph.size(); ++i) {
        const Vec<D> x0 = p.position[i] - p.displacement[i];
        f << p.part[i];
        for (int a = 0; a < D; ++a) f << ' ' << p.position[i][a];
        for (int a = 0; a < D; ++a) f << ' ' << x0[a];
        f << ' ' << p.density[i] << ' ' << p.smoothing_length[i] << '\n';
      }
    }
    for (int g = 0; g < 3; ++g) m.gauge_peak_v[g] = peak[g];
    m.energy_error = (test::synchronised_kinetic_energy(sph, clock.dt_previous) + sph.internal_energy()) / e0 - 1.0;
    std::printf(
        "%s, %.0f ms: %zu particles, %ld cycles, energy %+.3f %%; columns r = 0.5/1.5/2.5 dx: u_z %.4f %.4f "
        "%.4f m, u_r %.4f %.4f %.4f m; gauges 0/45/90 deg: u %.4f %.4f %.4f m, peak v %.2f %.2f %.2f m/s; "
        "cavity %.3f %.3f %.3f m\n",
        D == 2 ? "r-z" : "3-D quarter", 1e3 * until, sph.size(), clock.cycles, 100.0 * m.energy_error, m.uz[0],
        m.uz[1], m.uz[2], m.ur[0], m.ur[1], m.ur[2], m.gauge_u[0], m.gauge_u[1], m.gauge_u[2],
        m.gauge_peak_v[0], m.gauge_peak_v[1], m.gauge_peak_v[2], m.cavity[0], m.cavity[1], m.cavity[2]);
    std::fflush(stdout);
    out.push_back(m);
  }
  return out;
}

}  // namespace

// Ensemble means of each model's motion over CFL numbers in equal steps within 2e-4 of 0.5, at one
// of the problem's times, with the spread (largest minus smallest over the mean) of each column's
// displacements and the standard error of every mean (the runs' standard deviation / sqrt(n)).
struct Ensemble {
  ColumnMotion mean, error;  // error: standard errors of the means (m, m/s)
  double uz_spread[3] = {}, ur_spread[3] = {};
  double worst_energy_error = 0.0;
  int runs = 0;
};

// The quantities of a ColumnMotion that the ensembles average, as one list (mean and error alike).
std::vector<std::pair<std::string, double*>> named_fields(ColumnMotion& m) {
  std::vector<std::pair<std::string, double*>> f;
  for (int c = 0; c < 3; ++c) {
    f.push_back({fmt::format("column{}_uz", c + 1), &m.uz[c]});
    f.push_back({fmt::format("column{}_ur", c + 1), &m.ur[c]});
  }
  for (int b = 0; b < kProfileBins; ++b) {
    f.push_back({fmt::format("bin{}_uz", b), &m.profile_uz[b]});
    f.push_back({fmt::format("bin{}_hoop", b), &m.profile_hoop[b]});
  }
  for (int g = 0; g < 3; ++g) {
    const int angle = static_cast<int>(kGaugeAngles[g]);
    f.push_back({fmt::format("gauge{}_u", angle), &m.gauge_u[g]});
    f.push_back({fmt::format("gauge{}_peak_v", angle), &m.gauge_peak_v[g]});
    f.push_back({fmt::format("cavity{}", angle), &m.cavity[g]});
  }
  return f;
}

std::vector<double*> fields(ColumnMotion& m) {
  std::vector<double*> f;
  for (auto& [name, value] : named_fields(m)) f.push_back(value);
  return f;
}

// The means and standard errors (the runs' standard deviation / sqrt(n)) of every quantity:
// samples[run][q] in the order of fields().
void average_runs(const std::vector<std::vector<double>>& samples, Ensemble& e) {
  e.runs = static_cast<int>(samples.size());
  const double n = e.runs;
  const std::vector<double*> mean = fields(e.mean), error = fields(e.error);
  for (std::size_t q = 0; q < mean.size(); ++q) {
    double sum = 0.0, squares = 0.0;
    for (const auto& run : samples) sum += run[q];
    *mean[q] = sum / n;
    for (const auto& run : samples) squares += std::pow(run[q] - *mean[q], 2);
    *error[q] = n > 1 ? std::sqrt(squares / (n - 1.0) / n) : 0.0;
  }
}

template <int D>
std::vector<Ensemble> ensemble(const Problem& problem, const HoopTerm& hoop = {}, int threads = 1) {
  std::vector<std::vector<ColumnMotion>> all;  // [run][time]
  const double five[] = {0.4998, 0.4999, 0.5, 0.5001, 0.5002};  // the first ensembles' numbers as written
  for (int k = 0; k < problem.runs; ++k) {
    const double cfl = problem.runs == 5 ? five[k] : 0.4998 + 4e-4 * k / (problem.runs - 1);
    all.push_back(run_column_motion<D>(problem, cfl, hoop, threads));
  }
  std::vector<Ensemble> out(problem.times.size());
  for (std::size_t t = 0; t < problem.times.size(); ++t) {
    Ensemble& e = out[t];
    std::vector<std::vector<double>> samples;
    for (auto& run : all) {
      samples.emplace_back();
      for (const double* value : fields(run[t])) samples.back().push_back(*value);
    }
    average_runs(samples, e);
    for (int c = 0; c < 3; ++c) {
      double uz_min = 1e30, uz_max = -1e30, ur_min = 1e30, ur_max = -1e30;
      for (const auto& run : all) {
        uz_min = std::min(uz_min, run[t].uz[c]), uz_max = std::max(uz_max, run[t].uz[c]);
        ur_min = std::min(ur_min, run[t].ur[c]), ur_max = std::max(ur_max, run[t].ur[c]);
      }
      e.uz_spread[c] = (uz_max - uz_min) / std::abs(e.mean.uz[c]);
      e.ur_spread[c] = (ur_max - ur_min) / std::abs(e.mean.ur[c]);
    }
    for (const auto& run : all) e.worst_energy_error = std::max(e.worst_energy_error, std::abs(run[t].energy_error));
  }
  return out;
}

// Both ensembles of the first problem once, shared by the tests below (about 3 min on one core).
const std::pair<Ensemble, Ensemble>& runs() {
  static const std::pair<Ensemble, Ensemble> both{ensemble<2>(kFirst)[0], ensemble<3>(kFirst)[0]};
  return both;
}

// The r-z ensemble with [sph] smoothed_hoop (a few seconds more: r-z is 700 particles).
const Ensemble& smoothed_runs() {
  static const Ensemble rz{ensemble<2>(kFirst, {true, 0.0})[0]};
  return rz;
}

// The r-z ensemble with the smoothed hoop term, its band of h/2 and the viscosity's hoop term
// ([sph] smoothed_hoop_width = 0.5, viscosity_hoop = true).
const Ensemble& band_runs() {
  static const Ensemble rz{ensemble<2>(kFirst, {true, 0.5, true})[0]};
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

// The longer problem (the quarter cylinder, 1 and 5 ms): its 3-D runs are stored, one row per
// run, time and quantity, in tests/sph/data/axis_reference_3d.txt (a 3-D run to 5 ms takes about 4
// minutes on one core); the tests below run the r-z ensembles against their means. Write runs
// (indices of the ensemble's CFL numbers, 0 to kLonger.runs - 1) with
//   AXIS_REFERENCE_RUNS=0,1,2 AXIS_REFERENCE_OUT=part0.txt build/tests/test_sph_long
//     --gtest_also_run_disabled_tests
//     --gtest_filter=SphAxisReference.DISABLED_WriteLongerThreeDimensionalReference
// (one command line)
// (AXIS_REFERENCE_THREADS: OpenMP threads per run) and concatenate the parts under a header line
// naming the commit, date and machine.
const std::filesystem::path kStoredReference =
    std::filesystem::path(CAMOUFLET_SOURCE_DIR) / "tests" / "sph" / "data" / "axis_reference_3d.txt";

double longer_cfl(int run) {
  return 0.4998 + 4e-4 * run / (kLonger.runs - 1);
}

// The settings of the disabled instruments' runs besides the hoop terms, from the environment:
// AXIS_ALPHA (the viscosity's alpha, else 0.2), AXIS_NO_ARTIFICIAL_STRESS (set: off) and
// AXIS_DUMP=prefix (each run's particles at each sampled time to files named from it).
HoopTerm instrument_settings(HoopTerm hoop) {
  if (const char* alpha = std::getenv("AXIS_ALPHA")) hoop.viscosity_alpha = std::atof(alpha);
  if (std::getenv("AXIS_NO_ARTIFICIAL_STRESS")) hoop.artificial_stress = false;
  if (const char* dump = std::getenv("AXIS_DUMP")) hoop.dump = dump;
  return hoop;
}

TEST(SphAxisReference, DISABLED_WriteLongerThreeDimensionalReference) {
  std::vector<int> runs;
  const char* list = std::getenv("AXIS_REFERENCE_RUNS");
  std::istringstream items(list ? list : "");
  for (std::string item; std::getline(items, item, ',');) runs.push_back(std::stoi(item));
  if (runs.empty())
    for (int k = 0; k < kLonger.runs; ++k) runs.push_back(k);
  const char* threads = std::getenv("AXIS_REFERENCE_THREADS");
  const char* path = std::getenv("AXIS_REFERENCE_OUT");
  std::ofstream out(path ? std::filesystem::path(path) : kStoredReference, std::ios::app);
  for (const int run : runs) {
    std::vector<ColumnMotion> motion = run_column_motion<3>(kLonger, longer_cfl(run), instrument_settings({}),
                                                            threads ? std::atoi(threads) : 1);
    for (std::size_t t = 0; t < motion.size(); ++t) {
      for (auto& [name, value] : named_fields(motion[t]))
        out << fmt::format("{} {:g} {} {:.9g}\n", run, 1e3 * kLonger.times[t], name, *value);
      out << fmt::format("{} {:g} energy_error {:.9g}\n", run, 1e3 * kLonger.times[t], motion[t].energy_error);
    }
    out.flush();
  }
}

// The stored 3-D runs as ensembles, by time (ms): means, standard errors, run count, worst energy
// error.
std::map<double, Ensemble> read_stored_reference(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::map<double, std::map<int, std::map<std::string, double>>> rows;  // time, run, quantity
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    int run = 0;
    double time_ms = 0.0, value = 0.0;
    std::string name;
    if (row >> run >> time_ms >> name >> value) rows[time_ms][run][name] = value;
  }
  std::map<double, Ensemble> out;
  for (const auto& [time_ms, by_run] : rows) {
    Ensemble& e = out[time_ms];
    const auto names = named_fields(e.mean);
    std::vector<std::vector<double>> samples;
    for (const auto& [run, values] : by_run) {
      samples.emplace_back();
      for (const auto& [name, unused] : names) samples.back().push_back(values.at(name));
    }
    average_runs(samples, e);
    for (const auto& [run, values] : by_run)
      e.worst_energy_error = std::max(e.worst_energy_error, std::abs(values.at("energy_error")));
  }
  return out;
}

// An r-z ensemble of the longer problem against the stored 3-D one, recorded quantity by quantity
// as "r-z / 3-D = ratio (standard errors of the two means, relative)", inside when the ratio is
// within 5 % of 1 (the target of the axis work) and both standard errors below 2 %.
void record_longer_against_stored(const std::vector<Ensemble>& rz, const std::string& variant,
                                  const std::filesystem::path& reference = kStoredReference) {
  const std::map<double, Ensemble> stored = read_stored_reference(reference);
  ASSERT_FALSE(stored.empty()) << "no stored 3-D runs in " << reference;
  for (std::size_t t = 0; t < kLonger.times.size(); ++t) {
    const double time_ms = 1e3 * kLonger.times[t];
    ASSERT_TRUE(stored.count(time_ms)) << "the stored reference has no rows at " << time_ms << " ms";
    Ensemble ref = stored.at(time_ms);
    Ensemble e = rz[t];
    EXPECT_LT(e.worst_energy_error, 0.01);
    EXPECT_LT(ref.worst_energy_error, 0.01);
    const auto mean = named_fields(e.mean);
    const auto error = fields(e.error);
    const auto ref_mean = fields(ref.mean);
    const auto ref_error = fields(ref.error);
    for (std::size_t q = 0; q < mean.size(); ++q) {
      const std::string& name = mean[q].first;
      const double ratio = *mean[q].second / *ref_mean[q];
      const double rz_rel = std::abs(*error[q] / *mean[q].second), ref_rel = std::abs(*ref_error[q] / *ref_mean[q]);
      std::printf("%s, %g ms, %s: r-z %.5g +- %.2g, 3-D %.5g +- %.2g, ratio %.3f\n", variant.c_str(), time_ms,
                  name.c_str(), *mean[q].second, *error[q], *ref_mean[q], *ref_error[q], ratio);
      if (name.rfind("bin", 0) == 0) continue;  // the profile: in the printout only
      test::record_observation(
          fmt::format(
              "Buried 1.4 kg TNT, SPH at 0.02 m in a cylinder {:g} m x {:g} m, {:g} ms, r-z with {}: {}; "
              "means of {} r-z and {} 3-D runs",
              kLonger.radius, kLonger.bottom, time_ms, variant, name, e.runs, ref.runs),
          "1 within 5 %, standard errors below 2 % (the same problem in 3-D, quarter cylinder, no axis; "
          "stored)",
          *mean[q].second == 0.0  // nothing of the quantity in r-z (no explosive in the sector)
              ? fmt::format("r-z / 3-D 0 (the r-z runs all 0; 3-D standard error {:.1f} %)", 100.0 * ref_rel)
              : fmt::format("r-z / 3-D {:.3f} (standard errors {:.1f} %; {:.1f} %)", ratio, 100.0 * rz_rel,
                            100.0 * ref_rel),
          std::abs(ratio - 1.0) < 0.05 && rz_rel < 0.02 && ref_rel < 0.02);
    }
  }
}

// Against the ten stored 3-D runs (docs/theory/sph.md, "A longer reference"): recorded, not
// asserted, until the axis treatment meets the 5 % target.
TEST(SphAxisReference, LongerProblemPointHoopTermsAgainstStoredReference) {
  record_longer_against_stored(ensemble<2>(kLonger), "the point hoop terms (the [sph] defaults)");
}

TEST(SphAxisReference, LongerProblemSmoothedHoopTermAgainstStoredReference) {
  // The smoothed hoop term alone: which part of the generator's axis terms moves what.
  record_longer_against_stored(ensemble<2>(kLonger, {true, 0.0}), "the smoothed hoop term");
}

TEST(SphAxisReference, LongerProblemGeneratorAxisTermsAgainstStoredReference) {
  record_longer_against_stored(ensemble<2>(kLonger, {true, 0.5, true}),
                               "the band of h/2 and the viscosity's hoop term (the buried-structure generator's)");
}

TEST(SphAxisReference, LongerProblemSmoothedAndViscousHoopTermsAgainstStoredReference) {
  // The generator's terms without the band: does the viscosity's hoop term alone take the near-axis
  // columns' radial throw back where the band puts it 1.3-2.2x too far?
  record_longer_against_stored(ensemble<2>(kLonger, {true, 0.0, true}),
                               "the smoothed hoop term and the viscosity's hoop term (no band)");
}

// A sweep's instrument, not a test: the longer problem in r-z with the axis terms of
// AXIS_HOOP="smoothed width viscous" (e.g. "1 0.25 0"), against the stored 3-D runs (or those of
// the file AXIS_REFERENCE_IN, written with the same AXIS_ALPHA by the writer above); about a
// minute on one core. Run with --gtest_also_run_disabled_tests
// --gtest_filter=*LongerProblemFromEnvironment. Besides instrument_settings()'s keys:
// AXIS_TIMES="0.1 0.2 ..." (ms) samples those times instead and compares nothing (for dumps),
// with AXIS_RUNS runs (at least 2) and, with AXIS_3D set, in 3-D.
TEST(SphAxisReference, DISABLED_LongerProblemFromEnvironment) {
  const char* spec = std::getenv("AXIS_HOOP");
  ASSERT_NE(spec, nullptr) << "set AXIS_HOOP=\"smoothed width viscous\"";
  std::istringstream in(spec);
  int smoothed = 0, viscous = 0;
  double width = 0.0;
  ASSERT_TRUE(in >> smoothed >> width >> viscous) << "AXIS_HOOP: three numbers, got \"" << spec << "\"";
  const HoopTerm hoop = instrument_settings({smoothed != 0, width, viscous != 0});
  Problem problem = kLonger;
  if (const char* times = std::getenv("AXIS_TIMES")) {
    problem.times.clear();
    std::istringstream t(times);
    for (double ms; t >> ms;) problem.times.push_back(1e-3 * ms);
    const char* runs = std::getenv("AXIS_RUNS");
    problem.runs = runs ? std::atoi(runs) : 2;
    ASSERT_GE(problem.runs, 2) << "AXIS_RUNS: at least 2 (the CFL numbers span 0.5 +- 2e-4)";
    if (std::getenv("AXIS_3D"))
      ensemble<3>(problem, hoop);
    else
      ensemble<2>(problem, hoop);
    return;
  }
  const char* reference = std::getenv("AXIS_REFERENCE_IN");
  record_longer_against_stored(ensemble<2>(problem, hoop),
                               fmt::format("AXIS_HOOP {}, alpha {:g}{}", spec, hoop.viscosity_alpha,
                                           hoop.artificial_stress ? "" : ", no artificial stress"),
                               reference ? std::filesystem::path(reference) : kStoredReference);
}
