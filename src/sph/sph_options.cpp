#include "sph/sph_options.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace camouflet::sph {

SphOptions read_sph_options(Parameters& block) {
  SphOptions o;
  if (block.has("kernel")) {
    try {
      o.kernel = kernel_from_name(block.string("kernel"));
    } catch (const std::invalid_argument& e) {
      block.fail("kernel", e.what());
    }
  }
  o.smoothing_factor = block.positive("smoothing_factor", o.smoothing_factor);
  o.variable_smoothing_length = block.flag("variable_smoothing_length", o.variable_smoothing_length);
  o.h_min_factor = block.positive("h_min_factor", o.h_min_factor);
  o.h_max_factor = block.positive("h_max_factor", o.h_max_factor);
  if (o.h_min_factor > o.h_max_factor)
    block.fail("h_min_factor", "smoothing-length bounds inverted: h_min_factor > h_max_factor");
  o.viscosity_alpha = block.non_negative("viscosity_alpha", o.viscosity_alpha);
  o.viscosity_beta = block.non_negative("viscosity_beta", o.viscosity_beta);
  o.viscosity_switch = block.flag("viscosity_switch", o.viscosity_switch);
  o.viscosity_alpha_min = block.non_negative("viscosity_alpha_min", o.viscosity_alpha_min);
  if (o.viscosity_switch && o.viscosity_alpha_min > o.viscosity_alpha)
    block.fail("viscosity_alpha_min",
               "viscosity_alpha_min is larger than viscosity_alpha (the switch's maximum)");
  o.viscosity_switch_decay = block.positive("viscosity_switch_decay", o.viscosity_switch_decay);
  o.viscosity_hoop = block.flag("viscosity_hoop", o.viscosity_hoop);
  o.artificial_stress = block.flag("artificial_stress", o.artificial_stress);
  o.artificial_stress_epsilon =
      block.in_range("artificial_stress_epsilon", 0.0, 1.0, o.artificial_stress_epsilon);
  o.artificial_stress_power = block.positive("artificial_stress_power", o.artificial_stress_power);
  o.conductivity = block.non_negative("conductivity", o.conductivity);
  o.volume_form = block.flag("volume_form", o.volume_form);
  o.xsph = block.in_range("xsph", 0.0, 1.0, o.xsph);
  o.kernel_correction = block.flag("kernel_correction", o.kernel_correction);
  o.smoothed_hoop = block.flag("smoothed_hoop", o.smoothed_hoop);
  if (o.smoothed_hoop && !o.volume_form)
    block.fail("smoothed_hoop", "the smoothed hoop term is built on the volume form; it needs volume_form = true");
  o.smoothed_hoop_width = block.non_negative("smoothed_hoop_width", o.smoothed_hoop_width);
  if (o.smoothed_hoop_width > 0.0 && !o.smoothed_hoop)
    block.fail("smoothed_hoop_width", "sets the band of the smoothed hoop term; it needs smoothed_hoop = true");
  o.skin_factor = block.non_negative("skin_factor", o.skin_factor);
  const double sort_interval = block.number("sort_interval", o.sort_interval);
  if (!(sort_interval >= 0.0 && sort_interval <= 1e6) || sort_interval != std::floor(sort_interval))
    block.fail(
        "sort_interval",
        fmt::format("must be a whole number in [0, 1000000] (0 = never re-sort), got {}", sort_interval));
  o.sort_interval = static_cast<int>(sort_interval);
  return o;
}

}  // namespace camouflet::sph
