// A compaction wave in the FEM soil and its reflection: a column of the
// seismic sandy clay (1 m x 3 m, 0.1 m quads, plane strain) on a rigid base,
// laterally confined, its top pushed down at 20 m/s (to 4.9 ms, before the piston stops). Every joule the
// piston does must end up as the soil's kinetic or internal energy (the
// compaction is irreversible, so the internal energy keeps it); the wave
// reflects from the base at about 1.3 ms, doubling the compaction.
//
// At CFL 0.3 the balance closes to 0.01 % (0.15 % once the piston stops at 5 ms,
// a velocity step of the boundary). At CFL 0.6 (the buried cases'
// value) it holds to 0.07 % until the reflection, then the run creates 7.7 %
// within 2 ms and the energy guard stops it (main 812912a, 2 Dec 2026): the
// time step does not bound the strongly compacted soil. That test is disabled
// until the time-step vote does.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case/case_reader.hpp"
#include "common/test_output.hpp"
#include "common/verification.hpp"
#include "solver/run.hpp"

namespace camouflet {
namespace {

std::string piston_case(double cfl) {
  return fmt::format(R"(title = "soil column under a piston, rigid base"
[run]
geometry = "plane_strain"
end_time = 0.0049
cfl = {}
[run.hourglass]
form = "stiffness"
coefficient = 0.1
[output]
field_interval = 0.0
gauge_interval = 1e-4
[materials.soil]
preset = "sandy_clay_wang2005_seismic"
[[parts]]
name = "column"
material = "soil"
block = {{ origin = [0.0, -3.0], size = [1.0, 3.0], cells = [10, 30] }}
[[boundary]]
type = "velocity"
set = "column.ymax"
components = ["y"]
value = [-20.0]
history = [[0.0, 1.0], [0.005, 1.0], [0.0051, 0.0]]
[[boundary]]
type = "symmetry"
set = "column.xmin"
normal = [1.0, 0.0]
[[boundary]]
type = "symmetry"
set = "column.xmax"
normal = [1.0, 0.0]
[[boundary]]
type = "symmetry"
set = "column.ymin"
normal = [0.0, 1.0]
)",
                     cfl);
}

void check_piston(double cfl, double tolerance) {
  const auto out = test::fresh_test_output(fmt::format("compaction_piston_cfl{}", cfl));
  const Model model = read_case_text(piston_case(cfl), "piston.toml");
  const RunSummary summary = run_model(model, test::quiet_run_options(out));
  ASSERT_FALSE(summary.failed) << summary.stop_reason;
  test::verify(
      {fmt::format("Soil column under a 20 m/s piston, compaction wave reflected at a rigid base, CFL {}: "
                   "energy balance at 4.9 ms",
                   cfl),
       "piston work = kinetic + internal energy", 0.0, summary.energy.relative_error, tolerance, false,
       "relative"});
}

TEST(CompactionPiston, EnergyBalanceAtCfl03) {
  check_piston(0.3, 0.002);
}

TEST(CompactionPiston, DISABLED_EnergyBalanceAtCfl06) {
  check_piston(0.6, 0.002);
}

}  // namespace
}  // namespace camouflet
