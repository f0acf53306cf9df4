// The output folder read back: gauge CSV (header, complete rows, values),
// VTU snapshots (well-formed XML, array lengths match point and cell counts),
// the .pvd index (lists files that exist) and summary.json (peaks).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "output/run_output.hpp"
#include "output/summary_json.hpp"
#include "snapshot_fixture.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;
using test::SnapshotFixture;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Minimal XML check: every element closed in order; returns the arrays' token
// counts by Name (the last Piece's), and the Piece attributes.
struct XmlSummary {
  bool well_formed = true;
  std::map<std::string, std::size_t> array_tokens;
  std::map<std::string, int> array_components;
  long points = -1, cells = -1;
};

long attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return -1;
  return std::stol(tag.substr(at + name.size() + 3));
}
std::string attribute_text(const std::string& tag, const std::string& name) {
  const auto at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return {};
  const auto start = at + name.size() + 3;
  return tag.substr(start, tag.find('"', start) - start);
}

XmlSummary parse_xml(const std::string& text) {
  XmlSummary r;
  std::vector<std::string> stack;
  std::size_t pos = 0;
  while ((pos = text.find('<', pos)) != std::string::npos) {
    const auto end = text.find('>', pos);
    if (end == std::string::npos) {
      r.well_formed = false;
      break;
    }
    const std::string tag = text.substr(pos + 1, end - pos - 1);
    if (tag[0] == '?') {
      pos = end + 1;
      continue;
    }
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != tag.substr(1)) r.well_formed = false;
      if (!stack.empty()) stack.pop_back();
    } else {
      const std::string name = tag.substr(0, tag.find_first_of(" /"));
      if (name == "Piece") {
        r.points = attribute(tag, "NumberOfPoints");
        r.cells = attribute(tag, "NumberOfCells");
      }
      if (name == "DataArray") {
        const auto close = text.find("</DataArray>", end);
        std::istringstream body(text.substr(end + 1, close - end - 1));
        std::string token;
        std::size_t n = 0;
        while (body >> token) ++n;
        r.array_tokens[attribute_text(tag, "Name")] = n;
        r.array_components[attribute_text(tag, "Name")] =
            static_cast<int>(attribute(tag, "NumberOfComponents"));
      }
      if (tag.back() != '/') stack.push_back(name);
    }
    pos = end + 1;
  }
  if (!stack.empty()) r.well_formed = false;
  return r;
}

