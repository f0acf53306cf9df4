// `camouflet sweep` (docs/buried-structure.md "Parameter studies"):
// the sweep file's expansion and its bad input, and a study of four tiny
// cases run through the executable: the CSV has one row per case with the
// varied keys, the status and the results; a case the generator refuses and
// one whose run (a child process) fails are recorded without stopping the
// others; the front wall's peak velocity grows with the charge mass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "case/run_executable.hpp"
#include "case/sweep_spec.hpp"
#include "common/verification.hpp"
#include "core/error.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

// A reduced paper case (tests/case/test_buried_regression.cpp, coarser): 1 kg
// TNT at 0.2 m, a 0.6 m x 0.4 m box 0.5 m away, SPH zone r <= 0.25 m, 0.5 ms; the charge's
// particles of about the zone's spacing (2 across its radius, as `camouflet generate` advises).
constexpr const char* tiny_base = R"(title = "tiny sweep base"
[charge]
mass = 1.0
depth = 0.2
particles_across_radius = 2
[structure]
standoff = 0.5
length = 0.6
height = 0.4
wall_thickness = 0.06
[sph]
radius = 0.25
[domain]
radius = 1.6
depth = 1.2
[mesh]
near_radius = 0.2
near = 0.03
structure = 0.05
soil = 0.12
far = 0.3
[run]
end_time = 0.5e-3
field_interval = 0.0
gauge_interval = 1e-5
[gauges]
count = 3
)";

fs::path folder(const std::string& name) {
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A sweep file next to the tiny base; returns its path.
fs::path sweep_file(const fs::path& dir, const std::string& body) {
  write(dir / "tiny.params.toml", tiny_base);
  write(dir / "study.sweep.toml", "base = \"tiny.params.toml\"\n" + body);
  return dir / "study.sweep.toml";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cell += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  out.push_back(cell);
  return out;
}

// sweep.csv as rows of {column: text}, and its header.
std::vector<std::map<std::string, std::string>> read_rows(const fs::path& csv,
                                                          std::vector<std::string>& header) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  header = split_csv_line(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const auto cells = split_csv_line(line);
    auto& row = rows.emplace_back();
    for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k) row[header[k]] = cells[k];
  }
  return rows;
}

TEST(SweepFile, GridExpandsEveryCombinationWithTheCommonValues) {
  const fs::path dir = folder("sweep_grid");
  const fs::path file = sweep_file(dir,
                                   "[set]\n"
                                   "run.end_time = 1e-4\n"
                                   "[grid]\n"
                                   "charge.mass = [0.5, 1.0]\n"
                                   "\"structure.standoff\" = [0.5, 0.6, 0.7]\n");
  const SweepSpec s = read_sweep(file);
  ASSERT_EQ(s.cases.size(), 6u);
  EXPECT_EQ(s.varied_keys, (std::vector<std::string>{"charge.mass", "structure.standoff"}));
  EXPECT_EQ(s.cases[0].name, "case_1");
  EXPECT_EQ(s.cases[5].name, "case_6");
  // The last key varies fastest.
  EXPECT_EQ(s.cases[1].values, (std::vector<std::string>{"0.5", "0.6"}));
  EXPECT_EQ(s.cases[3].values, (std::vector<std::string>{"1", "0.5"}));
  const auto& p = s.cases[4].params;
  EXPECT_DOUBLE_EQ(p["charge"]["mass"].value_or(0.0), 1.0);
  EXPECT_DOUBLE_EQ(p["structure"]["standoff"].value_or(0.0), 0.6);
  EXPECT_DOUBLE_EQ(p["run"]["end_time"].value_or(0.0), 1e-4);
  EXPECT_DOUBLE_EQ(p["structure"]["length"].value_or(0.0), 0.6);  // from the base
  EXPECT_NE(sweep_case_params_text(s, s.cases[4]).find("structure.standoff = 0.6"), std::string::npos);
}

TEST(SweepFile, ListCasesTakeTheirNames) {
  const fs::path dir = folder("sweep_list");
  const SweepSpec s = read_sweep(sweep_file(dir,
                                            "[[case]]\nname = \"light\"\ncharge.mass = 0.5\n"
                                            "[[case]]\nsoil.preset = \"sandy_clay_wang2005\"\n"));
  ASSERT_EQ(s.cases.size(), 2u);
  EXPECT_EQ(s.cases[0].name, "light");
  EXPECT_EQ(s.cases[1].name, "case_2");
  EXPECT_EQ(s.varied_keys, (std::vector<std::string>{"charge.mass", "soil.preset"}));
  EXPECT_EQ(s.cases[0].values, (std::vector<std::string>{"0.5", ""}));
  EXPECT_EQ(s.cases[1].values, (std::vector<std::string>{"", "sandy_clay_wang2005"}));
}

