// The case-file tables the axisymmetric and the 3-D buried-structure
// generators write alike (buried_structure_internal.hpp): [run], [output] and
// [materials.*], the soil gauge groups, the member gauges, the structure
// targets and the per-part hourglass and geostatic lines.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "mesh/buried_structure_internal.hpp"

namespace camouflet::buried_detail {

std::string generator_interface(const BuriedStructureSpec& s) {
  if (!s.slide_interface || s.free_field) return "";
  return fmt::format(" interface=slide friction={}", s.interface_friction);
}

void write_slide_interface(const BuriedStructureSpec& s, const std::vector<std::string>& box_parts, std::string& b) {
  if (!s.slide_interface || s.free_field || box_parts.empty()) return;
  auto out = std::back_inserter(b);
  b += "# Soil-structure interface (structure.interface = \"slide\"): the box's parts are detached from the\n"
       "# soil along the faces they share, which may separate, recontact and slide with Coulomb friction\n"
       "# (Wang et al. 2005, section 4.13; coupling/slide_surface.hpp).\n";
  b += "[[slide_surfaces]]\nparts = [";
  for (std::size_t k = 0; k < box_parts.size(); ++k)
    fmt::format_to(out, "{}\"{}\"", k == 0 ? "" : ", ", box_parts[k]);
  fmt::format_to(out, "]\nfriction = {}\n\n", s.interface_friction);
}

void write_member_gauges(const BuriedStructureSpec& s, bool three_d, std::string& b) {
  auto out = std::back_inserter(b);
  // The walls take the box's full height, the roof and the floor the span between the walls, so no
  // element belongs to two members; in 3-D the roof and the floor stop at the side wall.
  const double r0 = s.standoff, r1 = s.standoff + s.box_length, t = s.wall_thickness;
  const double top = -s.top_depth, bottom = -s.top_depth - s.box_height, eps = 1e-6;
  struct Member {
    const char* name;
    double r_lo, r_hi, z_lo, z_hi, y_hi;
  };
  const double half_width = 0.5 * s.box_width;
  const Member members[] = {
      {"front_wall", r0, r0 + t, bottom, top, half_width},
      {"roof", r0 + t, r1 - t, top - t, top, half_width - t},
      {"floor", r0 + t, r1 - t, bottom, bottom + t, half_width - t},
      {"rear_wall", r1 - t, r1, bottom, top, half_width},
  };
  b += "\n# Members of the box (docs/buried-structure.md, \"In-structure shock in the report\"): the mass-weighted mean motion\n"
       "# of the concrete elements centred in each box, the span's rigid-body motion (members.csv).\n";
  b += "[[gauges]]\nname = \"members\"\nmembers = [\n";
  // A free-field run measures the soil in the members' places.
  const char* member_material = s.free_field ? "soil" : "concrete";
  for (const Member& m : members) {
    if (three_d)
      fmt::format_to(out,
                     "  {{ name = \"{}\", material = \"{}\", min = [{:.9g}, {:.9g}, {:.9g}], "
                     "max = [{:.9g}, {:.9g}, {:.9g}] }},\n",
                     m.name, member_material, m.r_lo - eps, -eps, m.z_lo - eps, m.r_hi + eps, m.y_hi + eps, m.z_hi + eps);
    else
      fmt::format_to(out,
                     "  {{ name = \"{}\", material = \"{}\", min = [{:.9g}, {:.9g}], max = [{:.9g}, {:.9g}] }},\n",
                     m.name, member_material, m.r_lo - eps, m.z_lo - eps, m.r_hi + eps, m.z_hi + eps);
  }
  b += "]\n";
}

void write_soil_gauges(const BuriedStructureSpec& s, bool three_d, std::string& b) {
  auto out = std::back_inserter(b);
  const double d = s.burst_depth, w3 = std::cbrt(s.charge_mass);
  // Group A parallel to the ground at the charge depth, stopping short of the
  // structure; group B on the 45-degree line down.
  const double a_limit = s.standoff - 2.0 * s.size_structure;
  const double b_limit = std::min({2.5 * w3, 0.9 * (s.domain_depth - d) * std::numbers::sqrt2,
                                   0.9 * s.domain_radius * std::numbers::sqrt2});
  const auto ranges = soil_gauge_ranges(s, b_limit);
  const auto write_group = [&](const char* group, bool inclined, double limit) {
    fmt::format_to(out, "[[gauges]]\nname = \"group_{}\"\npoints = [\n", group);
    int k = 0;
    for (double R : ranges) {
      if (R > limit + 1e-9) break;
      const double r = inclined ? R / std::numbers::sqrt2 : R;  // from the charge axis (r, or x in 3-D)
      const double z = inclined ? -d - R / std::numbers::sqrt2 : -d;
      if (three_d)
        fmt::format_to(
            out, "  {{ name = \"{}{}\", position = [{:.6g}, 0.0, {:.6g}] }},  # R = {:.3f} m, Z = {:.3f}\n",
            group, ++k, r, z, R, R / w3);
      else
        fmt::format_to(out,
                       "  {{ name = \"{}{}\", position = [{:.6g}, {:.6g}] }},  # R = {:.3f} m, Z = {:.3f}\n",
                       group, ++k, r, z, R, R / w3);
    }
    b += "]\n\n";
  };
  b += three_d ? "# Soil gauges (Wang et al. 2005, Fig. 8a) in the symmetry plane. A_k and B_k lie at the "
                 "same range.\n"
               : "# Soil gauges (Wang et al. 2005, Fig. 8a). Names: A1.. / B1..; A_k and B_k lie at the same "
                 "range.\n";
  write_group("A", false, a_limit);
  write_group("B", true, b_limit);
}

void write_run_and_materials(const BuriedStructureSpec& s, const char* geometry, std::string& b) {
  auto out = std::back_inserter(b);
  fmt::format_to(out, "title = \"{}\"\n\n[run]\ngeometry = \"{}\"\nend_time = {}  # s\ncfl = {}\n", s.title,
                 geometry, s.run.end_time, s.run.cfl);
  // r-z with an SPH zone: the axis below the zone. The volume form's hoop force drew the axis
  // element below the zone into a needle that set the time step (default: 0.13 us by 41 ms,
  // against 2 us at the start) unless the soil eroded; the area form (the momentum of a radian's
  // planar area, Wilkins) keeps it whole. Subzonal pressures and the edge viscosity (Caramana,
  // Shashkov and Whalen 1998) in the soil hold the elements the flow tangles, and with them
  // default's first SPH column moves with the second (docs/buried-structure.md, "The axis
  // without soil erosion"). Not without the zone: there the charge and the strongest shock are
  // FEM, and the edge viscosity without its limiter halves the near-field peaks (the same page).
  const bool axis_treatment = s.axis_treatment();
  if (axis_treatment) b += "axisymmetric_momentum = \"area\"  # the r-z area form (docs/buried-structure.md, \"The axis without soil erosion\")\n";
  if (s.run.gravity > 0.0)
    fmt::format_to(
        out,
        "gravity = {}  # m/s^2\n\n[run.dynamic_relaxation]  # settles the box in the geostatic soil\n"
        "period = {}  # s\n",
        std::string(geometry) == "3d" ? fmt::format("[0, 0, {}]", -s.run.gravity)
                                      : fmt::format("[0, {}]", -s.run.gravity),
        s.run.relaxation_period);
  b += "\n";
  // Stiffness-form hourglass control: under the charge the soil flows plastically for tens of
  // milliseconds, and the viscous form (resisting hourglass velocities only) let the elements next
  // to the axis drift into a sawtooth that grew until nodes crossed the axis (coarse 29 ms, default
  // 65 ms). The stiffness form holds it (docs/buried-structure.md, "Hourglass control").
  // The soil's control is the run's; the box's parts carry their own when it differs
  // (part_hourglass below).
  fmt::format_to(out, "[run.hourglass]  # {}\nform = \"{}\"\ncoefficient = {}\n",
                 s.soil_hourglass == "stiffness"
                     ? "stiffness form: the soil under the charge flows for tens of ms"
                     : "the soil's (soil.hourglass)",
                 s.soil_hourglass, s.soil_hourglass_kappa());
  if (axis_treatment)
    b += "subzonal = 1.0  # the soil's subzonal pressures (the box's parts: none)\n\n"
         "[run.viscosity]\nform = \"edge\"  # the soil's edge viscosity (the box's parts: the point q)\n";
  b += "\n";
  fmt::format_to(out, "[output]\nfield_interval = {}  # s\ngauge_interval = {}  # s\n\n", s.run.field_interval,
                 s.run.gauge_interval);
  fmt::format_to(out, "[materials.soil]\npreset = \"{}\"\n", s.soil);
  if (s.soil_erosion_strain > 0.0)
    fmt::format_to(out, "erosion = {{ geometric_strain = {} }}  # soil.erosion: FEM soil elements only\n",
                   s.soil_erosion_strain);
  fmt::format_to(out, "\n[materials.charge]\npreset = \"{}\"\n\n", s.explosive);
  fmt::format_to(out, "[materials.concrete]\npreset = \"{}\"\n\n", s.concrete);
  if (s.has_rebar && !s.free_field) fmt::format_to(out, "[materials.steel]\npreset = \"{}\"\n\n", s.steel);
}

std::string part_geostatic(const BuriedStructureSpec& s, const std::string& material) {
  if (s.run.gravity == 0.0 || material != "soil") return "";
  return "geostatic = { surface = 0.0, k0 = \"jaky\" }\n";
}

std::string part_hourglass(const BuriedStructureSpec& s, const std::string& material, bool axis_treatment) {
  if (material != "concrete") return "";
  if (axis_treatment)
    // The box keeps the volume form: under a standing load (gravity) a structure in the area form
    // does not come to rest (docs/theory-fem.md, "Axisymmetric momentum").
    return fmt::format("hourglass = {{ form = \"{}\", coefficient = {}, subzonal = 0.0 }}  # structure.hourglass\n"
                       "viscosity = {{ form = \"acceleration\" }}  # the box: the point q, no subzonal pressures\n"
                       "axisymmetric_momentum = \"volume\"  # the box: the volume form (the soil's: the area form)\n",
                       s.structure_hourglass, s.structure_hourglass_kappa());
  if (s.structure_hourglass == s.soil_hourglass && s.structure_hourglass_kappa() == s.soil_hourglass_kappa())
    return "";
  return fmt::format("hourglass = {{ form = \"{}\", coefficient = {} }}  # structure.hourglass\n",
                     s.structure_hourglass, s.structure_hourglass_kappa());
}

std::vector<StructureTarget> structure_targets(const BuriedStructureSpec& s) {
  const double r0 = s.standoff, t = s.wall_thickness, r1 = s.standoff + s.box_length;
  const double d0 = s.top_depth, d1 = s.top_depth + s.box_height;
  const double rf = r0 + 0.5 * t;   // front wall mid-line
  const double dfl = d1 - 0.5 * t;  // floor mid-line
  return {
      {"t1", rf, d0 + 0.5 * t, "front wall, top (roof corner)"},
      {"t2", rf, 0.5 * (d0 + d1), "front wall, mid-height"},
      {"t3", rf, dfl, "front wall, bottom (floor corner)"},
      {"t4", r0 + 0.25 * s.box_length, dfl, "floor, quarter span"},
      {"t5", r0 + 0.5 * s.box_length, dfl, "floor, mid-span"},
      {"t6", r1 - 0.5 * t, dfl, "floor, back corner"},
      {"t7", r0 + 0.5 * s.box_length, d0 + 0.5 * t, "roof, mid-span"},
      {"t8", r1 - 0.5 * t, 0.5 * (d0 + d1), "back wall, mid-height"},
      {"t9", r0 - 0.5 * std::min(s.size_structure, t), 0.5 * (d0 + d1),
       "front wall, mid-height, soil side of the interface"},
  };
}

}  // namespace camouflet::buried_detail