TEST(OutputFiles, FolderReadsBack) {
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "files";
  fs::remove_all(dir);
  const fs::path case_file = dir.parent_path() / "files_case.toml";
  fs::create_directories(dir.parent_path());
  std::ofstream(case_file) << "# a case\n";

  auto f = SnapshotFixture::distorted(2, 3);
  Model model;
  model.case_file = case_file.string();
  model.run.end_time = 1.0;
  model.output.gauge_interval = 0.1;
  model.output.field_interval = 0.5;
  GaugeGroup group;
  group.name = "column";
  group.points = {{"a", {0.5, 0.5, 0.0}, {}}, {"b", {0.7, 0.8, 0.0}, {}}};
  model.gauges.push_back(group);
  RunOptions options;
  options.output_dir = dir;

  f.set_linear_fields(0.0);
  RunOutput out(model, options, f.view(0.0, 0));
  const int cycles = 40;  // dt = 0.025: a gauge row every 4 cycles, a snapshot at 0.5 and 1.0
  for (int c = 1; c <= cycles; ++c) {
    const double t = c * 0.025;
    f.pressure[4] = 1e6 * std::sin(3.0 * t);  // peak 1e6 at t = pi/6 ~ 0.5236 (sampled: 0.5)
    f.set_linear_fields(t);
    out.after_cycle(f.view(t, c));
  }
  RunSummary summary;
  summary.time = 1.0;
  summary.cycles = cycles;
  summary.stop_reason = "end time reached";
  summary.energy.relative_error = 1e-6;
  out.finish(f.view(1.0, cycles), summary);

  // case copy
  EXPECT_EQ(slurp(dir / "case.toml"), "# a case\n");

  // CSV: header, 11 rows (t = 0, 0.1 .. 1.0), every row complete
  std::ifstream csv(dir / "column.csv");
  std::string line;
  std::getline(csv, line);
  const std::size_t columns = static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
  EXPECT_EQ(line.rfind("time_s,a.position_x,a.position_y,a.displacement_x", 0), 0u) << line;
  EXPECT_NE(line.find("b.stress_zx,b.pressure,b.plastic_strain,b.damage,b.temperature"), std::string::npos)
      << line;
  EXPECT_EQ(columns, 1 + 2 * (4 * 2 + 10));
  int rows = 0;
  double last_time = -1.0;
  while (std::getline(csv, line)) {
    ++rows;
    EXPECT_EQ(static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1, columns);
    last_time = std::stod(line.substr(0, line.find(',')));
  }
  EXPECT_EQ(rows, 11);
  EXPECT_DOUBLE_EQ(last_time, 1.0);
  EXPECT_EQ(out.gauges()[0].time.size(), 11u);

  // VTU snapshots at t = 0, 0.5, 1.0
  for (const char* name : {"fields_0000.vtu", "fields_0001.vtu", "fields_0002.vtu"}) {
    ASSERT_TRUE(fs::exists(dir / name)) << name;
    const XmlSummary x = parse_xml(slurp(dir / name));
    EXPECT_TRUE(x.well_formed) << name;
    EXPECT_EQ(x.points, 16);
    EXPECT_EQ(x.cells, 9);
    EXPECT_EQ(x.array_tokens.at("position"), 16u * 3);
    EXPECT_EQ(x.array_tokens.at("velocity"), 16u * 3);
    EXPECT_EQ(x.array_tokens.at("displacement"), 16u * 3);
    EXPECT_EQ(x.array_tokens.at("acceleration"), 16u * 3);
    EXPECT_EQ(x.array_tokens.at("connectivity"), 9u * 4);
    EXPECT_EQ(x.array_tokens.at("offsets"), 9u);
    EXPECT_EQ(x.array_tokens.at("types"), 9u);
    EXPECT_EQ(x.array_tokens.at("stress"), 9u * 6);
    EXPECT_EQ(x.array_components.at("stress"), 6);
    for (const char* cell : {"density", "pressure", "plastic_strain", "damage", "temperature", "material"})
      EXPECT_EQ(x.array_tokens.at(cell), 9u) << cell;
  }
  EXPECT_FALSE(fs::exists(dir / "fields_0003.vtu"));

  // PVD lists exactly those files, all of which exist
  const std::string pvd = slurp(dir / "fields.pvd");
  EXPECT_TRUE(parse_xml(pvd).well_formed);
  int listed = 0;
  for (std::size_t p = 0; (p = pvd.find("file=\"", p)) != std::string::npos; ++listed) {
    p += 6;
    EXPECT_TRUE(fs::exists(dir / pvd.substr(p, pvd.find('"', p) - p)));
  }
  EXPECT_EQ(listed, 3);

  // summary.json: the pressure peak of the gauge in element 4 is the sample at t = 0.5
  const std::string json = slurp(dir / "summary.json");
  EXPECT_NE(json.find("\"stop_reason\": \"end time reached\""), std::string::npos);
  EXPECT_NE(json.find("\"relative_error\": 9.9999999999999995e-07"), std::string::npos)
      << json.substr(0, 800);
  EXPECT_NE(json.find("\"cycles\": 40"), std::string::npos);
  const auto& series = out.gauges()[0];
  std::size_t q_pressure = 0;
  while (series.quantities[q_pressure] != "pressure") ++q_pressure;
  // Gauge "a" at the centre sits in element 4 (the middle one of 3 x 3).
  const Peak pk = peak_of(series.values[q_pressure][0], series.time);
  EXPECT_NEAR(pk.value, 1e6 * std::sin(1.5), 1e-6);
  EXPECT_NEAR(pk.time, 0.5, 1e-12);
  EXPECT_NE(json.find("\"pressure\": {\"peak\": 997494.98660405446, \"time_s\": 0.5}"), std::string::npos);
}

