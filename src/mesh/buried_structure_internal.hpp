#pragma once
// Shared between the axisymmetric (buried_structure.cpp) and the 3-D
// (buried_structure_3d.cpp) buried-structure generators, with the checks and
// derived sizes both use in buried_checks.cpp and the case-file tables both
// write in buried_case_tables.cpp; not a public interface.
#include <string>
#include <vector>

#include "mesh/buried_structure.hpp"

namespace camouflet::buried_detail {

// Whether the near field is an SPH zone (sph.radius > 0) rather than FEM.
inline bool has_sph_zone(const BuriedStructureSpec& s) {
  return s.sph_radius > 0.0;
}

// The checks both geometries share (charge buried, structure clear of the
// charge and of the near-field and SPH zones, domain holds them, sizes
// positive, rebar cover and ratio): InputError naming the key. `a` is the charge radius (m).
void check_common(const BuriedStructureSpec& s, double a);
// Radius (m) of the charge sphere of the given mass and density.
double charge_radius(const BuriedStructureSpec& s);
// Ranges (m from the charge centre) of the soil gauges of groups A and B, out to `far`.
std::vector<double> soil_gauge_ranges(const BuriedStructureSpec& s, double far);

// A structure target of Fig. 10 (our reading, docs/buried-structure.md): on
// the wall mid-lines, t9 in the soil at the front wall; `range` (m) from the
// charge axis (r, or x in 3-D), `depth` (m) below the ground.
struct StructureTarget {
  const char* name;
  double range, depth;
  const char* where;
};
std::vector<StructureTarget> structure_targets(const BuriedStructureSpec& s);

// The soil gauge groups A and B of Fig. 8a as [[gauges]] tables: points
// (r, z) in r-z, (x, 0, z) in the 3-D symmetry plane.
void write_soil_gauges(const BuriedStructureSpec& s, bool three_d, std::string& b);
// The box's members (front wall, roof, floor, rear wall) as member-average gauges (members.csv).
void write_member_gauges(const BuriedStructureSpec& s, bool three_d, std::string& b);

// The case file's [run], [output] and [materials.*] tables, the same in both
// geometries but for [run] geometry (`geometry`: "axisymmetric" or "3d").
void write_run_and_materials(const BuriedStructureSpec& s, const char* geometry, std::string& b);

// `hourglass = { ... }` line of a part of `material` ("concrete", "soil",
// "charge"): the box's own control where it differs from the soil's (the
// run's); empty otherwise. `axis_treatment` (r-z with an SPH zone): the box's parts always carry
// their own, without the subzonal pressures, and keep the point viscosity (write_run_and_materials
// gives the soil subzonal pressures and the edge viscosity).
std::string part_hourglass(const BuriedStructureSpec& s, const std::string& material, bool axis_treatment = false);
// `geostatic = { ... }` line of a FEM part of `material`: soil under gravity; empty otherwise.
std::string part_geostatic(const BuriedStructureSpec& s, const std::string& material);

// The generator line's interface keys (" interface=slide friction=MU" for a slide interface on a
// box, empty otherwise): the report names the interface from them.
std::string generator_interface(const BuriedStructureSpec& s);
// The [[slide_surfaces]] block that detaches the box's parts `box_parts` from the soil
// (structure.interface = "slide"), with its comment; nothing for a fused interface or a free field.
void write_slide_interface(const BuriedStructureSpec& s, const std::vector<std::string>& box_parts, std::string& b);

// Keys of one geometry given in the other (structure.width, domain.side in
// r-z) or missing (structure.width in 3-D): InputError naming the key.
void check_geometry_keys(const BuriedStructureSpec& s);
BuriedStructureLayout layout_3d(const BuriedStructureSpec& s);
std::string case_3d(const BuriedStructureSpec& s, const std::string& regenerate);
// Appends the 3-D box's rebar mats as [[bars]] (buried_rebar_3d.cpp).
void write_rebar_3d(const BuriedStructureSpec& s, std::string& b);

}  // namespace camouflet::buried_detail
