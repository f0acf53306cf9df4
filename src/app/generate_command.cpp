// `camouflet generate PARAMS.toml [-o CASE.toml]`: writes the case file of a
// buried structure under a side burst from a small parameter file
// (src/mesh/buried_structure.hpp, docs/buried-structure.md).
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "app/commands.hpp"
#include "app/error_report.hpp"
#include "case/buried_structure_params.hpp"

namespace camouflet::app {

namespace {

// PARAMS "x.params.toml" -> "x.toml"; anything else -> "<stem>.case.toml".
std::filesystem::path default_case_path(const std::filesystem::path& params) {
  const std::string name = params.filename().string();
  const std::string suffix = ".params.toml";
  if (name.size() > suffix.size() && name.ends_with(suffix))
    return params.parent_path() / (name.substr(0, name.size() - suffix.size()) + ".toml");
  return params.parent_path() / (params.stem().string() + ".case.toml");
}

}  // namespace

void add_generate_command(CLI::App& app, CommandResult& result) {
  auto params = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("generate", "Write a buried-structure case file from a parameter file");
  cmd->add_option("PARAMS", *params, "Parameter file (TOML, see docs/buried-structure.md)")->required();
  cmd->add_option("-o,--output", *output, "Case file to write (default: NAME.toml for NAME.params.toml)");
  cmd->callback([params, output, &result] {
    result.exit_code = run_guarded([&] {
      const BuriedStructureSpec spec = read_buried_structure_params(*params);
      const BuriedStructureLayout layout = layout_buried_structure(spec);
      const std::filesystem::path target =
          output->empty() ? default_case_path(*params) : std::filesystem::path(*output);
      const std::string text =
          buried_structure_case(spec, fmt::format("camouflet generate {} -o {}", *params, target.string()));
      std::ofstream out(target, std::ios::binary);
      if (!out || !(out << text) || !out.flush())
        throw std::ios_base::failure(fmt::format("cannot write {}", target.string()));
      std::cout << fmt::format(
          "wrote {}{}: {} blocks, {} elements; charge radius {:.3f} m; grid {}{} x {} lines\n"
          "far edges {}: a reflected wave would reach the front wall after {:.1f} ms (end time {:.1f} "
          "ms){}\n",
          target.string(), spec.three_d ? " (3-D half model)" : "", layout.block_count, layout.element_count,
          layout.charge_radius, layout.r_lines.size(),
          spec.three_d ? fmt::format(" x {}", layout.y_lines.size()) : std::string(), layout.z_lines.size(),
          spec.transmitting ? "transmitting" : "FIXED", 1e3 * layout.reflection_time, 1e3 * spec.run.end_time,
          !spec.transmitting && layout.reflection_time < spec.run.end_time ? "  WARNING: before the end time"
                                                                       : "");
      if (spec.sph_radius > 0.0) {
        std::cout << fmt::format(
            "SPH zone {} <= {} m: {} soil particles of {:.4g} m joined to the FEM soil; charge {} particles "
            "of {:.4g} m, {} across its {} ({:.2f} kg modelled)\n",
            spec.three_d ? "|x|, y" : "r", spec.sph_radius, layout.zone_particles, layout.zone_spacing,
            layout.charge_particles, layout.charge_spacing, spec.charge_particles_across,
            spec.three_d ? "half side" : "radius", layout.charge_model_mass);
        // The time step follows the finest particles while the products are dense; a zone much
        // coarser than the charge also couples them through very unequal kernels.
        const double ratio = layout.zone_spacing / layout.charge_spacing;
        if (ratio > 4.0 || ratio < 0.5)
          std::cout << fmt::format(
              "WARNING: the zone's particles are {:.2g} times the charge's; charge.particles_across_radius "
              "= {} would match them\n",
              ratio, std::max<long>(1, std::lround(spec.charge_particles_across / ratio)));
      }
      return static_cast<int>(exit_ok);
    });
  });
}

}  // namespace camouflet::app