TEST(OutputFiles, ParticlesAsVertices) {
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "particles";
  fs::remove_all(dir);
  Model model;
  RunOptions options;
  options.output_dir = dir;
  FieldSnapshot s;
  s.dimension = 3;
  const std::vector<double> pos{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  const std::vector<double> h(5, 0.7);
  const std::vector<int> nb{4, 3, 3, 3, 2};
  s.particle_position = pos;
  s.particle_smoothing_length = h;
  s.particle_neighbour_count = nb;
  RunOutput out(model, options, s);
  out.finish(s, RunSummary{});
  const XmlSummary x = parse_xml(slurp(dir / "particles_0000.vtu"));
  EXPECT_TRUE(x.well_formed);
  EXPECT_EQ(x.points, 5);
  EXPECT_EQ(x.cells, 5);
  EXPECT_EQ(x.array_tokens.at("types"), 5u);
  EXPECT_EQ(x.array_tokens.at("smoothing_length"), 5u);
  EXPECT_EQ(x.array_tokens.at("neighbour_count"), 5u);
  EXPECT_EQ(x.array_tokens.at("stress"), 30u);
  EXPECT_NE(slurp(dir / "particles_0000.vtu").find("1 1 1 1 1"), std::string::npos);  // VTK_VERTEX types
  EXPECT_FALSE(fs::exists(dir / "fields_0000.vtu"));
}

TEST(OutputFiles, UnwritableFolderIsAnIoError) {
  Model model;
  RunOptions options;
  options.output_dir = "/proc/camouflet-cannot-write-here";
  auto f = SnapshotFixture::distorted(2, 1);
  EXPECT_THROW(RunOutput(model, options, f.view(0.0, 0)), fs::filesystem_error);
}

}  // namespace
}  // namespace camouflet

namespace camouflet {
namespace {

TEST(OutputFiles, RunningPeakKeepsLargestMagnitudeAndSkipsNaN) {
  GroupPeaks p;
  p.add(1, std::nan(""), 0.0);
  p.add(1, 2.0, 1.0);
  p.add(1, -3.0, 2.0);
  p.add(1, std::nan(""), 3.0);
  p.add(1, 2.5, 4.0);
  EXPECT_EQ(p.peaks[1].value, -3.0);
  EXPECT_EQ(p.peaks[1].time, 2.0);
  EXPECT_EQ(json_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\n\"");
}

}  // namespace
}  // namespace camouflet

namespace camouflet {
namespace {

TEST(OutputFiles, HexMeshSnapshot) {
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "hexes";
  fs::remove_all(dir);
  auto f = SnapshotFixture::distorted(3, 2);  // 27 nodes, 8 hexes
  f.set_linear_fields(0.0);
  Model model;
  model.run.mode = GeometryMode::three_d;
  RunOptions options;
  options.output_dir = dir;
  RunOutput out(model, options, f.view(0.0, 0));
  out.finish(f.view(0.0, 0), RunSummary{});
  const std::string text = slurp(dir / "fields_0000.vtu");
  const XmlSummary x = parse_xml(text);
  EXPECT_TRUE(x.well_formed);
  EXPECT_EQ(x.points, 27);
  EXPECT_EQ(x.cells, 8);
  EXPECT_EQ(x.array_tokens.at("connectivity"), 8u * 8);
  EXPECT_EQ(x.array_tokens.at("velocity"), 27u * 3);
  EXPECT_NE(text.find("12 12 12 12 12 12 12 12"), std::string::npos);  // VTK_HEXAHEDRON
  EXPECT_NE(text.find("8 16 24 32 40 48 56 64"), std::string::npos);   // end offsets
}

}  // namespace
}  // namespace camouflet
