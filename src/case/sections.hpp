#pragma once
// The case reader's section readers, one file each (case/read_*.cpp), and the
// whole-model check run before the first cycle (case/check_model.cpp).
#include <filesystem>

#include "case/toml_reader.hpp"
#include "mesh/block_generator.hpp"
#include "model/model.hpp"

namespace camouflet::case_detail {

void read_run(TomlReader& run, Model& model);
// `form` of [run.viscosity] or of a FEM part's `viscosity` table (case/read_run.cpp).
ViscosityForm read_viscosity_form(TomlReader& viscosity, ViscosityForm fallback);
void read_output(TomlReader& output, Model& model);
void read_materials(TomlReader& materials, Model& model);
void read_parts(TomlReader& root, Model& model, const std::filesystem::path& case_dir);
void read_boundaries(TomlReader& root, Model& model);
// [[contacts]]: SPH part against FEM face set (case/read_contacts.cpp).
void read_contacts(TomlReader& root, Model& model);
// [sph]: numerical SPH settings (sph/sph_options.hpp), checked here.
void read_sph(TomlReader& sph, Model& model);
void read_gauges(TomlReader& root, Model& model);
void read_detonations(TomlReader& root, Model& model);
void read_checkpoint(TomlReader& checkpoint, Model& model);

// Reinforced concrete (case/read_reinforcement.cpp): a block part with
// `rebar_layers`, the [[bars]] section, a material's `erosion` table.
void read_rebar_wall(TomlReader& part, const BlockSpec& block, Model& model);
void read_bars(TomlReader& root, Model& model);
ErosionCriteria read_erosion(TomlReader& material);

// Densities, element shapes (corner Jacobians), gauges inside the mesh.
void check_model(const Model& model);

// A name used in a file name or a CSV header: letters, digits, '_', '-', '.'.
void check_name(const TomlReader& table, const std::string& key, const std::string& name);

// Index into Model::materials of the material named by `key`; fails at that key, with the
// nearest defined name, when there is none (case/read_parts.cpp).
int material_index(const Model& model, TomlReader& table, const std::string& key);

// A non-empty list of part names at `key` (resolved by the caller; case/read_parts.cpp).
std::vector<std::string> name_list(TomlReader& table, const std::string& key);

// [[slide_surfaces]]: FEM parts detached from the rest and sliding on it (case/read_slide_surfaces.cpp).
void read_slide_surfaces(TomlReader& root, Model& model);

}  // namespace camouflet::case_detail
