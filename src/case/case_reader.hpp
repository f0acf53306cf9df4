#pragma once
// Reads a TOML case file (format: docs/case-format.md) into a Model and checks
// it completely before the first cycle: every problem is an InputError naming
// file, line and key (or the 1-based element id and part).
#include <filesystem>
#include <string>

#include "model/model.hpp"

namespace camouflet {

Model read_case(const std::filesystem::path& file);

// The same from text (tests, fuzzing); `file` names it in messages, and
// relative mesh paths are resolved against its folder.
Model read_case_text(const std::string& text, const std::filesystem::path& file);

// A few lines describing the model (`camouflet check`).
std::string describe_model(const Model& model);

}  // namespace camouflet
