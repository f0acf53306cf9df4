// Rebar strain histories: a run with [[bars]] writes bars.csv with
// one column group per segment; a bar stretched by its host records the host's
// strain: the segments' stretches add up to the imposed elongation.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/test_output.hpp"
#include "common/verification.hpp"
#include "solver/rc_models.hpp"
#include "solver/run.hpp"

using namespace camouflet;

TEST(BarOutput, BarsCsvHoldsTheAxialStrainHistory) {
  test::use_threads(1);
  // The left end held, the right end pulled: a homogeneous stretch of the host along x.
  Model model = test::pulled_host_strip();
  model.materials.push_back({"steel", test::steel_1006(), {}});
  BarSet bar;
  bar.name = "rebar";
  bar.from = {0.0, 0.01, 0.0};
  bar.to = {0.1, 0.01, 0.0};
  bar.segments = 2;
  bar.area = 1e-4;
  bar.material = 1;
  model.bars.push_back(bar);
  const auto dir = std::filesystem::temp_directory_path() / "camouflet_bar_output_test";
  std::filesystem::remove_all(dir);
  run_model(model, test::quiet_run_options(dir, 0));

  std::ifstream in(dir / "bars.csv");
  ASSERT_TRUE(in) << "bars.csv was not written";
  std::string header, line, last;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("time_s,rebar.1.axial_strain,rebar.1.axial_stress,rebar.1.axial_force,", 0), 0u)
      << header;
  EXPECT_NE(header.find("rebar.2.plastic_strain"), std::string::npos) << header;
  while (std::getline(in, line)) last = line;
  std::stringstream row(last);
  std::string cell;
  std::vector<double> values;
  while (std::getline(row, cell, ',')) values.push_back(std::stod(cell));
  ASSERT_EQ(values.size(), 9u);
  // The two half-length segments together span the host: their stretches
  // exp(eps) average to the bar's, 1 + v t / L0.
  const double stretch = 0.5 * (std::exp(values[1]) + std::exp(values[5]));
  test::verify({"Rebar strain history (bars.csv): stretch of the pulled bar from its segments' strains",
                "1 + v t / L0", 1.0 + 0.1 * values[0] / 0.1, stretch, 1e-9, true, "-"});
  std::filesystem::remove_all(dir);
}
