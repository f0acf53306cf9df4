// Momentum sum next to the axis of an r-z model: a stress field with a known
// divergence must give the same acceleration in every particle column, the
// first one (r = dx/2, with its mirror images) included.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <array>
#include <map>

#include "common/verification.hpp"
#include "sph_test_models.hpp"

using namespace camouflet;
using namespace camouflet::sph;

namespace {

struct ColumnAcceleration {
  double radial = 0.0, axial = 0.0;
  int count = 0;
};

// The mean rho a per particle column (interior rows only) for a stress field sigma(r, z) set on
// a square lattice of 0.3 m x 1 m in r-z.
// The velocity of each particle from `velocity(r, z)` when given (the viscous force's tests).
using VelocityField = std::function<Vec<2>(double, double)>;
template <class StressField>
std::map<int, ColumnAcceleration> column_accelerations(const StressField& sigma, double spacing,
                                                      double z_low = 0.3, double z_high = 0.7,
                                                      SphOptions options = {}, VelocityField velocity = {}) {
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  const double rho = 1000.0;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", rho, 1.4, 1e5),
                     test::box_fill({0, 0, 0}, {0.3, 1, 0}, spacing));
  SphSystem<2> sph(model, options);
  sph.update_state(1e-12, 1e-12);
  auto& p = sph.particles();
  for (std::size_t i = 0; i < sph.size(); ++i) {
    p.stress[i] = sigma(p.position[i][0], p.position[i][1]);
    p.stress_term[i] = p.stress[i] * (1.0 / p.density[i]);
    if (velocity) p.velocity[i] = velocity(p.position[i][0], p.position[i][1]);
  }
  sph.compute_accelerations();
  std::map<int, ColumnAcceleration> columns;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    const double z = p.position[i][1];
    if (z < z_low || z > z_high) continue;
    ColumnAcceleration& c = columns[static_cast<int>(p.position[i][0] / spacing)];
    c.radial += p.acceleration[i][0] * p.density[i];
    c.axial += p.acceleration[i][1] * p.density[i];
    ++c.count;
  }
  for (auto& [k, c] : columns) {
    c.radial /= c.count;
    c.axial /= c.count;
  }
  return columns;
}

// The elastic field around a spherical cavity of radius a under pressure p centred on the axis at
// z = zc (Lame): sigma_RR = -p (a/R)^3, sigma_tt = +p/2 (a/R)^3, in equilibrium.
auto lame_field(double p, double a, double zc) {
  return [=](double r, double z) {
    const double dz = z - zc, R = std::hypot(r, dz), s = std::pow(a / R, 3);
    const double A = 0.5 * p * s, B = -1.5 * p * s, nr = r / R, nz = dz / R;
    return SymTensor{A + B * nr * nr, A + B * nz * nz, A, B * nr * nz, 0, 0};
  };
}

// Hydrostatic sigma = -p(z) I, p = p0 + g z: div sigma = -g e_z, no hoop
// imbalance; a = -g / rho e_z everywhere.
std::map<int, ColumnAcceleration> hydrostatic_column(double p0, double g, double spacing,
                                                     const SphOptions& options = {}) {
  return column_accelerations(
      [&](double, double z) {
        const double pressure = p0 + g * z;
        return SymTensor{-pressure, -pressure, -pressure, 0, 0, 0};
      },
      spacing, 0.3, 0.7, options);
}

}  // namespace

