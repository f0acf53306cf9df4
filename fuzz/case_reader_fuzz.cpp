// libFuzzer target for the case reader (issue 9, "hardened input"): any input
// must either read or raise InputError; anything else (another exception, a
// crash, a sanitizer report, a hang) is a defect. Build and run: see
// fuzz/CMakeLists.txt.
#include <cstddef>
#include <cstdint>
#include <string>

#include "case/case_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Keep a mutant from asking for a huge mesh: the reader accepts up to 5e7
  // elements, which is legitimate input but would make fuzzing crawl.
  if (size > 4096) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (text.find("cells") != std::string::npos) {
    for (std::size_t at = text.find("cells"); at != std::string::npos; at = text.find("cells", at + 1)) {
      const std::size_t digits = text.find_first_of("0123456789", at);
      if (digits != std::string::npos && text.find_first_not_of("0123456789", digits) - digits > 3) return 0;
    }
  }
  try {
    camouflet::read_case_text(text, "fuzz.toml");
  } catch (const camouflet::InputError&) {
  }
  return 0;
}