// The examples of docs/buried-structure.md read and expand.
TEST(SweepFile, ExamplesInCasesSweepsRead) {
  const fs::path dir = fs::path(CAMOUFLET_SOURCE_DIR) / "cases" / "sweeps";
  const SweepSpec grid = read_sweep(dir / "charge_standoff.sweep.toml");
  EXPECT_EQ(grid.cases.size(), 6u);
  EXPECT_DOUBLE_EQ(grid.cases[0].params["run"]["end_time"].value_or(0.0), 0.03);
  const SweepSpec list = read_sweep(dir / "soil.sweep.toml");
  ASSERT_EQ(list.cases.size(), 2u);
  EXPECT_EQ(list.cases[1].name, "seismic");
}

// Bad input: status 2 and one line naming the sweep file, the line and the key.
TEST(SweepCommand, BadInputNamesFileLineAndKey) {
  const fs::path dir = folder("sweep_bad");
  struct Bad {
    std::string body;
    std::string expected;  // part of the message
  };
  const Bad cases[] = {
      {"[grid]\ncharge.mas = [1.0, 2.0]\n",
       "study.sweep.toml:3: key 'charge.mas': case 'case_1': unknown key"},
      {"[grid]\ncharge.mass = []\n", "study.sweep.toml:3: key 'charge.mass': empty list"},
      {"[grid]\ncharge.mass = [1.0, \"heavy\"]\n",
       "study.sweep.toml:3: key 'charge.mass': case 'case_2': expected a number"},
      {"[grid]\ncharge.mass = 1.0\n", "study.sweep.toml:3: key 'charge.mass': expected a list of values"},
      {"[set]\ncharge.mass = 2.0\n", "key 'grid': a sweep needs"},
      {"[grid]\ncharge.mass = [1.0]\n[[case]]\ncharge.depth = 0.3\n", "key 'case': give either"},
      {"[set]\ncharge.mass = 2.0\n[[case]]\ncharge.mass = 1.0\n",
       "study.sweep.toml:5: key 'charge.mass': 'charge.mass' is also given in [set]"},
      {"repeats = 2\n[grid]\ncharge.mass = [1.0]\n", "study.sweep.toml:2: key 'repeats': unknown key"},
      {"[grid]\ncharge.mass = [1.0]\nrepeats = 2\n", "study.sweep.toml:4: key 'repeats': expected a list"},
  };
  for (const Bad& b : cases) {
    const fs::path file = sweep_file(dir, b.body);
    const auto r = test::run_camouflet("sweep '" + file.string() + "' -o '" + (dir / "out").string() + "'");
    EXPECT_EQ(r.status, 2) << b.body << r.output;
    EXPECT_NE(r.output.find(b.expected), std::string::npos) << b.body << "\n" << r.output;
  }
  write(dir / "missing.sweep.toml", "base = \"nowhere.params.toml\"\n[grid]\ncharge.mass = [1.0]\n");
  const auto r = test::run_camouflet("sweep '" + (dir / "missing.sweep.toml").string() + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("missing.sweep.toml:1: key 'base': cannot open the base parameter file"),
            std::string::npos)
      << r.output;
}

