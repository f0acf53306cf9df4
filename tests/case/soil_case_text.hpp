#pragma once
// Pieces of the small case files of the joined-zone tests
// (test_joined_case.cpp, test_split_symmetry_plane.cpp), written out as a
// case file spells them: one elastic "soil" (rho = 2000 kg/m^3,
// K = 6.6667e8 Pa, G = 4e8 Pa: c_p = 1000 m/s), blocks of it, and the
// boundary tables of a strip driven along x between two symmetry planes.
#include <string>

namespace camouflet::test {

// The [run] table holding `run_keys` ("key = value" lines), then the soil.
inline std::string soil_case_header(const std::string& run_keys) {
  return "[run]\n" + run_keys + R"([materials.soil]
eos = { type = "linear", density = 2000.0, bulk_modulus = 6.6667e8 }
strength = { type = "elastic", shear_modulus = 4.0e8 }
)";
}

// A FEM part `name` of soil, one block; origin, size and cells as the case
// file writes them ("[0.0, 0.0]").
inline std::string soil_block(const std::string& name, const std::string& origin, const std::string& size,
                              const std::string& cells) {
  return "[[parts]]\nname = \"" + name + "\"\nmaterial = \"soil\"\nblock = { origin = " + origin +
         ", size = " + size + ", cells = " + cells + " }\n";
}

// The SPH zone joined to the FEM around it across the strip [0.4, 0.8] m x [0, 0.1] m.
inline const std::string joined_strip_zone = R"([[parts]]
name = "zone"
kind = "sph"
material = "soil"
join = true
fill = { shape = "box", min = [0.4, 0.0], max = [0.8, 0.1], spacing = 0.025 }
)";

// A velocity of 1 m/s along x on `set`, scaled by `history` ("[[t, f], ...]").
inline std::string x_velocity_pulse(const std::string& set, const std::string& history) {
  return "[[boundary]]\ntype = \"velocity\"\nset = \"" + set +
         "\"\ncomponents = [\"x\"]\nvalue = [1.0]\nhistory = " + history + "\n";
}

// A symmetry plane of normal y on `set`.
inline std::string y_symmetry(const std::string& set) {
  return "[[boundary]]\ntype = \"symmetry\"\nset = \"" + set + "\"\nnormal = [0.0, 1.0]\n";
}

}  // namespace camouflet::test
