// The layer rule of docs/architecture.md, checked on the source tree: every
// `#include "<layer>/..."` in src/<folder>/ points to the same layer or one
// below it, and the layers of one rank (mesh, fem, sph, boundary, output)
// never include each other in a cycle. A new folder under src/ must be given
// a rank here and in the docs before it builds green. Beside it the size
// rule of the same page: no source file in src/ longer than 600 lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Rank of each layer, lowest first; equal ranks are peers (docs/architecture.md, "Layers").
const std::map<std::string, int>& layer_rank() {
  static const std::map<std::string, int> rank = {
      {"core", 0},     {"materials", 1}, {"checkpoint", 1}, {"empirical", 1}, {"model", 2},
      {"mesh", 3},     {"fem", 3},       {"sph", 3},        {"boundary", 3},  {"output", 3},
      {"coupling", 4}, {"parallel", 4},  {"solver", 5},     {"case", 6},      {"app", 7},
  };
  return rank;
}

struct Include {
  std::string file;  // src-relative path of the including file
  int line = 0;
  std::string from, to;  // layers
};

std::vector<Include> layer_includes(const fs::path& src) {
  std::vector<Include> out;
  const std::regex include_re(R"(^\s*#\s*include\s*"([a-z_0-9]+)/)");
  for (const auto& entry : fs::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    const std::string rel = fs::relative(entry.path(), src).generic_string();
    const std::string from = rel.substr(0, rel.find('/'));
    std::ifstream in(entry.path());
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) {
      std::smatch m;
      if (std::regex_search(text, m, include_re)) out.push_back({rel, n, from, m[1].str()});
    }
  }
  return out;
}

TEST(Layers, EveryIncludePointsToTheSameLayerOrBelow) {
  const fs::path src = fs::path(CAMOUFLET_SOURCE_DIR) / "src";
  const auto& rank = layer_rank();
  const std::vector<Include> includes = layer_includes(src);
  ASSERT_GT(includes.size(), 100u) << "no includes found under " << src;
  for (const auto& entry : fs::directory_iterator(src)) {
    if (entry.is_directory()) {
      EXPECT_TRUE(rank.count(entry.path().filename().string()))
          << "src/" << entry.path().filename().string() << " has no rank in the layer order";
    }
  }
  for (const Include& i : includes) {
    if (!rank.count(i.from) || !rank.count(i.to)) continue;  // reported above, or a system path
    EXPECT_LE(rank.at(i.to), rank.at(i.from))
        << "src/" << i.file << ":" << i.line << ": layer '" << i.from << "' includes '" << i.to
        << "', which is above it (docs/architecture.md, \"Layers\")";
  }
}

TEST(Layers, PeerLayersDoNotIncludeEachOtherInACycle) {
  const fs::path src = fs::path(CAMOUFLET_SOURCE_DIR) / "src";
  std::map<std::string, std::set<std::string>> edges;
  std::map<std::pair<std::string, std::string>, std::string> where;
  for (const Include& i : layer_includes(src))
    if (i.from != i.to && layer_rank().count(i.to)) {
      edges[i.from].insert(i.to);
      where.emplace(std::make_pair(i.from, i.to), "src/" + i.file + ":" + std::to_string(i.line));
    }
  // Depth-first search for a back edge.
  std::map<std::string, int> state;  // 0 new, 1 on the path, 2 done
  std::vector<std::string> path;
  std::string cycle;
  const auto visit = [&](auto&& self, const std::string& layer) -> void {
    state[layer] = 1;
    path.push_back(layer);
    for (const std::string& next : edges[layer]) {
      if (!cycle.empty()) break;
      if (state[next] == 1) {
        for (auto p = std::find(path.begin(), path.end(), next); p != path.end(); ++p) cycle += *p + " -> ";
        cycle += next + " (" + where.at({layer, next}) + ")";
      } else if (state[next] == 0) {
        self(self, next);
      }
    }
    path.pop_back();
    state[layer] = 2;
  };
  for (const auto& [layer, rank] : layer_rank())
    if (state[layer] == 0 && cycle.empty()) visit(visit, layer);
  EXPECT_TRUE(cycle.empty()) << "layers include each other: " << cycle;
}

TEST(Layers, NoSourceFileLongerThan600Lines) {
  // One job per file (docs/architecture.md, "Layers"): a file past this has
  // grown a second job and is split where its parts meet.
  constexpr int limit = 600;
  const fs::path src = fs::path(CAMOUFLET_SOURCE_DIR) / "src";
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    ++files;
    std::ifstream in(entry.path());
    int lines = 0;
    for (std::string text; std::getline(in, text);) ++lines;
    EXPECT_LE(lines, limit) << "src/" << fs::relative(entry.path(), src).generic_string() << " has " << lines
                            << " lines";
  }
  EXPECT_GT(files, 100) << "no sources found under " << src;
}

TEST(Layers, SolverStagesReachTheParticlesOnlyAsAPackage) {
  // The driver loops over packages (docs/architecture.md, "Packages"): no file of src/solver
  // holds or names the particle system; the couplings reach it through SphPackage::system().
  const fs::path solver = fs::path(CAMOUFLET_SOURCE_DIR) / "src" / "solver";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(solver)) {
    if (entry.path().extension() != ".cpp") continue;
    ++files;
    std::ifstream in(entry.path());
    int line = 0;
    for (std::string text; std::getline(in, text);) {
      ++line;
      for (const char* name : {"particles_", "SphSystem"})
        EXPECT_EQ(text.find(name), std::string::npos)
            << "src/solver/" << entry.path().filename().string() << ":" << line << " names " << name;
    }
  }
  EXPECT_GT(files, 5) << "no sources found under " << solver;
}

TEST(Layers, StepCallsNoMethodByName) {
  // step() is the list of stages, each a loop over the packages (docs/architecture.md, "The
  // explicit cycle"): inside Solver<D>::step the FEM package is named only as what the
  // boundaries act on, never called at a stage of its own.
  std::ifstream in(fs::path(CAMOUFLET_SOURCE_DIR) / "src" / "solver" / "solver.cpp");
  std::string text;
  int line = 0, body_lines = 0;
  bool inside = false;
  while (std::getline(in, text)) {
    ++line;
    if (text.rfind("void Solver<D>::step() {", 0) == 0) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (text.rfind("}", 0) == 0) break;  // the function's closing brace
    ++body_lines;
    for (const char* name : {"fem_", "sph_", "coupling_->"})
      if (text.find(name) != std::string::npos && text.find("boundaries_.") == std::string::npos)
        ADD_FAILURE() << "src/solver/solver.cpp:" << line << ": step() names " << name
                      << " outside a boundary call: " << text;
  }
  EXPECT_GT(body_lines, 10) << "Solver<D>::step() not found in src/solver/solver.cpp";
}

}  // namespace
