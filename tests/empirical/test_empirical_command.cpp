// `camouflet empirical` run as a user would: the paper's in-structure shock
// from the table and the CSV, and status 2 naming the option for bad values.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/verification.hpp"

namespace {

struct CommandRun {
  int status = -1;
  std::string output;  // stdout and stderr together
};

CommandRun run_empirical(const std::string& arguments) {
  const std::string command = std::string("'") + CAMOUFLET_EXECUTABLE + "' empirical " + arguments + " 2>&1";
  CommandRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) run.output.append(buffer, n);
  const int raw = pclose(pipe);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return run;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  for (std::string f; std::getline(ss, f, sep);) fields.push_back(f);
  return fields;
}

const std::string paper_case = "--charge-mass 100 --coupling 0.6 --span 6 10";

}  // namespace

TEST(EmpiricalCommand, PrintsThePapersInStructureShockAsCsv) {
  const CommandRun run = run_empirical(paper_case + " --csv");
  ASSERT_EQ(run.status, 0) << run.output;
  std::stringstream lines(run.output);
  std::string header;
  std::getline(lines, header);
  const auto columns = split(header, ',');
  const auto column = [&](const std::string& name) {
    for (size_t i = 0; i < columns.size(); ++i)
      if (columns[i] == name) return i;
    ADD_FAILURE() << "no column " << name << " in " << header;
    return size_t{0};
  };
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    const auto f = split(line, ',');
    ASSERT_EQ(f.size(), columns.size()) << line;
    ASSERT_EQ(f[column("section")], "in_structure");
    const double n = std::stod(f[column("attenuation_n")]);
    const double v = std::stod(f[column("velocity_m_per_s")]);
    const double a = std::stod(f[column("acceleration_g")]);
    const bool n2 = n == 2.0;
    const std::string ref = "Wang et al. 2005 §5.5, printed";
    camouflet::test::verify({fmt::format("camouflet empirical, paper case: V_avg (n = {})", n), ref,
                             n2 ? 1.59 : 0.78, v, 0.01, true, "m/s"});
    camouflet::test::verify({fmt::format("camouflet empirical, paper case: a_avg (n = {})", n), ref,
                             n2 ? 311.0 : 154.0, a, 0.01, true, "g"});
    ++rows;
  }
  EXPECT_EQ(rows, 2);  // n = 2 and n = 2.5 by default, as in the paper
}

TEST(EmpiricalCommand, TableShowsThePapersAverages) {
  const CommandRun run = run_empirical(paper_case + " --range 6 10");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("In-structure shock"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("Free-field peaks"), std::string::npos) << run.output;
  // Rows "n  V_avg  a_avg  p_avg  d_avg" for n = 2 and 2.5.
  std::stringstream lines(run.output.substr(run.output.find("In-structure shock")));
  int found = 0;
  for (std::string line; std::getline(lines, line);) {
    std::stringstream words(line);
    double n = 0, v = 0, a = 0;
    if (!(words >> n >> v >> a)) continue;
    EXPECT_NEAR(v, n == 2.0 ? 1.59 : 0.78, 0.01 * v) << line;
    EXPECT_NEAR(a, n == 2.0 ? 311.0 : 154.0, 0.01 * a) << line;
    ++found;
  }
  EXPECT_EQ(found, 2) << run.output;
}

TEST(EmpiricalCommand, GeneralLawTakesTheSoil) {
  // Doubling the seismic velocity doubles acceleration and halves displacement.
  const CommandRun slow =
      run_empirical("--charge-mass 50 --law tm5 --attenuation 2.4 --range 5 --csv --seismic-velocity 600");
  const CommandRun fast =
      run_empirical("--charge-mass 50 --law tm5 --attenuation 2.4 --range 5 --csv --seismic-velocity 1200");
  ASSERT_EQ(slow.status, 0) << slow.output;
  ASSERT_EQ(fast.status, 0) << fast.output;
  const auto last_row = [](const std::string& out) {
    std::stringstream lines(out);
    std::string line, last;
    while (std::getline(lines, line))
      if (!line.empty()) last = line;
    return split(last, ',');
  };
  const auto s = last_row(slow.output), f = last_row(fast.output);
  ASSERT_EQ(s.size(), 10u);
  ASSERT_EQ(f.size(), 10u);
  EXPECT_NEAR(std::stod(f[8]) / std::stod(s[8]), 2.0, 1e-6);  // acceleration_g
  EXPECT_NEAR(std::stod(f[9]) / std::stod(s[9]), 0.5, 1e-6);  // displacement_mm
  EXPECT_NEAR(std::stod(f[7]) / std::stod(s[7]), 1.0, 1e-6);  // velocity does not depend on c
}

TEST(EmpiricalCommand, BadValuesExitWithStatus2NamingTheOption) {
  const struct {
    std::string arguments, option;
  } cases[] = {
      {"--charge-mass 0 --span 6 10", "--charge-mass"},
      {"--charge-mass -100 --span 6 10", "--charge-mass"},
      {"--charge-mass heavy --span 6 10", "--charge-mass"},
      {"--span 6 10", "--charge-mass"},
      {"--charge-mass 100 --range 0", "--range"},
      {"--charge-mass 100 --range 5 -2", "--range"},
      {"--charge-mass 100 --span 10 6", "--span"},
      {"--charge-mass 100 --span 6 6", "--span"},
      {"--charge-mass 100 --span 6", "--span"},
      {"--charge-mass 100 --coupling 0 --span 6 10", "--coupling"},
      {"--charge-mass 100 --coupling 1.2 --span 6 10", "--coupling"},
      {"--charge-mass 100 --attenuation 2.2 --span 6 10", "--attenuation"},
      {"--charge-mass 100 --law tm5 --attenuation -2 --span 6 10", "--attenuation"},
      {"--charge-mass 100 --law tm5 --soil-density 0 --span 6 10", "--soil-density"},
      {"--charge-mass 100 --law tm5 --seismic-velocity -1 --span 6 10", "--seismic-velocity"},
      {"--charge-mass 100 --seismic-velocity 300 --span 6 10", "--seismic-velocity"},
      {"--charge-mass 100 --law conwep --span 6 10", "--law"},
      {"--charge-mass 100", "--range"},
  };
  for (const auto& c : cases) {
    const CommandRun run = run_empirical(c.arguments);
    EXPECT_EQ(run.status, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.option), std::string::npos) << c.arguments << "\n" << run.output;
  }
}
