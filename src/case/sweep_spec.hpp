#pragma once
// The sweep file of `camouflet sweep` (docs/buried-structure.md, "Parameter
// studies"): a base generator parameter file and the generator keys to vary,
// as a grid (every combination) or a list of explicit cases, plus overrides
// for every case. Reading it expands and checks every case against the
// generator's parameter reader, so an unknown key or a value of the wrong type
// is refused before anything runs, naming the sweep file's line and key.
#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace camouflet {

struct SweepCase {
  std::string name;  // folder name under the output folder
  // The varied keys' values as written in the sweep file (TOML text), in the
  // order of SweepSpec::varied_keys ("" where a list case leaves a key at the base).
  std::vector<std::string> values;
  toml::table params;  // base + [set] + this case's values
};

struct SweepSpec {
  std::filesystem::path file;  // the sweep file
  std::string title;
  std::filesystem::path base;            // the base parameter file (resolved against the sweep file's folder)
  std::vector<std::string> varied_keys;  // dotted generator keys, in the file's order
  std::vector<SweepCase> cases;
};

SweepSpec read_sweep(const std::filesystem::path& file);
SweepSpec read_sweep_text(const std::string& text, const std::filesystem::path& file);

// The parameter file of one case: a comment naming the sweep, then the merged table.
std::string sweep_case_params_text(const SweepSpec& sweep, const SweepCase& c);

}  // namespace camouflet
