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
  // Skip inputs whose cell counts could be large: a run of 4 digits or an
  // exponent anywhere in the rest of a line that mentions `cells`.
  for (std::size_t at = text.find("cells"); at != std::string::npos; at = text.find("cells", at + 1)) {
    const std::string rest = text.substr(at, text.find('\n', at) - at);
    int run = 0;
    for (std::size_t k = 0; k < rest.size(); ++k) {
      const bool digit = rest[k] >= '0' && rest[k] <= '9';
      run = digit ? run + 1 : 0;
      if (run > 3 || ((rest[k] == 'e' || rest[k] == 'E') && k + 1 < rest.size() && rest[k + 1] != 'l'))
        return 0;
    }
  }
  try {
    camouflet::read_case_text(text, "fuzz.toml");
  } catch (const camouflet::InputError&) {
  }
  return 0;
}
