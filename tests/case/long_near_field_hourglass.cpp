// The soil's hourglass form (long label): the cut-down r-z near field
// of the buried-structure case (the set-up of test_join_near_field.cpp: 100 kg
// TNT 0.5 m deep, 0.05 m cells, SPH zone r <= 1.5 m down to 2 m joined to the
// FEM soil, transmitting far edges) run to 30 ms under each hourglass form.
// The wang2005 cases use the stiffness form in the soil because under the
// viscous form the soil elements next to the axis, below the zone, drifted
// into a sawtooth until nodes crossed the axis (docs/buried-structure.md,
// docs/theory/coupling.md "Still open"). Guarded here: with the stiffness
// form, 30 ms with no tangled element, no node across the axis and no warning;
// with the viscous form, what happens is recorded (see the test).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "case/case_reader.hpp"
#include "common/fem_models.hpp"
#include "common/verification.hpp"
#include "near_field_case.hpp"
#include "solver/solver.hpp"

namespace camouflet {
namespace {

struct NearFieldRun {
  double reached = 0.0;                     // s, simulated time at the end (or the failure)
  std::string failure;                      // the NumericalError that stopped it, if any
  double first_tangled = -1.0;              // s, first tangled element (-1: none)
  double first_crossing = -1.0;             // s, first node across the axis (-1: none)
  std::string warnings;                     // what the run wrote on stderr
  double tangled_r = 0.0, tangled_z = 0.0;  // m, initial centre of the first tangled element
  double wall_s = 0.0;
};

// Runs to 30 ms, or (stop_at_tangle) until the first element tangles.
NearFieldRun run_near_field(const std::string& form, bool stop_at_tangle) {
  test::use_threads(1);
  const Model model = read_case_text(
      test::near_field_case(fmt::format("joined near field, {} hourglass form", form), 0.03, form),
      "near_field_" + form + ".toml");
  NearFieldRun out;
  const auto start = std::chrono::steady_clock::now();
  testing::internal::CaptureStderr();
  try {
    Solver<2> solver(model);
    while (solver.time() < model.run.end_time * (1 - 1e-12)) {
      solver.limit_next_step(model.run.end_time - solver.time());  // land on the end time
      solver.step();
      if (out.first_tangled < 0.0 && solver.first_tangled_cycle() >= 0) {
        out.first_tangled = solver.time();
        const std::size_t e = static_cast<std::size_t>(solver.first_tangled_element() - 1);
        for (int a = 0; a < 4; ++a) {
          const auto n =
              static_cast<std::size_t>(model.mesh.connectivity[4 * e + static_cast<std::size_t>(a)]);
          out.tangled_r += 0.25 * model.mesh.coordinates[2 * n];
          out.tangled_z += 0.25 * model.mesh.coordinates[2 * n + 1];
        }
        if (stop_at_tangle) break;
      }
      if (out.first_crossing < 0.0 && solver.first_axis_crossing_cycle() >= 0)
        out.first_crossing = solver.time();
      out.reached = solver.time();
    }
  } catch (const NumericalError& e) {
    out.failure = e.what();
  }
  out.warnings = testing::internal::GetCapturedStderr();
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "%s form: reached %.4g ms in %.0f s; first tangled %.4g ms (element centre r %.3f m, z %.3f m), first "
      "axis crossing %.4g ms%s%s\n",
      form.c_str(), 1e3 * out.reached, out.wall_s, 1e3 * out.first_tangled, out.tangled_r, out.tangled_z,
      1e3 * out.first_crossing, out.failure.empty() ? "" : "; stopped: ", out.failure.c_str());
  return out;
}

TEST(NearFieldHourglass, StiffnessFormRuns30msWithoutTanglingOrCrossingTheAxis) {
  const NearFieldRun r = run_near_field("stiffness", false);
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  test::verify({"Joined near field (r-z, 100 kg TNT), stiffness hourglass form: simulated time reached",
                "30 ms (the end time)", 30.0, 1e3 * r.reached, 1e-6, true, "ms"});
  EXPECT_LT(r.first_tangled, 0.0) << "tangled at " << r.first_tangled;
  EXPECT_LT(r.first_crossing, 0.0) << "crossed the axis at " << r.first_crossing;
  const bool quiet = r.warnings.find("warning") == std::string::npos;
  test::record_check(
      "Joined near field (r-z, 100 kg TNT), stiffness hourglass form, 30 ms",
      "no tangled element, no node across the axis, no warning",
      quiet && r.first_tangled < 0.0 && r.first_crossing < 0.0 ? "none" : r.warnings.substr(0, 300),
      quiet && r.first_tangled < 0.0 && r.first_crossing < 0.0);
  EXPECT_TRUE(quiet) << r.warnings;
}

// The viscous form tangles the soil within 30 ms. Where: while the time step
// did not bound the compacted soil's release on its grains (before 3c26797,
// 2 Dec 2026), the elements next to the axis drifted into a sawtooth and the
// element at r = 0.025 m, z = -2.025 m, just below the zone, tangled at
// 10.2 ms. With the soil's stable sound speed the axis column holds, and the
// first tangled element is at the zone's outer top corner (r = 1.525 m,
// z = -0.175 m) at 13.7 ms, where the join's face meets the free surface. The
// run stops at the first tangled element.
TEST(NearFieldHourglass, ViscousFormTanglesAnElementWithin30ms) {
  const NearFieldRun r = run_near_field("viscous", true);
  const bool tangles = r.first_tangled >= 0.0;
  test::record_check("Joined near field (r-z, 100 kg TNT), viscous hourglass form, 30 ms",
                     "an element tangles (the failure that chose the stiffness form)",
                     tangles ? fmt::format("tangled at {:.3g} ms, element centre r = {:.3f} m, z = {:.3f} m",
                                           1e3 * r.first_tangled, r.tangled_r, r.tangled_z)
                             : "no tangled element within 30 ms",
                     tangles);
  EXPECT_TRUE(tangles)
      << "the viscous form no longer tangles the soil within 30 ms: update docs/buried-structure.md";
}

}  // namespace
}  // namespace camouflet
