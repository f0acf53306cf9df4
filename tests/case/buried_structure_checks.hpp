#pragma once
// Checks shared by the r-z and 3-D buried-structure generator tests
// (test_buried_structure.cpp, test_buried_structure_3d.cpp): the same
// questions asked of either geometry's generated case.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/buried_structure.hpp"
#include "model/model.hpp"
#include "run_executable.hpp"

namespace camouflet::test {

// `spec` with the paper's zoning (Fig. 6): the soil within `sph_radius` (m)
// of the axis an SPH zone joined to the FEM, and reinforcement mats at
// `rebar_cover` (m) with steel ratio `rebar_ratio` in every wall.
inline BuriedStructureSpec with_sph_zone_and_rebar(BuriedStructureSpec spec, double sph_radius,
                                                   double rebar_cover, double rebar_ratio) {
  spec.sph_radius = sph_radius;
  spec.has_rebar = true;
  spec.rebar_cover = rebar_cover;
  spec.rebar_ratio = rebar_ratio;
  return spec;
}

// The layout of `spec` must be refused with an InputError naming `key`.
inline void expect_refused(const BuriedStructureSpec& spec, const std::string& key) {
  try {
    layout_buried_structure(spec);
    ADD_FAILURE() << "accepted; expected an error naming " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, key) << e.what();
  }
}

// Whether two nodes of the mesh stand at one place (to 0.1 um): adjacent
// blocks that share their nodes (fused) have none.
inline bool has_duplicate_nodes(const FemMesh& mesh) {
  const auto d = static_cast<std::size_t>(mesh.dimension);
  std::vector<std::array<long long, 3>> at;
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    std::array<long long, 3> p{};
    for (std::size_t i = 0; i < d; ++i) p[i] = std::llround(mesh.coordinates[d * n + i] * 1e7);
    at.push_back(p);
  }
  std::sort(at.begin(), at.end());
  return std::adjacent_find(at.begin(), at.end()) != at.end();
}

// The SPH parts of a generated case with an SPH zone: the charge's and the
// zone's part indices (-1: absent), particle counts and volumes (m^3; r-z:
// per radian x r, as the particles carry them).
struct SphZoneParticles {
  int charge = -1, zone = -1;
  std::size_t charge_count = 0, zone_count = 0;
  double charge_volume = 0.0, zone_volume = 0.0;
};

inline SphZoneParticles sph_zone_particles(const Model& model) {
  SphZoneParticles s;
  for (std::size_t k = 0; k < model.parts.size(); ++k) {
    if (model.parts[k].name == "charge") s.charge = static_cast<int>(k);
    if (model.parts[k].name == "near_field") s.zone = static_cast<int>(k);
  }
  for (std::size_t i = 0; i < model.particles.count(); ++i) {
    if (model.particles.particle_part[i] == s.charge)
      s.charge_volume += model.particles.volume[i], ++s.charge_count;
    if (model.particles.particle_part[i] == s.zone)
      s.zone_volume += model.particles.volume[i], ++s.zone_count;
  }
  return s;
}

// `camouflet generate` on a parameter file `file` holding `text`, written to
// <build>/test-output/<folder>; the case it writes goes to `case_file`
// (out.toml beside it).
struct Generated : Completed {
  std::filesystem::path case_file;
};

inline Generated generate_from(const std::string& folder, const std::string& file, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(CAMOUFLET_BINARY_DIR) / "test-output" / folder;
  fs::create_directories(dir);
  const fs::path params = dir / file;
  std::ofstream(params) << text;
  Generated g;
  g.case_file = dir / "out.toml";
  static_cast<Completed&>(g) =
      run_camouflet("generate '" + params.string() + "' -o '" + g.case_file.string() + "'");
  return g;
}

}  // namespace camouflet::test
