// The headline results that `camouflet report` and `camouflet sweep` share
// (scripts/run_metrics.py, docs/buried-structure.md "Parameter studies"),
// checked on a synthetic output folder whose answers are known by
// construction: a soil grid with a paraboloid bowl pressed into it and soil
// particles thrown above it (ejecta, which must not fill the crater), and a
// box whose elements carry a prescribed damage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "case/run_executable.hpp"
#include "common/verification.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

constexpr double dz = 0.05;                 // m, grid spacing
constexpr double bowl_radius = 0.6;         // m
constexpr double bowl_depth = 0.3;          // m
constexpr double depth_of_burst = 0.3;      // m
constexpr double r1 = 2.0, r2 = 3.0;        // m, the box's front and back faces
constexpr double height = 0.5, wall = 0.1;  // m

struct Grid {
  std::vector<double> ref, u;  // node positions and displacements (x, y, 0)
  std::vector<int> conn;
  std::vector<double> damage;
  std::vector<int> material;
};

// Soil r in [0, 3.5], z in [-1.5, 0]; the box's interior has no cells.
Grid synthetic_grid() {
  Grid g;
  const int nr = 70, nz = 30;
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nr; ++i) {
      const double r = i * dz, z = -1.5 + j * dz;
      g.ref.insert(g.ref.end(), {r, z, 0.0});
      const double sink = r < bowl_radius ? bowl_depth * (1.0 - (r / bowl_radius) * (r / bowl_radius)) : 0.0;
      g.u.insert(g.u.end(), {0.0, -sink, 0.0});
    }
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nr; ++i) {
      const double rc = (i + 0.5) * dz, zc = -1.5 + (j + 0.5) * dz;
      const bool in_box = rc > r1 && rc < r2 && zc > -height;
      const bool interior = in_box && rc > r1 + wall && rc < r2 - wall && zc < -wall && zc > -height + wall;
      if (interior) continue;
      const int n0 = j * (nr + 1) + i;
      g.conn.insert(g.conn.end(), {n0, n0 + 1, n0 + nr + 2, n0 + nr + 1});
      int m = 0;  // soil
      double d = 0.0;
      if (std::hypot(rc, zc + depth_of_burst) < 0.1) m = 1;  // the charge
      if (in_box) {
        m = 2;
        if (rc < r1 + wall)
          d = zc > -0.25 ? 0.8 : 0.1;  // front wall: mean 0.45
        else if (zc > -wall && rc < r2 - wall)
          d = 0.05;  // roof
      }
      g.material.push_back(m);
      g.damage.push_back(d);
    }
  return g;
}

template <class T>
void array(std::ostream& o, const char* type, const char* name, int components, const std::vector<T>& v) {
  o << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
    << "\" format=\"ascii\">";
  for (const T& x : v) o << x << ' ';
  o << "</DataArray>\n";
}

