// [materials.NAME] with its eos / strength / damage blocks, or a preset.
#include <fmt/format.h>

#include <algorithm>

#include "case/sections.hpp"
#include "materials/registry.hpp"

namespace camouflet::case_detail {

namespace {

Parameters block_parameters(TomlReader& material, const char* key) {
  if (auto block = material.table(key)) return block->parameters();
  SourceLocation w = material.where();
  w.key = material.key_path(key);
  return Parameters(w);
}

}  // namespace

void read_materials(TomlReader& materials, Model& model) {
  // In the order of the file (TOML tables are unordered): material indices
  // in the output then follow the case as written.
  std::vector<std::pair<int, std::string>> ordered;
  for (const std::string& name : materials.keys()) ordered.emplace_back(materials.where(name).line, name);
  std::sort(ordered.begin(), ordered.end());
  for (const auto& [line, name] : ordered) {
    auto material = materials.table(name);
    check_name(materials, name, name);
    const SourceLocation preset_where = material->where("preset");
    const std::string preset = material->string("preset", "");
    Parameters eos = block_parameters(*material, "eos");
    Parameters strength = block_parameters(*material, "strength");
    Parameters damage = block_parameters(*material, "damage");
    material->finish();
    if (preset.empty() && eos.keys().empty())
      throw InputError(material->where("eos"),
                       fmt::format("material '{}' needs an [materials.{}.eos] block with a "
                                   "type (or a preset)",
                                   name, name));
    auto built =
        make_material(name, preset, preset_where, std::move(eos), std::move(strength), std::move(damage));
    model.materials.push_back({name, std::move(built), material->where()});
  }
}

}  // namespace camouflet::case_detail
