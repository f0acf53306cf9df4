#pragma once
// Shared pieces of the restart tests: a small FEM case, a small
// particle model, a run split in two at a checkpoint, and comparing two runs'
// final checkpoints array by array.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "checkpoint/checkpoint_file.hpp"
#include "common/test_output.hpp"
#include "solver/run.hpp"
#include "sph/sph_test_models.hpp"

namespace camouflet::test {

// Plane-strain column hit at its base (0.5 m x 4 m, 4 x 40 quads): ~135 cycles.
inline std::string restart_fem_case(const std::string& extra_run = "", const std::string& checkpoint = "") {
  return R"([run]
geometry = "plane_strain"
end_time = 0.01
cfl = 0.6
)" + extra_run +
         R"(
[output]
field_interval = 0.001
gauge_interval = 0.0

[checkpoint]
)" + (checkpoint.empty() ? std::string("interval_cycles = 100000\n") : checkpoint) +
         R"(
[materials.soil]
eos = { type = "linear", density = 2000.0, bulk_modulus = 6.6667e8 }
strength = { type = "von_mises", shear_modulus = 4.0e8, yield_stress = 1.0e6 }

[[parts]]
name = "column"
material = "soil"
block = { origin = [0.0, 0.0], size = [0.5, 4.0], cells = [4, 40] }

[[boundary]]
type = "velocity"
set = "column.ymin"
components = ["y"]
value = [5.0]
history = [[0.0, 1.0], [0.001, 1.0], [0.0011, 0.0]]

[[boundary]]
type = "symmetry"
set = "column.xmin"
normal = [1.0, 0.0]

[[gauges]]
name = "axis"
from = [0.25, 0.5]
to = [0.25, 3.5]
count = 4
)";
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// Every array of the newest checkpoint in each folder, bit for bit (metadata aside).
inline void expect_same_final_state(const std::filesystem::path& a, const std::filesystem::path& b) {
  const auto la = list_checkpoints(a / "checkpoints"), lb = list_checkpoints(b / "checkpoints");
  ASSERT_FALSE(la.empty());
  ASSERT_FALSE(lb.empty());
  const CheckpointData da = read_checkpoint(la.front()), db = read_checkpoint(lb.front());
  std::size_t compared = 0;
  for (const auto& [name, array] : da.arrays) {
    if (name.rfind("meta.", 0) == 0) continue;
    const auto it = db.arrays.find(name);
    ASSERT_NE(it, db.arrays.end()) << name;
    EXPECT_EQ(array.count, it->second.count) << name;
    EXPECT_TRUE(array.bytes == it->second.bytes) << "'" << name << "' differs after the restart";
    ++compared;
  }
  EXPECT_EQ(da.arrays.size(), db.arrays.size());
  EXPECT_GT(compared, 50u);
}

// Two elastic steel blocks of particles colliding at 40 m/s (plane strain),
// stopped after `max_cycles`; the callers add their gauges.
inline Model colliding_particle_blocks(std::int64_t max_cycles) {
  Model model;
  model.run.mode = GeometryMode::plane_strain;
  model.run.end_time = 1.5e-4;
  model.run.cfl = 0.5;
  model.run.max_cycles = max_cycles;
  model.output.field_interval = 5e-5;
  model.checkpoint.interval_cycles = 1000000;
  const auto solid = elastic_solid("steel", 7800.0, 1.6e11, 8.0e10);
  add_sph_part(model, "striker", solid, box_fill({0.0, 0.0, 0.0}, {0.04, 0.04, 0.0}, 0.004),
               {40.0, 0.0, 0.0});
  add_sph_part(model, "target", solid, box_fill({0.0401, 0.0, 0.0}, {0.1, 0.04, 0.0}, 0.004));
  return model;
}

// A model built in code run to its end and in two halves (one thread):
// `make(max_cycles)` gives the model stopped after that many cycles. `root`
// is emptied; the uninterrupted run writes <root>/full, the split one
// <root>/split: to half the cycles, then on from that checkpoint.
struct SplitRun {
  RunSummary reference;  // the uninterrupted run
  std::int64_t half = 0;
  RunSummary first, second;  // the split run before and after its restart
};

template <class MakeModel>
SplitRun run_split(const std::filesystem::path& root, MakeModel make) {
  std::filesystem::remove_all(root);
  SplitRun r;
  RunOptions o = quiet_run_options(root / "full");
  const auto full = make(std::numeric_limits<std::int64_t>::max());
  r.reference = run_model(full, o);
  r.half = r.reference.cycles / 2;
  o.output_dir = root / "split";
  r.first = run_model(make(r.half), o);
  o.restart = "latest";
  r.second = run_model(full, o);
  return r;
}

// A model built in code (no case file): `make(max_cycles)` gives the model
// stopped after that many cycles. Runs it to the end in <root>/full, then to
// half its cycles in <root>/split and on from that checkpoint, and expects
// the gauge CSV `gauge_csv`, the energy history (and the rebar history, if
// any) and every final state array bit-identical (one
// thread). The models must enable checkpoints (a final one is written).
// Returns the cycles of the uninterrupted run.
template <class MakeModel>
std::int64_t expect_split_run_bit_identical(const std::filesystem::path& root, MakeModel make,
                                            const std::string& gauge_csv) {
  const SplitRun run = run_split(root, make);
  EXPECT_EQ(run.first.cycles, run.half);
  EXPECT_EQ(run.second.cycles, run.reference.cycles);
  EXPECT_EQ(run.second.time, run.reference.time);
  const std::string a = read_text(root / "full" / gauge_csv), b = read_text(root / "split" / gauge_csv);
  EXPECT_FALSE(a.empty()) << gauge_csv;
  EXPECT_EQ(a, b) << gauge_csv << " differs after the restart";
  // The histories kept outside the checkpoint: energy (always) and rebar (models with bars).
  for (const char* history : {"energy.csv", "bars.csv"}) {
    if (!std::filesystem::exists(root / "full" / history)) continue;
    EXPECT_EQ(read_text(root / "full" / history), read_text(root / "split" / history))
        << history << " differs after the restart";
  }
  EXPECT_TRUE(std::filesystem::exists(root / "full" / "energy.csv"));
  expect_same_final_state(root / "full", root / "split");
  return run.reference.cycles;
}

// One array of a checkpoint file (empty when it has none by that name).
inline StateArray checkpoint_array(const std::filesystem::path& file, const std::string& name) {
  const CheckpointData data = read_checkpoint(file);
  const auto it = data.arrays.find(name);
  return it == data.arrays.end() ? StateArray{} : it->second;
}

}  // namespace camouflet::test