void write_vtu(const fs::path& path, const std::vector<double>& x, const std::vector<double>& u,
               const std::vector<int>& conn, int per_cell, const std::vector<double>& cell_damage,
               const std::vector<int>& cell_material, bool point_fields) {
  std::ofstream o(path);
  const std::size_t n = x.size() / 3, m = conn.size() / per_cell;
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n<UnstructuredGrid>\n"
    << "<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << m << "\">\n<PointData>\n";
  array(o, "Float64", "displacement", 3, u);
  if (point_fields) {
    array(o, "Float64", "damage", 1, cell_damage);
    array(o, "Int32", "material", 1, cell_material);
  }
  o << "</PointData>\n<CellData>\n";
  if (!point_fields) {
    array(o, "Float64", "damage", 1, cell_damage);
    array(o, "Int32", "material", 1, cell_material);
  }
  o << "</CellData>\n<Points>\n";
  array(o, "Float64", "position", 3, x);
  o << "</Points>\n<Cells>\n";
  std::vector<int> offsets, types;
  for (std::size_t c = 0; c < m; ++c) {
    offsets.push_back(static_cast<int>((c + 1) * per_cell));
    types.push_back(per_cell == 8 ? 12 : per_cell == 4 ? 9 : 1);  // hexahedron, quad, vertex
  }
  array(o, "Int64", "connectivity", 1, conn);
  array(o, "Int64", "offsets", 1, offsets);
  array(o, "UInt8", "types", 1, types);
  o << "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

// Ejecta: six soil particles from the bowl, now about 1 m above the ground (in
// 3-D at several azimuths), which must not fill the crater; and fields.pvd
// naming the mesh snapshot fields_0001.vtu and these particles at t = 0.01 s
// (in r-z after an entry at t = 0 whose file is missing, which must not matter).
void write_ejecta_and_collection(const fs::path& dir, bool three_d) {
  std::vector<double> px, pu, pdamage;
  std::vector<int> pconn, pmat;
  for (int k = 0; k < 6; ++k) {
    const double r = 0.025 + 0.1 * k, angle = 0.25 * k;
    if (three_d) {
      px.insert(px.end(), {r * std::cos(angle), r * std::sin(angle), 1.0});
      pu.insert(pu.end(), {0.0, 0.0, 1.05});
    } else {
      px.insert(px.end(), {r, 1.0, 0.0});
      pu.insert(pu.end(), {0.0, 1.05, 0.0});
    }
    pconn.push_back(k);
    pmat.push_back(0);
    pdamage.push_back(0.0);
  }
  write_vtu(dir / "particles_0001.vtu", px, pu, pconn, 1, pdamage, pmat, true);
  std::ofstream(dir / "fields.pvd")
      << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
      << (three_d ? "" : "<DataSet timestep=\"0\" part=\"0\" file=\"missing_0000.vtu\"/>\n")
      << "<DataSet timestep=\"0.01\" part=\"0\" file=\"fields_0001.vtu\"/>\n"
         "<DataSet timestep=\"0.01\" part=\"1\" file=\"particles_0001.vtu\"/>\n"
         "</Collection>\n</VTKFile>\n";
}

// run_metrics(folder) as {key: text}.
std::map<std::string, std::string> metrics(const fs::path& dir) {
  const std::string script = std::string(CAMOUFLET_SOURCE_DIR) + "/scripts";
  const auto r = test::run_camouflet_raw("/usr/bin/python3 -c \"import sys; sys.path.insert(0, '" + script +
                                         "'); import run_metrics as m\nfor k, v in m.run_metrics('" +
                                         dir.string() + "').items(): print(k, v)\"");
  EXPECT_EQ(r.status, 0) << r.output;
  std::map<std::string, std::string> out;
  std::istringstream in(r.output);
  for (std::string key, value; in >> key && std::getline(in, value);) out[key] = value.substr(1);
  return out;
}

// An r-z output folder `name` under test-output: the generator line of the synthetic box, the
// given summary.json, the grid `g` as the last mesh snapshot (x = ref + u) and the ejecta above it.
fs::path write_rz_output(const std::string& name, const Grid& g, const std::string& summary) {
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << "# generator: charge_mass_kg=1 burst_depth_m=" << depth_of_burst
                                   << " standoff_m=" << r1 << " box_length_m=" << r2 - r1
                                   << " box_height_m=" << height << " wall_thickness_m=" << wall
                                   << " top_depth_m=0\n";
  std::ofstream(dir / "summary.json") << summary;
  std::vector<double> x(g.ref.size());
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = g.ref[k] + g.u[k];
  write_vtu(dir / "fields_0001.vtu", x, g.u, g.conn, 4, g.damage, g.material, false);
  write_ejecta_and_collection(dir, false);
  return dir;
}

TEST(RunMetrics, CraterAndDamageOfASyntheticOutput) {
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy'").status != 0)
    GTEST_SKIP() << "python3-numpy is not installed";
  const fs::path dir = write_rz_output("run_metrics", synthetic_grid(),
                                       "{\"final_time_s\": 0.01, \"stop_reason\": \"end time reached\", "
                                       "\"energy_J\": {\"relative_error\": 0.012}}\n");

  const auto m = metrics(dir);
  ASSERT_TRUE(m.count("crater_radius_m")) << "no output";
  // The bowl's rim is resolved to one bin (dz); its depth exactly (the node on the axis).
  test::verify({"Apparent crater of a synthetic paraboloid bowl with ejecta above it: radius",
                "the bowl's radius (by construction), within one bin dz = 0.05 m", bowl_radius,
                std::stod(m.at("crater_radius_m")), dz, false, "m"});
  test::verify({"Apparent crater of a synthetic paraboloid bowl with ejecta above it: depth",
                "the bowl's depth (by construction)", bowl_depth, std::stod(m.at("crater_depth_m")), 1e-6,
                false, "m"});
  test::verify({"Box damage of a synthetic output: front-wall mean", "0.8 on the upper half, 0.1 below", 0.45,
                std::stod(m.at("front_wall_mean_damage")), 1e-9, false, "-"});
  EXPECT_DOUBLE_EQ(std::stod(m.at("max_damage")), 0.8);
  EXPECT_EQ(m.at("max_damage_member"), "front wall");
  EXPECT_DOUBLE_EQ(std::stod(m.at("other_members_mean_damage")), 0.05);  // the roof
  EXPECT_DOUBLE_EQ(std::stod(m.at("energy_error")), 0.012);
}

// After a dynamic relaxation the reference state (x - u, u counted from the relaxed state) is the
// relaxed mesh, whose layers have settled by microns, unevenly: the layer spacing the bins are
// made of must still be the mesh's, not the microns between two settled nodes of one layer.
TEST(RunMetrics, CraterOfARelaxedOutputWithUnevenlySettledLayers) {
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy'").status != 0)
    GTEST_SKIP() << "python3-numpy is not installed";
  Grid g = synthetic_grid();
  for (std::size_t k = 0; k < g.ref.size(); k += 3) g.ref[k + 1] -= 4e-6 * static_cast<double>((k / 3) % 3);
  const fs::path dir = write_rz_output("run_metrics_relaxed", g,
                                       "{\"final_time_s\": 0.01, \"stop_reason\": \"end time reached\"}\n");

  const auto m = metrics(dir);
  ASSERT_TRUE(m.count("crater_radius_m")) << "no output";
  test::verify(
      {"Apparent crater of a synthetic bowl in a relaxed mesh (layers settled by 0-8 microns): radius",
       "the bowl's radius (by construction), within one bin dz = 0.05 m", bowl_radius,
       std::stod(m.at("crater_radius_m")), dz, false, "m"});
  test::verify(
      {"Apparent crater of a synthetic bowl in a relaxed mesh (layers settled by 0-8 microns): depth",
       "the bowl's depth (by construction), within the settlement", bowl_depth,
       std::stod(m.at("crater_depth_m")), 1e-5, false, "m"});
}

// The same bowl in a 3-D quarter model (x, y >= 0 about the charge's vertical
// axis, hexahedra of dz): r = sqrt(x^2 + y^2), each bin a ring. The ring's top
// is its highest ground point, so the radius is the edge of the last bin whose
// every point is depressed by more than dz / 2: the bowl's depression is dz / 2
// at r* = R sqrt(1 - dz / (2 depth)), and the radius lies within one bin of it.
TEST(RunMetrics, CraterOfASyntheticThreeDimensionalOutput) {
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy'").status != 0)
    GTEST_SKIP() << "python3-numpy is not installed";
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "run_metrics_3d";
  fs::remove_all(dir);
  fs::create_directories(dir);
  constexpr double front = 1.0, back = 1.4, box_height = 0.3, half_width = 0.3;  // m
  std::ofstream(dir / "case.toml") << "# generator: charge_mass_kg=1 burst_depth_m=" << depth_of_burst
                                   << " standoff_m=" << front << " box_length_m=" << back - front
                                   << " box_height_m=" << box_height << " wall_thickness_m=" << wall
                                   << " top_depth_m=0 box_width_m=" << 2.0 * half_width << " three_d=1\n";
  std::ofstream(dir / "summary.json") << "{\"final_time_s\": 0.01, \"stop_reason\": \"end time reached\"}\n";
  const int n = 30, nz = 12;  // cells along x and y (1.5 m), and down (0.6 m)
  const auto node = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  std::vector<double> x, u, damage;
  std::vector<int> conn, material;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double px = i * dz, py = j * dz, pz = -nz * dz + k * dz, rho = std::hypot(px, py);
        const double sink =
            rho < bowl_radius ? bowl_depth * (1.0 - (rho / bowl_radius) * (rho / bowl_radius)) : 0.0;
        x.insert(x.end(), {px, py, pz - sink});
        u.insert(u.end(), {0.0, 0.0, -sink});
      }
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double xc = (i + 0.5) * dz, yc = (j + 0.5) * dz, zc = -nz * dz + (k + 0.5) * dz;
        const bool in_box = xc > front && xc < back && yc < half_width && zc > -box_height;
        if (in_box && xc > front + wall && xc < back - wall && yc < half_width - wall && zc < -wall &&
            zc > -box_height + wall)
          continue;  // the box is hollow
        conn.insert(conn.end(), {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                                 node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                                 node(i, j + 1, k + 1)});
        material.push_back(in_box ? 2 : std::hypot(xc, yc, zc + depth_of_burst) < 0.1 ? 1 : 0);
        damage.push_back(0.0);
      }
  write_vtu(dir / "fields_0001.vtu", x, u, conn, 8, damage, material, false);
  write_ejecta_and_collection(dir, true);

  const auto m = metrics(dir);
  ASSERT_TRUE(m.count("crater_radius_m")) << "no output";
  const double rim = bowl_radius * std::sqrt(1.0 - dz / (2.0 * bowl_depth));
  test::verify({"Apparent crater of a synthetic 3-D quarter bowl with ejecta above it: radius",
                "where the bowl's depression is dz / 2 (by construction), within one ring bin dz = 0.05 m",
                rim, std::stod(m.at("crater_radius_m")), dz, false, "m"});
  test::verify({"Apparent crater of a synthetic 3-D quarter bowl with ejecta above it: depth",
                "the bowl's depth (by construction)", bowl_depth, std::stod(m.at("crater_depth_m")), 1e-6,
                false, "m"});
}

