#pragma once
// The parameter file of the buried-structure generator (`camouflet generate`,
// docs/buried-structure.md): a small TOML file of physical numbers read into a
// BuriedStructureSpec. Every key is checked and every unknown key refused,
// naming file, line and key, like the case reader.
#include <filesystem>
#include <string>

#include "mesh/buried_structure.hpp"

namespace camouflet {

BuriedStructureSpec read_buried_structure_params(const std::filesystem::path& file);
BuriedStructureSpec read_buried_structure_params_text(const std::string& text,
                                                      const std::filesystem::path& file);

}  // namespace camouflet