TEST(SphAxis, HydrostaticGradientIsTheSameInEveryColumn) {
  // sigma = -p(z) I with p = 1 MPa + 1 MPa/m z, spacing 0.02 m. Before the images across the axis
  // carried signed ring weights, the first column felt rho a_z = -1.41 g and rho a_r = +0.53 p / r.
  const double p0 = 1e6, g = 1e6, spacing = 0.02;
  const auto columns = hydrostatic_column(p0, g, spacing);
  double worst_axial = 0.0, worst_radial = 0.0;
  for (const auto& [k, c] : columns) {
    std::printf("column %2d: rho a_r %+.4e  rho a_z %+.4e (expected 0, %+.4e)\n", k, c.radial, c.axial, -g);
    if (k > 12) continue;  // the free outer surface (r = 0.3 m) and its neighbour
    const double r = (k + 0.5) * spacing, pressure = p0 + g * 0.5;
    if (k < 3) worst_axial = std::max(worst_axial, std::abs(c.axial / -g - 1.0));
    worst_radial = std::max(worst_radial, std::abs(c.radial) * r / pressure);
  }
  test::verify(
      {"r-z SPH next to the axis, hydrostatic sigma = -p(z) I: rho a_z of the first three particle "
       "columns, largest relative error",
       "-dp/dz (exact); 0.9 % is the lattice's kernel-gradient normalisation, as in every column", 0.0,
       worst_axial, 0.02, false, "-"});
  test::verify(
      {"r-z SPH, hydrostatic sigma = -p(z) I: radial force imbalance rho a_r r / p, largest over the "
       "columns up to 12 spacings from the axis",
       "0 (uniform pressure balances the hoop term)", 0.0, worst_radial, 0.02, false, "-"});
}

namespace {

// A plane shock down an r-z gas column with a roller at r = R (uniaxial strain: an exact plane
// solution): the top slab starts moving down at `speed`. Per column, the mean axial velocity
// and displacement of the particles in a band at mid-height at t_end.
struct ColumnMotion {
  double velocity = 0.0, displacement = 0.0;  // m/s, m (axial)
  int count = 0;
};

std::map<int, ColumnMotion> plane_shock_columns(double speed, double t_end) {
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  const double dx = 0.02, radius = 0.2;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1000.0, 1.4, 1e5),
                     test::box_fill({0, 0, 0}, {radius, 2, 0}, dx));
  SphSystem<2> sph(model, SphOptions{},
                  {sph::MirrorPlane{0, 0.0, sph::PlaneKind::axis}, sph::MirrorPlane{0, radius, sph::PlaneKind::symmetry}});
  auto& p = sph.particles();
  for (std::size_t i = 0; i < sph.size(); ++i)
    if (p.position[i][1] > 1.6) p.velocity[i][1] = -speed;
  test::run_leapfrog_until(sph, t_end, 0.3);
  std::map<int, ColumnMotion> columns;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    const double z0 = p.position[i][1] - p.displacement[i][1];
    if (z0 < 0.9 || z0 > 1.3) continue;
    ColumnMotion& c = columns[static_cast<int>((p.position[i][0] - p.displacement[i][0]) / dx)];
    c.velocity += p.velocity[i][1];
    c.displacement += p.displacement[i][1];
    ++c.count;
  }
  for (auto& [k, c] : columns) c.velocity /= c.count, c.displacement /= c.count;
  return columns;
}

}  // namespace

TEST(SphAxis, PlaneShockMovesTheFirstColumnLikeTheSecond) {
  // A 200 m/s piston into gas at rest, along the axis: a plane shock, the same in every column.
  // With |r| ring weights on the images the first column had moved 17 % further than the second
  // after 1.2 ms (the axis jet of the buried-structure case in its simplest form).
  const auto columns = plane_shock_columns(200.0, 1.2e-3);
  for (const auto& [k, c] : columns)
    std::printf("column %2d: v_z %+.4f  u_z %+.5e\n", k, c.velocity, c.displacement);
  test::verify(
      {"r-z SPH, plane shock along the axis (gas, piston 200 m/s, 1.2 ms): axial displacement of the "
       "first particle column at mid-height",
       "the second column's (a plane wave)", columns.at(1).displacement, columns.at(0).displacement, 0.05,
       true, "m"});
}

