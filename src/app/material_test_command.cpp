// `camouflet material-test`: drive one point of a material along a load path
// (materials/material_driver.hpp) and write the path as CSV; `--cj` prints the
// Chapman-Jouguet state of a JWL explosive.
#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <stdexcept>

#include "app/commands.hpp"
#include "case/case_reader.hpp"
#include "core/error.hpp"
#include "materials/jwl_eos.hpp"
#include "materials/material_driver.hpp"
#include "materials/registry.hpp"

namespace camouflet::app {

namespace {

struct MaterialTestOptions {
  std::string preset;
  std::string case_file;
  std::string material;
  std::string path = "uniaxial_strain";
  double strain_rate = -1.0;
  double final_strain = -0.01;
  double final_pressure = 0.0;
  double confining_pressure = 0.0;
  int steps = 1000;
  double characteristic_length = 1.0e-3;
  std::string output;
  bool cj = false;
};

int print_cj_state(const Material& material) {
  const auto* jwl = dynamic_cast<const JwlEos*>(&material.eos());
  if (!jwl)
    throw InputError(SourceLocation{"", 0, 0, "--cj"},
                     fmt::format("material '{}' has no JWL equation of state (it has '{}')", material.name(),
                                 material.eos().type()));
  const CjState& cj = jwl->cj_state();
  fmt::print("Chapman-Jouguet state of '{}' (Rayleigh line tangent to the JWL product Hugoniot)\n",
             material.name());
  fmt::print("  detonation velocity D  {:.6g} m/s\n", cj.detonation_velocity);
  fmt::print("  CJ pressure            {:.6g} Pa\n", cj.pressure);
  fmt::print("  CJ density             {:.6g} kg/m^3\n", cj.density);
  fmt::print("  particle velocity      {:.6g} m/s\n", cj.particle_velocity);
  fmt::print("  relative volume V_CJ   {:.6g}\n", cj.relative_volume);
  fmt::print("  burn velocity used     {:.6g} m/s\n", jwl->detonation_velocity());
  return exit_ok;
}

int run_material_test(const MaterialTestOptions& o) {
  std::shared_ptr<const Material> material;
  Model model;  // keeps a case's materials alive
  if (!o.case_file.empty()) {
    if (!o.preset.empty() || o.material.empty())
      throw InputError(SourceLocation{"", 0, 0, "--material"},
                       "give --case FILE with --material NAME, or --preset");
    model = read_case(o.case_file);
    std::vector<std::string> names;
    for (const NamedMaterial& m : model.materials) {
      names.push_back(m.name);
      if (m.name == o.material) material = m.material;
    }
    if (!material) {
      const std::string guess = nearest(o.material, names);
      throw InputError(SourceLocation{o.case_file, 0, 0, "--material"},
                       fmt::format("no material '{}' in the case{}", o.material,
                                   guess.empty() ? "" : fmt::format("; did you mean '{}'?", guess)));
    }
  } else {
    if (o.preset.empty())
      throw InputError(SourceLocation{"", 0, 0, "--preset"},
                       "name a material with --preset, or --case and --material");
    material = make_material(o.preset, o.preset, SourceLocation{"", 0, 0, "--preset"}, Parameters{},
                             Parameters{}, Parameters{});
  }
  if (o.cj) return print_cj_state(*material);
  DriverSpec spec;
  try {
    spec.path = parse_load_path(o.path);
  } catch (const std::invalid_argument& e) {
    throw InputError(SourceLocation{"", 0, 0, "--path"}, e.what());
  }
  spec.strain_rate = o.strain_rate;
  spec.final_strain = o.final_strain;
  spec.final_pressure = o.final_pressure;
  spec.confining_pressure = o.confining_pressure;
  spec.steps = o.steps;
  spec.characteristic_length = o.characteristic_length;
  std::vector<DriverRow> rows;
  try {
    rows = drive_material(*material, spec);
  } catch (const std::invalid_argument& e) {
    throw InputError(SourceLocation{"", 0, 0, "--strain-rate"}, e.what());
  }
  if (o.output.empty() || o.output == "-") {
    write_driver_csv(std::cout, rows);
  } else {
    std::ofstream out(o.output);
    if (!out) {
      std::cerr << "camouflet material-test: cannot write " << o.output << "\n";
      return exit_io_failure;
    }
    write_driver_csv(out, rows);
    std::cerr << fmt::format("camouflet material-test: {} rows of '{}' along {} written to {}\n", rows.size(),
                             material->name(), to_string(spec.path), o.output);
  }
  return exit_ok;
}

}  // namespace

void add_material_test_command(CLI::App& app, CommandResult& result) {
  auto opts = std::make_shared<MaterialTestOptions>();
  auto* cmd =
      app.add_subcommand("material-test", "Drive one material point along a load path and write it as CSV");
  cmd->add_option("--preset", opts->preset, "Material preset name (e.g. steel_1006_wang2005)");
  cmd->add_option("--case", opts->case_file, "Case file to take the material from (with --material)");
  cmd->add_option("--material", opts->material, "Name of a [materials.NAME] block of the case file");
  cmd->add_option("--path", opts->path,
                  "uniaxial_strain | uniaxial_stress | hydrostatic | triaxial | simple_shear")
      ->capture_default_str();
  cmd->add_option("--strain-rate", opts->strain_rate,
                  "Axial (or shear) strain rate, 1/s; negative = compression")
      ->capture_default_str();
  cmd->add_option("--final-strain", opts->final_strain,
                  "Final axial true strain (shear strain for simple_shear)")
      ->capture_default_str();
  cmd->add_option("--final-pressure", opts->final_pressure, "Hydrostatic path: drive to this pressure, Pa");
  cmd->add_option("--confining-pressure", opts->confining_pressure, "Triaxial path: confining pressure, Pa");
  cmd->add_option("--steps", opts->steps, "Number of steps")->capture_default_str();
  cmd->add_option("--characteristic-length", opts->characteristic_length,
                  "Point size, m (the programmed-burn ramp width scales with it)")
      ->capture_default_str();
  cmd->add_option("-o,--output", opts->output, "CSV file (default: standard output)");
  cmd->add_flag("--cj", opts->cj, "Print the Chapman-Jouguet state of a JWL explosive and exit");
  cmd->callback([opts, &result] {
    try {
      result.exit_code = run_material_test(*opts);
    } catch (const InputError& e) {
      std::cerr << "camouflet material-test: " << e.what() << "\n";
      result.exit_code = exit_bad_input;
    } catch (const NumericalError& e) {
      std::cerr << "camouflet material-test: " << e.what() << "\n";
      result.exit_code = exit_numerical_failure;
    }
  });
}

}  // namespace camouflet::app
