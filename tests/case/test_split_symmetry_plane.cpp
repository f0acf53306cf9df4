// A symmetry plane given as several boundary sets (one per block, as the 3-D
// buried-structure generator writes it) mirrors SPH particles once: the
// run equals the one with the plane given as a single set. (Before the fix
// each set added its own mirror plane, so particles near it got a ghost per
// set and ghosts of ghosts on top of themselves.)
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "case/case_reader.hpp"
#include "common/verification.hpp"
#include "solver/run.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

// A sin^2 velocity pulse along a strip through a joined SPH zone, between the
// symmetry planes y = 0 and y = 0.1; the strip is one block or two.
std::string pulse_case(bool split) {
  std::string c = R"([run]
geometry = "plane_strain"
end_time = 6e-4
cfl = 0.5
[materials.soil]
eos = { type = "linear", density = 2000.0, bulk_modulus = 6.6667e8 }
strength = { type = "elastic", shear_modulus = 4.0e8 }
)";
  const auto block = [&](const char* name, double x0, double length, int cells) {
    c += "[[parts]]\nname = \"" + std::string(name) + "\"\nmaterial = \"soil\"\nblock = { origin = [" +
         std::to_string(x0) + ", 0.0], size = [" + std::to_string(length) + ", 0.1], cells = [" +
         std::to_string(cells) + ", 4] }\n";
    for (const char* side : {"ymin", "ymax"})
      c += "[[boundary]]\ntype = \"symmetry\"\nset = \"" + std::string(name) + "." + side +
           "\"\nnormal = [0.0, 1.0]\n";
  };
  if (split) {
    block("left", 0.0, 0.6, 24);
    block("right", 0.6, 0.6, 24);
  } else {
    block("left", 0.0, 1.2, 48);
  }
  c += R"([[parts]]
name = "zone"
kind = "sph"
material = "soil"
join = true
fill = { shape = "box", min = [0.4, 0.0], max = [0.8, 0.1], spacing = 0.025 }
[[boundary]]
type = "velocity"
set = "left.xmin"
components = ["x"]
value = [1.0]
history = [[0.0, 0.0], [6.4e-5, 0.5], [1.29e-4, 1.0], [1.93e-4, 0.5], [2.58e-4, 0.0]]
)";
  return c;
}

RunSummary run_pulse(bool split) {
  const fs::path out =
      fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / (split ? "split_symmetry_two" : "split_symmetry_one");
  fs::remove_all(out);
  RunOptions options;
  options.output_dir = out;
  options.progress = ProgressStyle::none;
  options.threads = 1;
  return run_model(read_case_text(pulse_case(split), split ? "two.toml" : "one.toml"), options);
}

TEST(SplitSymmetryPlane, ParticlesAreMirroredOnce) {
  const RunSummary one = run_pulse(false);
  const RunSummary two = run_pulse(true);
  ASSERT_FALSE(one.failed) << one.stop_reason;
  ASSERT_FALSE(two.failed) << two.stop_reason;
  EXPECT_EQ(one.cycles, two.cycles);
  // Same physics; only the element order (summation round-off) differs.
  test::verify({"Symmetry plane split into per-block sets: kinetic energy at the end",
                "the same plane as one set", one.energy.kinetic, two.energy.kinetic, 1e-9, true, "J"});
  test::verify({"Symmetry plane split into per-block sets: internal energy at the end",
                "the same plane as one set", one.energy.internal, two.energy.internal, 1e-9, true, "J"});
}

}  // namespace
}  // namespace camouflet
