// libFuzzer target for the Gmsh .msh import (issue 9, "hardened input"): the
// input is written as a mesh file and read through a case that names it; it
// must end in a Model or an InputError. (Gmsh itself is not instrumented.)
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "case/case_reader.hpp"
#include "core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string dir = "/tmp/camouflet-fuzz-" + std::to_string(getpid());
  static const bool made = [] { return system(("mkdir -p " + dir).c_str()) == 0; }();
  if (!made) return 0;
  {
    std::ofstream(dir + "/mesh.msh", std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  static const std::string case_text = R"([run]
end_time = 0.001
[materials.soil]
eos = { type = "linear", density = 2000.0, bulk_modulus = 1.0e9 }
strength = { type = "elastic", shear_modulus = 5.0e8 }
[[parts]]
name = "body"
material = "soil"
gmsh = "mesh.msh"
physical = "body"
)";
  try {
    (void)camouflet::read_case_text(case_text, dir + "/case.toml");
  } catch (const camouflet::InputError&) {
  }
  return 0;
}
