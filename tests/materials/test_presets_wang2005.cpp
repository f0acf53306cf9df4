// The seed paper's presets build, and `camouflet material-test` drives and
// prints them (exit codes of docs/exit-codes.md).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

#include "common/verification.hpp"
#include "materials/jwl_eos.hpp"
#include "materials/registry.hpp"

using namespace camouflet;

namespace {

std::shared_ptr<const Material> preset(const std::string& name) {
  return make_material(name, name, SourceLocation{}, Parameters{}, Parameters{}, Parameters{});
}

// Runs the command, returns its exit status and standard output.
std::pair<int, std::string> run(const std::string& args) {
  const std::string cmd = std::string(CAMOUFLET_EXECUTABLE) + " " + args + " 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), pipe.get())) out += buf.data();
  const int status = pclose(pipe.release());
  return {WEXITSTATUS(status), out};
}

// Position of the n-th comma (1-based) of a CSV line.
std::size_t nthcomma(const std::string& line, int n) {
  std::size_t at = std::string::npos;
  for (int k = 0; k < n; ++k) at = line.find(',', at + 1);
  return at;
}

}  // namespace

TEST(PresetsWang2005, BuildWithTheirTables) {
  auto tnt = preset("tnt_wang2005");
  EXPECT_EQ(tnt->eos().type(), "jwl");
  EXPECT_DOUBLE_EQ(tnt->reference_density(), 1630.0);
  // Chemical energy of the paper's 100 kg charge: 100 kg * 6.0e9 J/m^3 / 1630 kg/m^3.
  test::verify({"tnt_wang2005: chemical energy of 100 kg", "E0 x 100 kg / rho0 = 3.68e8 J", 3.68e8,
                100.0 * tnt->eos().reference_specific_energy(), 0.001, true, "J"});
  auto steel = preset("steel_1006_wang2005");
  ASSERT_NE(steel->strength(), nullptr);
  EXPECT_EQ(steel->strength()->type(), "johnson_cook");
  EXPECT_EQ(steel->eos().type(), "linear");
  MaterialPoints pts;
  steel->setup(pts, 1);
  EXPECT_DOUBLE_EQ(pts.shear_modulus[0], 81.8e9);
  // Bulk sound speed sqrt(K / rho0) with K = 200 GPa.
  EXPECT_NEAR(pts.sound_speed[0], std::sqrt(200e9 / 7896.0), 1e-6);
}

TEST(MaterialTestCommand, PrintsCjStateAndDrivesAPath) {
  auto [status, out] = run("material-test --preset tnt_wang2005 --cj");
  EXPECT_EQ(status, 0);
  EXPECT_NE(out.find("6929"), std::string::npos) << out;
  std::tie(status, out) =
      run("material-test --preset steel_1006_wang2005 --path uniaxial_stress --strain-rate -1 --final-strain "
          "-0.01 "
          "--steps 20");
  EXPECT_EQ(status, 0);
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 22);  // header + initial row + 20 steps
  EXPECT_EQ(run("material-test --preset steel_1006_wang2005 --cj").first, 2);
  EXPECT_EQ(run("material-test --preset tnt_wang2006 --cj").first, 2);
  EXPECT_EQ(run("material-test --preset steel_1006_wang2005 --path biaxial").first, 2);
  // A material of a case file: the example's elastic soil in uniaxial strain,
  // sigma_xx = (K + 4G/3) eps with K = 0.66667 GPa, G = 0.4 GPa.
  const std::string example = std::string(CAMOUFLET_SOURCE_DIR) + "/cases/examples/elastic_column.toml";
  std::tie(status, out) = run("material-test --case " + example +
                              " --material soil --path uniaxial_strain --strain-rate -1 --final-strain -1e-4 "
                              "--steps 10");
  EXPECT_EQ(status, 0);
  const std::string last = out.substr(out.rfind('\n', out.size() - 2) + 1);
  const double sigma_xx = std::stod(last.substr(nthcomma(last, 3) + 1));
  test::verify({"material-test --case: uniaxial strain of the example's elastic soil", "(K + 4G/3) eps",
                (6.6667e8 + 4.0 * 4.0e8 / 3.0) * -1e-4, sigma_xx, 1e-3, true, "Pa"});
  EXPECT_EQ(run("material-test --case " + example + " --material soyl").first, 2);
}
