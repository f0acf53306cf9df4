// SPH parts in case files: a
// filled part runs through run_model; bad particle input names its key.
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

#include "case/case_reader.hpp"
#include "solver/run.hpp"
#include "solver/solver.hpp"

using namespace camouflet;

namespace {

std::string gas_case(const std::string& fill, const std::string& extra = "") {
  return R"(
title = "SPH gas block"
[run]
end_time = 2e-4
geometry = "plane_strain"
[materials.gas]
eos = { type = "ideal_gas", density = 1.2, gamma = 1.4, specific_energy = 2.0e5 }
[materials.steel]
eos = { type = "ideal_gas", density = 7800, gamma = 1.4, specific_energy = 0.0 }
[[parts]]
name = "gas"
material = "gas"
kind = "sph"
fill = )" +
         fill + "\n" + extra;
}

std::string error_key(const std::string& text) {
  try {
    read_case_text(text, "sph_case.toml");
  } catch (const InputError& e) {
    return e.where().key;
  }
  return "(accepted)";
}

}  // namespace

TEST(SphCase, FilledPartRunsThroughRunModel) {
  const Model model =
      read_case_text(gas_case(R"({ shape = "box", min = [0, 0], max = [0.1, 0.1], spacing = 0.005 })",
                              "[sph]\nsmoothing_factor = 1.3\nviscosity_alpha = 1.0\n"),
                     "sph_case.toml");
  ASSERT_EQ(model.particles.count(), 400u);
  EXPECT_EQ(model.parts[0].kind, PartKind::sph);
  omp_set_num_threads(1);
  RunOptions options;
  options.progress = ProgressStyle::none;
  options.threads = 1;
  const RunSummary summary = run_model(model, options);
  EXPECT_FALSE(summary.failed) << summary.stop_reason;
  EXPECT_NEAR(summary.time, 2e-4, 1e-12);
  // A free gas block expands: the energy balance must still close.
  EXPECT_LT(summary.energy.relative_error, 0.01);
  // The particles vote the time step and the limiting one is named.
  const Solver<2> solver(model);
  EXPECT_NE(solver.time_step_limit().reason.find("particle"), std::string::npos)
      << solver.time_step_limit().reason;
}

TEST(SphCase, BadParticleInputNamesTheKey) {
  EXPECT_EQ(error_key(gas_case(R"({ shape = "box", min = [0, 0], max = [0.1, 0.1], spacing = 0 })")),
            "parts[0].fill.spacing");
  EXPECT_EQ(error_key(gas_case(R"({ shape = "box", min = [0, 0], max = [0.0, 0.1], spacing = 0.01 })")),
            "parts[0].fill.max");
  EXPECT_EQ(
      error_key(gas_case(
          R"({ shape = "sphere", centre = [0, 0], radius = 0.1, spacing = 0.01, grading_point = [0, 0], grading_ratio = 1.1, max_spacing = 0.005 })")),
      "parts[0].fill.max_spacing");
  EXPECT_EQ(
      error_key(gas_case(R"({ shape = "polygon", vertices = [0, 0, 1e-4, 0, 0, 1e-4], spacing = 0.01 })")),
      "parts[0].fill");
  EXPECT_EQ(error_key(gas_case(R"({ shape = "box", min = [0, 0], max = [0.1, 0.1], spacing = 0.01 })",
                               "[sph]\nh_min_factor = 3.0\nh_max_factor = 2.0\n")),
            "sph.h_min_factor");
  // Particles inside a FEM part without any join or contact.
  EXPECT_EQ(error_key(gas_case(R"({ shape = "box", min = [0, 0], max = [0.1, 0.1], spacing = 0.01 })",
                               R"(
[[parts]]
name = "plate"
material = "steel"
block = { origin = [0.05, 0.0], size = [0.1, 0.1], cells = [4, 4] }
)")),
            "parts[0].fill");
}
