// The bad-input corpus (hardened input): every case file
// under tests/case/bad/ names in its "# expect:" line the fragments its error
// message must contain ("|" separated: file:line, key, explanation). Each goes
// through the real executable and must exit with status 2 and one message,
// never a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/verification.hpp"
#include "run_executable.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> expectations(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    const std::string tag = "# expect: ";
    if (line.rfind(tag, 0) != 0) continue;
    std::vector<std::string> parts;
    std::string rest = line.substr(tag.size());
    for (std::size_t bar; (bar = rest.find(" | ")) != std::string::npos; rest = rest.substr(bar + 3))
      parts.push_back(rest.substr(0, bar));
    parts.push_back(rest);
    return parts;
  }
  return {};
}

std::vector<fs::path> corpus() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(CAMOUFLET_SOURCE_DIR) / "tests/case/bad"))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, ExitsTwoNamingFileLineAndKey) {
  const fs::path file = fs::path(CAMOUFLET_SOURCE_DIR) / "tests/case/bad" / GetParam();
  const auto expected = expectations(file);
  ASSERT_FALSE(expected.empty()) << file << " has no '# expect:' line";
  const auto r = test::run_camouflet("check '" + file.string() + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output.rfind("error: ", 0), 0u) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line expected:\n" << r.output;
  for (const auto& fragment : expected)
    EXPECT_NE(r.output.find(fragment), std::string::npos) << "missing '" << fragment << "' in:\n" << r.output;
}

std::vector<std::string> corpus_names() {
  std::vector<std::string> names;
  for (const auto& f : corpus()) names.push_back(f.filename().string());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(corpus_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = fs::path(info.param).stem().string();
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(BadInputCommand, RunAlsoExitsTwoAndWritesNothing) {
  const fs::path out = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / "bad-run";
  fs::remove_all(out);
  const fs::path file = fs::path(CAMOUFLET_SOURCE_DIR) / "tests/case/bad/gauge_outside_mesh.toml";
  const auto r = test::run_camouflet("run --quiet '" + file.string() + "' -o '" + out.string() + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("gauge_outside_mesh.toml:"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(BadInputCommand, MissingCaseFileAndBadArguments) {
  auto r = test::run_camouflet("check /no/such/case.toml");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("error: /no/such/case.toml: cannot open the case file"), std::string::npos)
      << r.output;
  r = test::run_camouflet("run");
  EXPECT_EQ(r.status, 2) << r.output;
  r = test::run_camouflet("frobnicate x");
  EXPECT_EQ(r.status, 2) << r.output;
  r = test::run_camouflet("run --threads 0 x.toml");
  EXPECT_EQ(r.status, 2) << r.output;
  r = test::run_camouflet("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find("camouflet "), std::string::npos);
  for (const char* help : {"--help", "run --help", "check --help"}) {
    r = test::run_camouflet(help);
    EXPECT_EQ(r.status, 0) << help;
    EXPECT_NE(r.output.find("Usage"), std::string::npos) << help;
  }
}

TEST(BadInputCommand, CorpusIsLarge) {
  // The corpus holds at least 50 bad inputs and covers every category below.
  const auto names = corpus_names();
  for (const char* required :
       {"malformed_toml.toml", "misspelt_run_key.toml", "missing_material.toml", "zero_density.toml",
        "negative_density.toml", "inverted_element.toml", "degenerate_element.toml",
        "gauge_outside_mesh.toml", "unknown_boundary_set.toml", "cfl_above_one.toml", "cfl_zero.toml"})
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
  EXPECT_GE(names.size(), 50u);
}

}  // namespace
}  // namespace camouflet