TEST(SphAxis, ShearGradientIsTheSameInEveryColumn) {
  // sigma_rz = k r on a uniform pressure p0: (1/r) d(r sigma_rz)/dr = 2 k along z in every column,
  // no radial force. The shear stress is what ties the first column's axial motion to the
  // second's; the images across the axis carry it with its sign flipped twice (mirror and ring
  // weight), so r sigma_rz continues evenly through r = 0.
  const double p0 = 1e6, k = 1e6, spacing = 0.02;
  const auto columns =
      column_accelerations([&](double r, double) { return SymTensor{-p0, -p0, -p0, k * r, 0, 0}; }, spacing);
  double worst_axial = 0.0, worst_radial = 0.0;
  for (const auto& [col, c] : columns) {
    std::printf("column %2d: rho a_r %+.4e  rho a_z %+.4e (expected 0, %+.4e)\n", col, c.radial, c.axial,
                2.0 * k);
    if (col > 12) continue;  // the free outer surface (r = 0.3 m) and its neighbour
    const double r = (col + 0.5) * spacing;
    if (col < 3) worst_axial = std::max(worst_axial, std::abs(c.axial / (2.0 * k) - 1.0));
    worst_radial = std::max(worst_radial, std::abs(c.radial) * r / p0);
  }
  test::verify(
      {"r-z SPH next to the axis, sigma_rz = k r: rho a_z of the first three particle columns, "
       "largest relative error",
       "2 k (exact)", 0.0, worst_axial, 0.02, false, "-"});
  test::verify(
      {"r-z SPH, sigma_rz = k r on a uniform pressure: radial force imbalance rho a_r r / p0, "
       "largest over the columns up to 12 spacings from the axis",
       "0", 0.0, worst_radial, 0.02, false, "-"});
}

TEST(SphAxis, SphericalEquilibriumFieldGivesNoForceNextToTheAxis) {
  // The elastic field around a pressurised spherical cavity (Lame): sigma_RR = -p (a/R)^3,
  // sigma_tt = +p/2 (a/R)^3 (hoop tension), centred on the axis. It is in equilibrium: no force
  // anywhere. Its hoop tension switches the artificial stress on; before the artificial stress
  // had a hoop term of its own (and its images' sign on the right half of the pair), the first
  // column felt an inward rho a_r of 0.81 |d sigma / dR|, the second 0.26, the third 0.15: the
  // (1/r) d(r R_rr)/dr of its ring sum with no -R_tt / r to balance it.
  const double p = 1e6, a = 0.1, zc = 0.5, spacing = 0.02;
  const auto lame = lame_field(p, a, zc);
  // Rows 0.25-0.35 m below the centre; the scale is |d sigma_RR / dR| at R = 0.3 m.
  const double scale = 3.0 * p * std::pow(a / 0.3, 3) / 0.3;
  SphOptions no_artificial_stress;
  no_artificial_stress.artificial_stress = false;
  double worst = 0.0, worst_without = 0.0;
  const auto columns = column_accelerations(lame, spacing, 0.15, 0.25);
  const auto without = column_accelerations(lame, spacing, 0.15, 0.25, no_artificial_stress);
  for (int col = 0; col < 3; ++col) {
    std::printf("column %d: rho a_r / scale %+.4f (artificial stress off: %+.4f), rho a_z / scale %+.4f\n", col,
                columns.at(col).radial / scale, without.at(col).radial / scale, columns.at(col).axial / scale);
    worst = std::max(worst, std::abs(columns.at(col).radial) / scale);
    worst_without = std::max(worst_without, std::abs(without.at(col).radial) / scale);
  }
  test::verify({"r-z SPH, Lame field of a pressurised sphere centred on the axis (hoop tension, artificial "
                "stress on): radial force of the first three columns / |d sigma / dR|",
                "0 (equilibrium); was 0.81 before the artificial stress's hoop term", 0.0, worst, 0.02, false,
                "-"});
  test::verify({"r-z SPH, the same Lame field with the artificial stress off: radial force of the first three "
                "columns / |d sigma / dR|",
                "0 (equilibrium)", 0.0, worst_without, 0.01, false, "-"});
}

