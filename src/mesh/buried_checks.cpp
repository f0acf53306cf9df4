// The checks of a buried-structure specification that both geometries share,
// and the quantities they derive from it (buried_structure_internal.hpp):
// the charge radius and the soil gauges' ranges.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "mesh/buried_structure_internal.hpp"

namespace camouflet::buried_detail {

void check_common(const BuriedStructureSpec& s, double a) {
  const auto fail = [&](const std::string& key, const std::string& message) {
    throw InputError(s.location(key), message);
  };
  const auto positive = [&](const std::string& key, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) fail(key, fmt::format("must be a positive number, got {}", v));
  };
  positive("charge.mass", s.charge_mass);
  positive("charge.density", s.explosive_density);
  positive("charge.depth", s.burst_depth);
  positive("structure.standoff", s.standoff);
  positive("structure.length", s.box_length);
  positive("structure.height", s.box_height);
  positive("structure.wall_thickness", s.wall_thickness);
  positive("domain.radius", s.domain_radius);
  positive("domain.depth", s.domain_depth);
  positive("soil.wave_speed", s.soil_wave_speed);
  positive("mesh.near_radius", s.near_radius);
  positive("mesh.near", s.size_near);
  positive("mesh.structure", s.size_structure);
  positive("mesh.soil", s.size_soil);
  positive("mesh.far", s.size_far);
  positive("run.end_time", s.run.end_time);
  if (!(s.top_depth >= 0.0))
    fail("structure.top_depth", fmt::format("must be >= 0 (m below the ground), got {}", s.top_depth));
  if (!(s.run.field_interval >= 0.0)) fail("run.field_interval", "must be >= 0");
  if (!(s.run.gauge_interval >= 0.0)) fail("run.gauge_interval", "must be >= 0");
  if (!(s.run.cfl > 0.0 && s.run.cfl <= 1.0)) fail("run.cfl", fmt::format("must lie in (0, 1], got {}", s.run.cfl));
  if (!(s.run.gravity >= 0.0))
    fail("run.gravity", fmt::format("must be >= 0 (m/s^2, its magnitude), got {}", s.run.gravity));
  if (s.run.gravity > 0.0 && !(s.run.relaxation_period > 0.0))
    fail("run.relaxation_period",
         "needed with run.gravity: the model's fundamental period (s), about 4 domain.depth / c_s with c_s "
         "the "
         "soil's shear-wave speed, for the dynamic relaxation that settles the box before t = 0");
  if (s.run.gravity == 0.0 && s.run.relaxation_period != 0.0)
    fail("run.relaxation_period", "given without run.gravity: there is nothing to relax");
  if (!(s.hourglass_coefficient > 0.0 && s.hourglass_coefficient <= 0.5))
    fail("run.hourglass_coefficient",
         fmt::format("must lie in (0, 0.5] (stiffness-form hourglass control), got {}",
                     s.hourglass_coefficient));
  for (const char* member : {"soil", "structure"}) {
    const bool soil = std::string(member) == "soil";
    const std::string& form = soil ? s.soil_hourglass : s.structure_hourglass;
    const double c = soil ? s.soil_hourglass_coefficient : s.structure_hourglass_coefficient;
    const std::string key = std::string(member) + ".hourglass";
    if (form != "stiffness" && form != "viscous")
      fail(key + ".form", fmt::format("must be \"stiffness\" or \"viscous\", got \"{}\"", form));
    // 0 stands for "not given" (run.hourglass_coefficient); given, it must be a coefficient.
    if ((c != 0.0 || s.where.count(key + ".coefficient")) && !(c > 0.0 && c <= 0.5))
      fail(key + ".coefficient", fmt::format("must lie in (0, 0.5], got {}", c));
  }
  if (s.gauge_count < 2 || s.gauge_count > 100) fail("gauges.count", "must be a whole number from 2 to 100");
  if (s.charge_particles_across < 1 || s.charge_particles_across > 64)
    fail("charge.particles_across_radius",
         fmt::format("must be a whole number from 1 to 64, got {}", s.charge_particles_across));
  if (2.0 * s.wall_thickness >= std::min(s.box_length, s.box_height))
    fail("structure.wall_thickness", fmt::format("{} m walls leave no room inside a {} m x {} m box",
                                                 s.wall_thickness, s.box_length, s.box_height));
  if (s.burst_depth <= a)
    fail("charge.depth",
         fmt::format("the charge (radius {:.3f} m) must be buried: depth {} m", a, s.burst_depth));
  if (s.standoff <= a)
    fail("structure.standoff",
         fmt::format("the structure overlaps the charge: standoff {} m <= charge radius {:.3f} m", s.standoff,
                     a));
  if (s.near_radius < a)
    fail("mesh.near_radius",
         fmt::format("must cover the charge (radius {:.3f} m), got {} m", a, s.near_radius));
  if (s.near_radius >= s.standoff)
    fail("mesh.near_radius",
         fmt::format("the near-field (SPH) zone of radius {} m crosses the structure at r = {} m",
                     s.near_radius, s.standoff));
  if (s.burst_depth + a >= s.domain_depth)
    fail("domain.depth", fmt::format("{} m does not contain the charge", s.domain_depth));
  if (s.top_depth + s.box_height + s.size_structure >= s.domain_depth)
    fail("domain.depth", fmt::format("{} m does not contain the structure", s.domain_depth));
  if (s.standoff + s.box_length + s.size_structure >= s.domain_radius)
    fail("domain.radius", fmt::format("{} m does not contain the structure", s.domain_radius));
  if (s.has_rebar) {
    if (!(s.rebar_cover >= 0.0)) fail("rebar.cover", fmt::format("must be >= 0 (m), got {}", s.rebar_cover));
    if (!(s.rebar_cover < 0.5 * s.wall_thickness))
      fail("rebar.cover",
           fmt::format("{} m of cover leaves no room in a {} m wall", s.rebar_cover, s.wall_thickness));
    if (!(s.rebar_ratio > 0.0 && s.rebar_ratio < 0.1))
      fail("rebar.ratio", fmt::format("steel ratio must lie in (0, 0.1), got {}", s.rebar_ratio));
  }
  if (!(s.sph_radius >= 0.0) || !std::isfinite(s.sph_radius))
    fail("sph.radius", fmt::format("must be >= 0 (m; 0 = no SPH zone), got {}", s.sph_radius));
  if (has_sph_zone(s)) {
    if (s.sph_radius < a + 2.0 * s.size_near)
      fail("sph.radius", fmt::format("the SPH zone of radius {} m must hold the charge (radius {:.3f} m) and "
                                     "two particle spacings ({} m each) of soil around it",
                                     s.sph_radius, a, s.size_near));
    if (s.sph_radius + 2.0 * s.size_structure >= s.standoff)
      fail("sph.radius",
           fmt::format("the SPH zone (r <= {} m) crosses the structure at r = {} m: keep at least "
                       "two structure cells ({} m) of FEM soil between them",
                       s.sph_radius, s.standoff, 2.0 * s.size_structure));
    if (!(s.sph_depth >= 0.0) || !std::isfinite(s.sph_depth))
      fail("sph.depth",
           fmt::format("must be >= 0 (m below the ground; 0 = charge depth + radius), got {}", s.sph_depth));
    if (s.sph_depth > 0.0 && s.sph_depth < s.burst_depth + a + 2.0 * s.size_near)
      fail("sph.depth",
           fmt::format("the SPH zone's bottom at {} m must lie below the charge (down to {:.3f} m) "
                       "with two particle spacings ({} m each) of soil under it",
                       s.sph_depth, s.burst_depth + a, s.size_near));
    if (s.sph_bottom() + 2.0 * s.size_near >= s.domain_depth)
      fail(s.sph_depth > 0.0 ? "sph.depth" : "domain.depth",
           fmt::format("the domain ({} m deep) does not contain the SPH zone (down to {} m) and two cells "
                       "under it",
                       s.domain_depth, s.sph_bottom()));
  }
}

double charge_radius(const BuriedStructureSpec& s) {
  return std::cbrt(3.0 * s.charge_mass / (4.0 * std::numbers::pi * s.explosive_density));
}

// Gauge ranges (m from the charge centre) shared by groups A and B, so that
// both have gauges at equal distances (Fig. 9): geometric from the edge of the
// near field out to a scaled distance of 2.5 m/kg^(1/3) (Fig. 8b's range).
std::vector<double> soil_gauge_ranges(const BuriedStructureSpec& s, double far) {
  const double w3 = std::cbrt(s.charge_mass);
  const double first = std::max(s.near_radius + s.size_near, 0.3 * w3);
  std::vector<double> out;
  const double q = std::pow(far / first, 1.0 / (s.gauge_count - 1));
  for (int k = 0; k < s.gauge_count; ++k) out.push_back(first * std::pow(q, k));
  return out;
}

}  // namespace camouflet::buried_detail
