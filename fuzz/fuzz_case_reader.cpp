// libFuzzer target for the case reader (issue 9, "hardened input"): any byte
// string read as a case file must end in a Model or an InputError, never a
// crash, hang, leak or sanitizer report. Build: docs/reliability.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "case/case_reader.hpp"
#include "core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // Meshes named by the input are looked up relative to this (non-existent) folder.
    (void)camouflet::read_case_text(text, "/nonexistent-fuzz-dir/case.toml");
  } catch (const camouflet::InputError&) {
  }
  return 0;
}
