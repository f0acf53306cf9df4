#pragma once
// Shared pieces of the restart tests (issue 9): a small FEM case, a small
// particle model, and comparing two runs' final checkpoints array by array.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "checkpoint/checkpoint_file.hpp"

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

}  // namespace camouflet::test