TEST(SphAxis, UniformCompressionGivesNoViscousForceNextToTheAxis) {
  // A uniform compression towards a point on the axis, v = -k (x - c), with no stress: the
  // artificial viscosity acts as a uniform viscous pressure, whose divergence is zero. Its pair
  // sum weighs the neighbours by ring mass and gave a force towards the axis of order q / r in
  // every column without the viscosity's hoop term (rho a_r = -6.0e6 Pa/m in the third column,
  // -2.6e6 in the sixth, as 1/r; the first column less, its images carrying |r|). The term is an
  // option ([sph] viscosity_hoop), off by default (sph_options.hpp says why).
  const double k = 100.0, zc = 0.5, spacing = 0.02;
  SphOptions options;
  options.artificial_stress = false;
  options.viscosity_hoop = true;
  auto zero = [](double, double) { return SymTensor{}; };
  const auto columns = column_accelerations(zero, spacing, 0.4, 0.6, options,
                                            [&](double r, double z) { return Vec<2>{-k * r, -k * (z - zc)}; });
  // The scale: one column's viscous pair sum alone, rho (alpha c h k + beta h^2 k^2) / h, with
  // c = 11.8 m/s (the gas at rest), h = 1.2 spacings, alpha = 1, beta = 2.
  const double c = std::sqrt(1.4e5 / 1000.0), h = 1.2 * spacing;
  const double scale = 1000.0 * (c * h * k + 2.0 * h * h * k * k) / h;
  double worst = 0.0;
  for (const auto& [col, a] : columns) {
    if (col > 12) continue;  // the free outer surface (r = 0.3 m) and its neighbour
    std::printf("column %2d: rho a_r %+.4e  rho a_z %+.4e Pa/m\n", col, a.radial, a.axial);
    worst = std::max({worst, std::abs(a.radial) / scale, std::abs(a.axial) / scale});
  }
  test::verify({"r-z SPH, uniform compression towards a point on the axis, no stress: viscous force of the "
                "columns up to 12 spacings from the axis / (rho q / h)",
                "0 (a uniform viscous pressure); 6.0e6 Pa/m = 3.6 in the third column without the viscosity's "
                "hoop term ([sph] viscosity_hoop = true)",
                0.0, worst, 1e-6, false, "-"});
}
TEST(SphAxis, UniformExpansionHasTheSameStrainRateInEveryColumn) {
  // v = k (x - c), a uniform expansion from a point on the axis: D = k I in every column, the hoop
  // rate v_r / r exactly, the in-plane rates with the lattice's kernel-gradient normalisation
  // (0.9 %, the same in every column, as in the momentum sums above).
  const double k = 100.0, zc = 0.5, spacing = 0.02;
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1000.0, 1.4, 1e5),
                     test::box_fill({0, 0, 0}, {0.3, 1, 0}, spacing));
  SphSystem<2> sph(model, SphOptions{});
  auto& p = sph.particles();
  for (std::size_t i = 0; i < sph.size(); ++i)
    p.velocity[i] = Vec<2>{k * p.position[i][0], k * (p.position[i][1] - zc)};
  sph.update_state(1e-9, 1e-9);
  std::map<int, std::array<double, 5>> columns;  // D_rr, D_zz, D_tt, D_rz (/ k) and the count
  for (std::size_t i = 0; i < sph.size(); ++i) {
    if (p.position[i][1] < 0.4 || p.position[i][1] > 0.6) continue;
    auto& c = columns[static_cast<int>(p.position[i][0] / spacing)];
    const SymTensor& d = p.strain_rate[i];
    c[0] += d.xx / k, c[1] += d.yy / k, c[2] += d.zz / k, c[3] += d.xy / k, c[4] += 1;
  }
  const auto& interior = columns.at(6);
  double worst_in_plane = 0.0, worst_hoop = 0.0;
  for (const auto& [col, c] : columns) {
    if (col > 12) continue;  // the free outer surface (r = 0.3 m) and its neighbour
    std::printf("column %2d: D_rr %.5f D_zz %.5f D_tt %.5f D_rz %+.1e (/ k)\n", col, c[0] / c[4], c[1] / c[4],
                c[2] / c[4], c[3] / c[4]);
    worst_in_plane = std::max({worst_in_plane, std::abs(c[0] / c[4] - interior[0] / interior[4]),
                               std::abs(c[1] / c[4] - interior[1] / interior[4]), std::abs(c[3] / c[4])});
    worst_hoop = std::max(worst_hoop, std::abs(c[2] / c[4] - 1.0));
  }
  test::verify({"r-z SPH, uniform expansion from a point on the axis: in-plane strain rates of the columns up to "
                "12 spacings from the axis, largest difference from the seventh column's / k",
                "0 (the same rate in every column)", 0.0, worst_in_plane, 1e-3, false, "-"});
  test::verify({"r-z SPH, uniform expansion from a point on the axis: hoop strain rate v_r / r of the same "
                "columns / k",
                "exact (to k dt / 2 = 5e-8: v(n+1/2) over the mid-step radius)", 0.0, worst_hoop, 1e-6, false, "-"});
}

