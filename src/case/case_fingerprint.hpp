#pragma once
// What a restart must not change (docs/reliability.md): every key of
// the case file as "dotted.key = value" lines, sorted, except the keys a
// restart may change: run.end_time, run.max_cycles, [output], [checkpoint]
// and title. The checkpoint stores it; `run --restart` compares and names the
// first key that differs.
#include <filesystem>
#include <string>

namespace camouflet {

std::string case_fingerprint(const std::filesystem::path& case_file);

}  // namespace camouflet