TEST(SweepCommand, RunsEveryCaseAndRecordsTheFailedOnes) {
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import numpy'").status != 0)
    GTEST_SKIP() << "python3-numpy is not installed: sweep.csv is not collected";
  const fs::path dir = folder("sweep_run");
  const fs::path file = sweep_file(dir,
                                   "[[case]]\nname = \"light\"\ncharge.mass = 1.0\n"
                                   "[[case]]\nname = \"overlap\"\nstructure.standoff = 0.1\n"
                                   "[[case]]\nname = \"heavy\"\ncharge.mass = 2.0\n"
                                   "[[case]]\nname = \"badsoil\"\nsoil.preset = \"no_such_soil\"\n");
  const fs::path out = dir / "out";
  const auto r = test::run_camouflet("sweep '" + file.string() + "' -o '" + out.string() + "' --jobs 2");
  std::cout << r.output;
  EXPECT_EQ(r.status, 1) << "two cases fail: status 1 " << r.output;
  std::vector<std::string> header;
  const auto rows = read_rows(out / "sweep.csv", header);
  ASSERT_EQ(rows.size(), 4u) << r.output;
  for (const char* column : {"case",
                             "charge.mass",
                             "structure.standoff",
                             "soil.preset",
                             "status",
                             "message",
                             "wall_s",
                             "front_wall_member_peak_velocity_m_s",
                             "floor_member_peak_velocity_m_s",
                             "front_wall_member_filtered_acceleration_g",
                             "t9_peak_normal_stress_MPa",
                             "t9_filtered_normal_stress_MPa",
                             "front_wall_lower_mean_damage",
                             "front_wall_upper_mean_damage",
                             "front_wall_peak_velocity_m_s",
                             "floor_peak_velocity_m_s",
                             "front_wall_peak_acceleration_g",
                             "floor_peak_acceleration_g",
                             "tm5_velocity_low_m_s",
                             "tm5_velocity_high_m_s",
                             "front_wall_peak_deflection_mm",
                             "front_wall_final_displacement_mm",
                             "max_damage",
                             "max_damage_member",
                             "crater_radius_m",
                             "crater_depth_m",
                             "energy_error"})
    EXPECT_NE(std::find(header.begin(), header.end(), column), header.end()) << column;
  const auto& light = rows[0];
  const auto& overlap = rows[1];
  const auto& heavy = rows[2];
  const auto& badsoil = rows[3];
  EXPECT_EQ(light.at("case"), "light");
  EXPECT_EQ(light.at("charge.mass"), "1");
  EXPECT_EQ(light.at("status"), "0");
  EXPECT_EQ(heavy.at("status"), "0");
  EXPECT_EQ(overlap.at("status"), "2");
  // The generator's own message, naming the case's parameter file.
  EXPECT_NE(overlap.at("message").find("overlap/input.params.toml"), std::string::npos)
      << overlap.at("message");
  EXPECT_NE(overlap.at("message").find("crosses the structure"), std::string::npos) << overlap.at("message");
  EXPECT_EQ(overlap.at("front_wall_peak_velocity_m_s"), "");
  // Generated, but its run (a child process) refuses the case: the child's error line.
  EXPECT_EQ(badsoil.at("status"), "2");
  EXPECT_NE(badsoil.at("message").find("unknown material preset 'no_such_soil'"), std::string::npos)
      << badsoil.at("message");
  const double v_light = std::stod(light.at("front_wall_peak_velocity_m_s"));
  const double v_heavy = std::stod(heavy.at("front_wall_peak_velocity_m_s"));
  std::cout << "front-wall peak velocity: 1 kg " << v_light << " m/s, 2 kg " << v_heavy << " m/s\n";
  EXPECT_GT(v_light, 0.0);
  // Twice the charge: a stronger ground shock at the wall.
  EXPECT_GT(v_heavy, 1.3 * v_light);
  test::record_check(
      "camouflet sweep of a tiny buried-structure case, 1 kg and 2 kg TNT at 0.5 m: front-wall peak "
      "horizontal velocity",
      "grows with the charge mass (more than 1.3x for twice the mass)",
      std::to_string(v_light) + " -> " + std::to_string(v_heavy) + " m/s", v_heavy > 1.3 * v_light);
  for (const auto* row : {&light, &heavy}) {
    EXPECT_LT(std::stod(row->at("energy_error")), 0.1);
    EXPECT_GT(std::stod(row->at("tm5_velocity_high_m_s")), std::stod(row->at("tm5_velocity_low_m_s")));
    EXPECT_TRUE(fs::exists(out / row->at("case") / "summary.json"));
    EXPECT_TRUE(fs::exists(out / row->at("case") / "input.params.toml"));
  }
  // The member average and the interface stress grow with the charge too.
  EXPECT_GT(std::stod(heavy.at("front_wall_member_peak_velocity_m_s")),
            std::stod(light.at("front_wall_member_peak_velocity_m_s")));
  EXPECT_GT(std::stod(heavy.at("t9_peak_normal_stress_MPa")), std::stod(light.at("t9_peak_normal_stress_MPa")));
  // The TM-5 averages grow with the charge too.
  EXPECT_GT(std::stod(heavy.at("tm5_velocity_low_m_s")), std::stod(light.at("tm5_velocity_low_m_s")));
  if (test::run_camouflet_raw("/usr/bin/python3 -c 'import matplotlib'").status == 0) {
    EXPECT_TRUE(fs::exists(out / "sweep.png"));
  }
}

}  // namespace
}  // namespace camouflet