// [sph] smoothed_hoop: the hoop term with the ring sum's own weights and its conjugate hoop rate
// (sph_options.hpp; docs/theory/sph.md, "The hoop term smoothed as the ring sum is"). The ring
// sum's sigma_rr / r part is the kernel average sum_j V_j (r_j - r_i) dW/dr_i sigma_rr,j; a hoop
// term with the same weights cancels it for any sigma_rr = sigma_tt, where the point value
// sigma_tt,i leaves the lattice's 0.9 % kernel-gradient normalisation of p / r (the radial
// imbalance of HydrostaticGradientIsTheSameInEveryColumn, largest in the first column).
TEST(SphAxisSmoothedHoop, HydrostaticFieldLeavesNoRadialForceInAnyColumn) {
  SphOptions smoothed;
  smoothed.smoothed_hoop = true;
  const double p0 = 1e6, g = 1e6, spacing = 0.02;
  const auto columns = hydrostatic_column(p0, g, spacing, smoothed);
  double worst_axial = 0.0, worst_radial = 0.0;
  for (const auto& [k, c] : columns) {
    if (k > 12) continue;  // the free outer surface (r = 0.3 m) and its neighbour
    const double r = (k + 0.5) * spacing, pressure = p0 + g * 0.5;
    if (k < 3) worst_axial = std::max(worst_axial, std::abs(c.axial / -g - 1.0));
    worst_radial = std::max(worst_radial, std::abs(c.radial) * r / pressure);
  }
  test::verify({"r-z SPH with the smoothed hoop term, hydrostatic sigma = -p(z) I: radial force imbalance "
                "rho a_r r / p, largest over the columns up to 12 spacings from the axis",
                "0 to round-off (the point hoop term leaves the lattice's 0.009)", 0.0, worst_radial, 1e-12,
                false, "-"});
  test::verify({"r-z SPH with the smoothed hoop term, hydrostatic sigma = -p(z) I: rho a_z of the first three "
                "particle columns, largest relative error",
                "-dp/dz (exact); 0.9 % is the lattice's kernel-gradient normalisation, as in every column", 0.0,
                worst_axial, 0.02, false, "-"});
}

// The band next to the axis ([sph] smoothed_hoop_width): inside it the point term takes the
// shares' part, whose lattice normalisation differs from the ring sum's, so the hydrostatic
// imbalance there is the point term's, no larger.
TEST(SphAxisSmoothedHoop, HydrostaticImbalanceInTheBandIsNoLargerThanThePointTerms) {
  const double p0 = 1e6, g = 1e6, spacing = 0.02;
  auto worst_imbalance = [&](const SphOptions& options) {
    const auto columns = hydrostatic_column(p0, g, spacing, options);
    double worst = 0.0;
    for (const auto& [k, c] : columns)
      if (k <= 12) worst = std::max(worst, std::abs(c.radial) * (k + 0.5) * spacing / (p0 + g * 0.5));
    return worst;
  };
  SphOptions point, band;
  band.smoothed_hoop = true;
  band.smoothed_hoop_width = 1.0;
  const double worst_point = worst_imbalance(point), worst_band = worst_imbalance(band);
  std::printf("hydrostatic radial imbalance rho a_r r / p: point %.2e, band %.2e\n", worst_point, worst_band);
  test::record_check("r-z SPH with the smoothed hoop term and its band of one smoothing length, hydrostatic "
                     "sigma = -p(z) I: radial force imbalance rho a_r r / p, largest over the columns up to 12 "
                     "spacings from the axis",
                     "no larger than the point hoop term's (the lattice's kernel-gradient normalisation)",
                     fmt::format("{:.2e} (point term {:.2e})", worst_band, worst_point), worst_band <= worst_point);
}

