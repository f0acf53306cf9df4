#include "case/case_fingerprint.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <sstream>
#include <vector>

namespace camouflet {

namespace {

bool may_change(const std::string& key) {
  for (const char* k : {"run.end_time", "run.max_cycles", "title"})
    if (key == k) return true;
  for (const char* prefix : {"output.", "checkpoint."})
    if (key.rfind(prefix, 0) == 0) return true;
  return key == "output" || key == "checkpoint";
}

void flatten(const toml::node& node, const std::string& key, std::vector<std::string>& out) {
  if (!key.empty() && may_change(key)) return;
  if (const auto* t = node.as_table()) {
    for (const auto& [k, v] : *t)
      flatten(v, key.empty() ? std::string(k.str()) : key + "." + std::string(k.str()), out);
  } else if (const auto* a = node.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i) flatten(*a->get(i), key + "[" + std::to_string(i) + "]", out);
    if (a->empty()) out.push_back(key + " = []");
  } else {
    std::ostringstream value;
    if (const auto* f = node.as_floating_point())
      value << fmt::format("{}", f->get());  // shortest form that reads back exactly
    else
      node.visit([&value](const auto& v) { value << v; });
    out.push_back(key + " = " + value.str());
  }
}

}  // namespace

std::string case_fingerprint(const std::filesystem::path& case_file) {
  const toml::table doc = toml::parse_file(case_file.string());
  std::vector<std::string> lines;
  flatten(doc, "", lines);
  std::sort(lines.begin(), lines.end());
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

}  // namespace camouflet
