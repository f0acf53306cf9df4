// A symmetry plane given as several boundary sets (one per block, as the 3-D
// buried-structure generator writes it) mirrors SPH particles once: the
// run equals the one with the plane given as a single set. (Before the fix
// each set added its own mirror plane, so particles near it got a ghost per
// set and ghosts of ghosts on top of themselves.)
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "case/case_reader.hpp"
#include "common/test_output.hpp"
#include "common/verification.hpp"
#include "soil_case_text.hpp"
#include "solver/run.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

// A sin^2 velocity pulse along a strip through a joined SPH zone, between the
// symmetry planes y = 0 and y = 0.1; the strip is one block or two.
std::string pulse_case(bool split) {
  std::string c = test::soil_case_header("geometry = \"plane_strain\"\nend_time = 6e-4\ncfl = 0.5\n");
  const auto pair = [](const std::string& a, const std::string& b) { return "[" + a + ", " + b + "]"; };
  const auto block = [&](const char* name, double x0, double length, int cells) {
    c += test::soil_block(name, pair(std::to_string(x0), "0.0"), pair(std::to_string(length), "0.1"),
                          pair(std::to_string(cells), "4"));
    for (const char* side : {"ymin", "ymax"}) c += test::y_symmetry(std::string(name) + "." + side);
  };
  if (split) {
    block("left", 0.0, 0.6, 24);
    block("right", 0.6, 0.6, 24);
  } else {
    block("left", 0.0, 1.2, 48);
  }
  c += test::joined_strip_zone;
  c += test::x_velocity_pulse("left.xmin",
                              "[[0.0, 0.0], [6.4e-5, 0.5], [1.29e-4, 1.0], [1.93e-4, 0.5], [2.58e-4, 0.0]]");
  return c;
}

RunSummary run_pulse(bool split) {
  const fs::path out = test::fresh_test_output(split ? "split_symmetry_two" : "split_symmetry_one");
  return run_model(read_case_text(pulse_case(split), split ? "two.toml" : "one.toml"),
                   test::quiet_run_options(out));
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