// The member averages and the interface stress that the TM 5-855-1 comparison and the
// structure-response study read (members.csv, structure.csv's t9), from synthetic histories
// sampled every 50 us with the gauges' jitter (a row at the first cycle past each interval):
// a smooth velocity pulse v = V sin^2(pi t / T) has its acceleration's peak V pi / T, which the
// 1 kHz low-pass keeps (T = 10 ms: 100 Hz, gain 1 - 4e-5); the interface stress is a pulse of
// peak P with a 5 kHz ripple of 0.3 P, which the low-pass removes (gain 0.004) and the raw peak keeps.
TEST(RunMetrics, MemberAveragesAndInterfaceStressOfSyntheticHistories) {
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy, scipy'").status != 0)
    GTEST_SKIP() << "python3-numpy or python3-scipy is not installed";
  const fs::path dir = write_rz_output("run_metrics_members", synthetic_grid(),
                                       "{\"final_time_s\": 0.02, \"stop_reason\": \"end time reached\"}\n");
  constexpr double V = 0.5, T = 0.01, P = 2e6, ripple_hz = 5000.0;  // m/s, s, Pa, Hz
  const double pi = std::acos(-1.0), g = 9.80665;
  std::ofstream members(dir / "members.csv"), structure(dir / "structure.csv");
  members << "time_s,front_wall.velocity_x,floor.velocity_y\n";
  structure << "time_s,t9.stress_xx\n";
  members.precision(17);
  structure.precision(17);
  double raw_peak = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const double t = k * 5e-5 + (k % 3 == 1 ? 2e-7 : 0.0);
    const double pulse = t < T ? std::pow(std::sin(pi * t / T), 2) : 0.0;
    const double normal = P * pulse + 0.3 * P * std::sin(2.0 * pi * ripple_hz * t);
    raw_peak = std::max(raw_peak, normal);
    members << t << ',' << V * pulse << ',' << -2.0 * V * pulse << '\n';
    structure << t << ',' << -normal << '\n';
  }
  members.close();
  structure.close();

  const auto m = metrics(dir);
  ASSERT_TRUE(m.count("front_wall_member_peak_velocity_m_s")) << "no output";
  test::verify({"Member average of a synthetic velocity pulse V sin^2(pi t/T): front wall, peak velocity",
                "V = 0.5 m/s (by construction)", V, std::stod(m.at("front_wall_member_peak_velocity_m_s")),
                1e-3, true, "m/s"});
  test::verify({"Member average of a synthetic velocity pulse, T = 10 ms: front wall, 1 kHz low-passed "
                "acceleration",
                "V pi / T = 16.02 g (the pulse's 100 Hz lies in the pass band)", V * pi / T / g,
                std::stod(m.at("front_wall_member_filtered_acceleration_g")), 5e-3, true, "g"});
  test::verify({"Member average of a synthetic velocity pulse, T = 10 ms: floor (downwards, 2V), 1 kHz "
                "low-passed acceleration",
                "2 V pi / T = 32.04 g", 2.0 * V * pi / T / g,
                std::stod(m.at("floor_member_filtered_acceleration_g")), 5e-3, true, "g"});
  test::verify({"Interface stress at t9, a 2 MPa pulse with a 5 kHz ripple of 0.3 P: raw peak",
                "the largest sample (by construction)", raw_peak / 1e6,
                std::stod(m.at("t9_peak_normal_stress_MPa")), 1e-9, true, "MPa"});
  test::verify({"Interface stress at t9, a 2 MPa pulse with a 5 kHz ripple of 0.3 P: 1 kHz low-passed peak",
                "P = 2 MPa (the ripple attenuated to 0.4 %)", P / 1e6,
                std::stod(m.at("t9_filtered_normal_stress_MPa")), 5e-3, true, "MPa"});
}

}  // namespace
}  // namespace camouflet