// The Lame field of a pressurised sphere centred on the axis (SphericalEquilibriumField... above):
// sigma_rr != sigma_tt, and the smoothed hoop term averages sigma_tt over the kernel as the ring
// sum averages sigma_rr; their difference is right to the kernel's smoothing of a field curved on
// the scale R: recorded per column.
TEST(SphAxisSmoothedHoop, SphericalEquilibriumFieldRecorded) {
  const double p = 1e6, a = 0.1, zc = 0.5, spacing = 0.02;
  const auto lame = lame_field(p, a, zc);
  const double scale = 3.0 * p * std::pow(a / 0.3, 3) / 0.3;
  SphOptions smoothed;
  smoothed.smoothed_hoop = true;
  smoothed.artificial_stress = false;
  const auto columns = column_accelerations(lame, spacing, 0.15, 0.25, smoothed);
  for (int col = 0; col < 3; ++col) {
    const double f = columns.at(col).radial / scale;
    test::record_observation(fmt::format("r-z SPH with the smoothed hoop term, Lame field of a pressurised sphere "
                                         "centred on the axis (artificial stress off): radial force of column {} "
                                         "/ |d sigma / dR|",
                                         col + 1),
                             "0 within 0.02 (equilibrium; the point hoop term: -0.002, -0.0003, +0.0002)",
                             fmt::format("{:+.4f}", f), std::abs(f) < 0.02);
  }
}

// The conjugate hoop rate (2 pi rho / eta) sum_j V_j (r_j - r_i) dW/dr_i v_r,j in a uniform
// expansion v = k (x - c): the same in every column, the first included (its images carry the
// mirrored v_r), and equal to the in-plane rates: the same kernel-gradient normalisation in all
// three directions, where the point rate v_r / r is exact and the in-plane rates 0.991 k.
TEST(SphAxisSmoothedHoop, UniformExpansionHasOneRateInEveryColumnAndDirection) {
  const double k = 100.0, zc = 0.5, spacing = 0.02;
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  test::add_sph_part(model, "gas", test::ideal_gas("gas", 1000.0, 1.4, 1e5),
                     test::box_fill({0, 0, 0}, {0.3, 1, 0}, spacing));
  SphOptions smoothed;
  smoothed.smoothed_hoop = true;
  SphSystem<2> sph(model, smoothed);
  auto& p = sph.particles();
  for (std::size_t i = 0; i < sph.size(); ++i)
    p.velocity[i] = Vec<2>{k * p.position[i][0], k * (p.position[i][1] - zc)};
  sph.update_state(1e-9, 1e-9);
  std::map<int, std::array<double, 3>> columns;  // D_rr, D_tt (/ k) and the count
  for (std::size_t i = 0; i < sph.size(); ++i) {
    if (p.position[i][1] < 0.4 || p.position[i][1] > 0.6) continue;
    auto& c = columns[static_cast<int>(p.position[i][0] / spacing)];
    c[0] += p.strain_rate[i].xx / k, c[1] += p.strain_rate[i].zz / k, c[2] += 1;
  }
  double worst = 0.0;
  for (const auto& [col, c] : columns) {
    if (col > 12) continue;  // the free outer surface and its neighbour
    worst = std::max(worst, std::abs(c[1] / c[0] - 1.0));
  }
  test::verify({"r-z SPH with the smoothed hoop term, uniform expansion from a point on the axis: hoop strain "
                "rate over the radial rate, largest difference from 1 over the columns up to 12 spacings",
                "1 (isotropic; the point rate v_r / r: 1 / 0.991), to k dt / 2 = 5e-8 (rho and eta at the step's "
                "start)",
                0.0, worst, 1e-6, false, "-"});
}
