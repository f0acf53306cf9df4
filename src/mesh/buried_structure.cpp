#include "mesh/buried_structure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "mesh/buried_structure_internal.hpp"
#include "mesh/graded_axis.hpp"
#include "mesh/particle_fill.hpp"

namespace camouflet {

SourceLocation BuriedStructureSpec::location(const std::string& key) const {
  const auto it = where.find(key);
  return it != where.end() ? it->second : SourceLocation{source, 0, 0, key};
}

namespace {

using buried_detail::ends_of;
using buried_detail::has_sph_zone;
using buried_detail::Interval;
using buried_detail::layout_axis;
using buried_detail::Zone;

enum class Fill { soil, charge, concrete, empty };

struct Grid {
  std::vector<Interval> r;      // along r
  std::vector<Interval> depth;  // along depth y = -z, from the ground down
};

Fill fill_of(const BuriedStructureSpec& s, double half, double r, double y) {
  // With an SPH zone the charge is particles: the FEM grid is soil there (cut by the zone).
  if (!has_sph_zone(s) && r < half && std::abs(y - s.burst_depth) < half) return Fill::charge;
  const double r0 = s.standoff, r1 = s.standoff + s.box_length;
  const double y0 = s.top_depth, y1 = s.top_depth + s.box_height, t = s.wall_thickness;
  if (r > r0 && r < r1 && y > y0 && y < y1) {
    const bool interior = r > r0 + t && r < r1 - t && y > y0 + t && y < y1 - t;
    if (s.free_field) return Fill::soil;  // the ground as it was before the box
    return interior ? Fill::empty : Fill::concrete;
  }
  return Fill::soil;
}

Grid make_grid(const BuriedStructureSpec& s, double half) {
  const double margin = 2.0 * s.size_structure;  // structure-sized cells reach this far into the soil
  const double r0 = s.standoff, r1 = s.standoff + s.box_length, t = s.wall_thickness;
  const double y0 = s.top_depth, y1 = s.top_depth + s.box_height;
  Grid g;
  const double near = s.near_extent();
  // Block lines: the charge square (FEM charge) or the SPH zone's edges (the hole).
  std::vector<double> r_lines{r0, r0 + t, r1 - t, r1};
  std::vector<double> y_lines{y0, y0 + t, y1 - t, y1};
  if (has_sph_zone(s)) {
    r_lines.push_back(s.sph_radius);
    y_lines.push_back(s.sph_bottom());
  } else {
    r_lines.push_back(half);
    y_lines.push_back(s.burst_depth - half);
    y_lines.push_back(s.burst_depth + half);
  }
  g.r = layout_axis(0.0, s.domain_radius, r_lines,
                    {{0.0, near, s.size_near}, {r0 - margin, r1 + margin, s.size_structure}}, s.size_soil,
                    s.size_far);
  g.depth = layout_axis(0.0, s.domain_depth, y_lines,
                        {{s.burst_depth - near, s.burst_depth + s.near_extent_below(), s.size_near},
                         {y0 - margin, y1 + margin, s.size_structure}},
                        s.size_soil, s.size_far);
  return g;
}

// The SPH zone's particles, filled here as the case reader will fill them
// (mesh/particle_fill.hpp) to count them. The charge is the cell-centred
// lattice of N = charge.particles_across_radius cells across a radius a' with
// spacing a'/N: the lattice is the same set of cells at every a', so its
// volume is c_N a'^3 and a' = (V / c_N)^(1/3) holds the charge's volume V
// exactly (no cell centre lies on the circle: (i+1/2)^2 + (j+1/2)^2 is never a
// whole number), whatever the mass and the zone's spacing.
double lattice_volume(const ParticleFillSpec& fill, ParticleSet& set) {
  fill_particles(set, fill, GeometryMode::axisymmetric);
  double v = 0.0;
  for (double dv : set.volume) v += dv;
  return v;
}

void layout_sph_zone(const BuriedStructureSpec& s, BuriedStructureLayout& L) {
  const double volume = s.charge_mass / s.explosive_density;
  const int n = s.charge_particles_across;
  ParticleFillSpec charge;
  charge.region.shape = ParticleRegion::Shape::sphere;
  charge.region.centre = {0.0, -s.burst_depth, 0.0};
  charge.region.radius = L.charge_radius;
  charge.spacing = L.charge_radius / n;
  ParticleSet trial;
  const double trial_volume = lattice_volume(charge, trial);
  charge.region.radius = L.charge_radius * std::cbrt(volume / trial_volume);
  charge.spacing = charge.region.radius / n;
  ParticleSet set;
  L.charge_model_mass = lattice_volume(charge, set) * s.explosive_density;
  L.charge_fill_radius = charge.region.radius;
  L.charge_spacing = charge.spacing;
  L.charge_particles = set.count();
  L.zone_spacing = s.size_near;
  ParticleFillSpec zone;
  zone.region.min = {0.0, -s.sph_bottom(), 0.0};
  zone.region.max = {s.sph_radius, 0.0, 0.0};
  zone.spacing = s.size_near;
  zone.exclude.push_back(charge.region);
  ParticleSet zone_set;
  fill_particles(zone_set, zone, GeometryMode::axisymmetric);
  L.zone_particles = zone_set.count();
}

// Inner and outer mats of every wall as embedded bars ([[bars]]), bar lines at
// the cover from each face, running between the mats of the adjoining walls;
// the front wall's bars run downwards, so segment 1 is at the top. The rebar
// gauges of the paper's Fig. 13 are front-wall segments: In-1..3 (inner mat)
// and Out-1..3 (outer, soil side) at the top, mid-height and bottom.
void write_rebar(const BuriedStructureSpec& s, std::string& b) {
  auto out = std::back_inserter(b);
  const double c = s.rebar_cover, t = s.wall_thickness;
  const double r0 = s.standoff, r1 = s.standoff + s.box_length;
  const double y0 = s.top_depth, y1 = s.top_depth + s.box_height;
  const double area = s.rebar_ratio * t;
  struct Line {
    const char* name;
    double ra, ya, rb, yb;
  };
  const double o = c, i = t - c;  // outer and inner bar lines from each outer face
  const Line lines[] = {
      {"front_out", r0 + o, y0 + o, r0 + o, y1 - o}, {"front_in", r0 + i, y0 + i, r0 + i, y1 - i},
      {"back_out", r1 - o, y0 + o, r1 - o, y1 - o},  {"back_in", r1 - i, y0 + i, r1 - i, y1 - i},
      {"roof_out", r0 + o, y0 + o, r1 - o, y0 + o},  {"roof_in", r0 + i, y0 + i, r1 - i, y0 + i},
      {"floor_out", r0 + o, y1 - o, r1 - o, y1 - o}, {"floor_in", r0 + i, y1 - i, r1 - i, y1 - i},
  };
  int out_segments = 1, in_segments = 1;
  b += "# Reinforcement mats as embedded bars (docs/buried-structure.md, \"Reinforcement\").\n";
  for (const Line& l : lines) {
    const int n =
        std::max(2, static_cast<int>(std::lround(std::hypot(l.rb - l.ra, l.yb - l.ya) / s.size_structure)));
    if (std::string(l.name) == "front_out") out_segments = n;
    if (std::string(l.name) == "front_in") in_segments = n;
    fmt::format_to(out,
                   "[[bars]]\nname = \"{}\"\nfrom = [{:.9g}, {:.9g}]\nto = [{:.9g}, {:.9g}]\nsegments = {}\n"
                   "area = {:.6g}  # m^2 per metre of circumference\nmaterial = \"steel\"\n\n",
                   l.name, l.ra, -l.ya + 0.0, l.rb, -l.yb + 0.0, n, area);
  }
  fmt::format_to(out,
                 "# rebar gauges (bars.csv): In-1=front_in.1 In-2=front_in.{} In-3=front_in.{} "
                 "Out-1=front_out.1 Out-2=front_out.{} Out-3=front_out.{}\n\n",
                 (in_segments + 1) / 2, in_segments, (out_segments + 1) / 2, out_segments);
}

}  // namespace

BuriedStructureLayout layout_buried_structure(const BuriedStructureSpec& spec) {
  buried_detail::check_geometry_keys(spec);
  if (spec.three_d) return buried_detail::layout_3d(spec);
  BuriedStructureLayout L;
  L.charge_radius = buried_detail::charge_radius(spec);
  buried_detail::check_common(spec, L.charge_radius);
  // Equal-volume cylinder of height = diameter: pi b^2 2b = 4/3 pi a^3.
  L.charge_half_size = std::cbrt(2.0 / 3.0) * L.charge_radius;
  const Grid g = make_grid(spec, L.charge_half_size);
  L.r_lines = ends_of(g.r);
  for (double y : ends_of(g.depth)) L.z_lines.push_back(-y + 0.0);
  std::reverse(L.z_lines.begin(), L.z_lines.end());
  for (const Interval& i : g.r)
    for (const Interval& j : g.depth) {
      if (fill_of(spec, L.charge_half_size, 0.5 * (i.a + i.b), 0.5 * (j.a + j.b)) == Fill::empty) continue;
      ++L.block_count;
      L.element_count += static_cast<std::size_t>(i.cells) * static_cast<std::size_t>(j.cells);
    }
  // Image sources of the charge in the far edges, seen from the front wall's mid-height.
  const double y9 = spec.top_depth + 0.5 * spec.box_height;
  const double via_side = std::hypot(2.0 * spec.domain_radius - spec.standoff, spec.burst_depth - y9);
  const double via_bottom = std::hypot(spec.standoff, 2.0 * spec.domain_depth - spec.burst_depth - y9);
  L.reflection_time = std::min(via_side, via_bottom) / spec.soil_wave_speed;
  if (has_sph_zone(spec)) layout_sph_zone(spec, L);
  return L;
}

std::string buried_structure_case(const BuriedStructureSpec& s, const std::string& regenerate) {
  if (s.three_d) return buried_detail::case_3d(s, regenerate);
  const BuriedStructureLayout L = layout_buried_structure(s);
  const Grid g = make_grid(s, L.charge_half_size);
  std::string b;
  auto out = std::back_inserter(b);
  fmt::format_to(
      out,
      "# Generated by `camouflet generate` (src/mesh/buried_structure.cpp, docs/buried-structure.md).\n"
      "# Do not edit the mesh by hand: change the parameter file and regenerate:\n#   {}\n#\n",
      regenerate);
  if (has_sph_zone(s))
    fmt::format_to(
        out,
        "# {} kg of {} (sphere radius {:.3f} m: an r-z disc of {} SPH particles of {:.4g} m, {} across\n"
        "# its radius, modelled mass {:.2f} kg) centred {} m deep on the axis, in an SPH soil zone r <= {} "
        "m, from the ground "
        "down\n"
        "# to {} m ({} particles of {:.4g} m) joined to the FEM soil; RC box {} m x {} m, walls {} m, front\n"
        "# face {} m from the axis, roof top {} m deep; domain {} m x {} m; {} blocks, {} elements before\n"
        "# the zone's hole is cut.\n#\n",
        s.charge_mass, s.explosive, L.charge_radius, L.charge_particles, L.charge_spacing,
        s.charge_particles_across, L.charge_model_mass, s.burst_depth, s.sph_radius, s.sph_bottom(),
        L.zone_particles, L.zone_spacing, s.box_length, s.box_height, s.wall_thickness, s.standoff,
        s.top_depth, s.domain_radius, s.domain_depth, L.block_count, L.element_count);
  else
    fmt::format_to(
        out,
        "# {} kg of {} (sphere radius {:.3f} m, modelled as the equal-volume r-z square of half side\n"
        "# {:.3f} m) centred {} m deep on the axis; RC box {} m x {} m, walls {} m, front face {} m from\n"
        "# the axis, roof top {} m deep; domain {} m x {} m; {} blocks, {} elements.\n#\n",
        s.charge_mass, s.explosive, L.charge_radius, L.charge_half_size, s.burst_depth, s.box_length,
        s.box_height, s.wall_thickness, s.standoff, s.top_depth, s.domain_radius, s.domain_depth,
        L.block_count, L.element_count);
  // Machine-readable for scripts/report.py.
  fmt::format_to(
      out,
      "# generator: charge_mass_kg={} burst_depth_m={} standoff_m={} box_length_m={} box_height_m={} "
      "wall_thickness_m={} top_depth_m={}{}{}\n#\n",
      s.charge_mass, s.burst_depth, s.standoff, s.box_length, s.box_height, s.wall_thickness, s.top_depth,
      s.free_field ? " structure_kind=free_field" : "", buried_detail::generator_interface(s));
  if (!has_sph_zone(s))
    b +=
        "# No SPH zone (sph.radius = 0): the charge (JWL elements, programmed burn) and the near field are\n"
        "# Lagrangian FEM: crater ejecta are not followed, and the run stops if elements next to the charge\n"
        "# invert.\n";
  else if (s.run.gravity == 0.0)
    b +=
        "# Ejecta: no domain box is set, so particles thrown above the ground fly on (no gravity) and never\n"
        "# stop the run; none is removed.\n";
  else
    b +=
        "# Ejecta: no domain box is set; particles thrown above the ground fly under gravity and never stop\n"
        "# the run; none is removed.\n";
  if (s.run.gravity > 0.0)
    b +=
        "# Gravity: the soil, FEM and SPH, starts in its geostatic state (Jaky's K0); the box settles in it\n"
        "# by a dynamic relaxation before t = 0, the charge held unlit (docs/theory/gravity.md).\n";
  if (s.free_field)
    b += "# Free field (structure.kind = \"free_field\"): the box's place and its interior are soil, no box and\n"
         "# no bars; the structure targets and the members measure the ground where the box would stand.\n";
  else if (s.has_rebar)
    fmt::format_to(
        out,
        "# Reinforcement: inner and outer mats in every wall, roof and floor as embedded bars at {} m\n"
        "# cover, steel area {:.4g} m^2 per metre of circumference per mat (ratio {} x wall {} m).\n",
        s.rebar_cover, s.rebar_ratio * s.wall_thickness, s.rebar_ratio, s.wall_thickness);
  else
    b += "# No reinforcement (plain concrete box): give [rebar] cover and ratio in the parameter file.\n";
  if (s.transmitting)
    fmt::format_to(
        out,
        "# Far edges: transmitting (Lysmer-Kuhlemeyer dashpots). A wave reflected there anyway would\n"
        "# reach the front wall after {:.1f} ms (at {} m/s).\n\n",
        1e3 * L.reflection_time, s.soil_wave_speed);
  else
    fmt::format_to(
        out,
        "# NOTE: far edges FIXED (not transmitting): the reflection reaches the front wall at {:.1f} ms\n"
        "# (at {} m/s); results after that time include the reflected wave.\n\n",
        1e3 * L.reflection_time, s.soil_wave_speed);

  buried_detail::write_run_and_materials(s, "axisymmetric", b);

  // One part per block of the tensor grid: adjacent blocks share nodes.
  std::string boundaries;
  auto bout = std::back_inserter(boundaries);
  std::vector<std::string> box_parts;  // the concrete blocks (a slide interface detaches them)
  const char* far_type = s.transmitting ? "transmitting" : "fixed";
  for (std::size_t i = 0; i < g.r.size(); ++i)
    for (std::size_t j = 0; j < g.depth.size(); ++j) {
      const Interval& ri = g.r[i];
      const Interval& yj = g.depth[j];
      const Fill fill = fill_of(s, L.charge_half_size, 0.5 * (ri.a + ri.b), 0.5 * (yj.a + yj.b));
      if (fill == Fill::empty) continue;
      const char* material = fill == Fill::charge ? "charge" : fill == Fill::concrete ? "concrete" : "soil";
      const std::string name = fmt::format("{}_r{}_z{}", material, i, j);
      if (fill == Fill::concrete) box_parts.push_back(name);
      // Grading along z runs from the block's deep edge up: the inverse of the depth grading.
      fmt::format_to(out,
                     "[[parts]]\nname = \"{}\"\nmaterial = \"{}\"\n{}{}block = {{ origin = [{:.9g}, {:.9g}], "
                     "size = [{:.9g}, {:.9g}], cells = [{}, {}], grading = [{:.9g}, {:.9g}] }}\n\n",
                     name, material, buried_detail::part_hourglass(s, material, s.axis_treatment()),
                     buried_detail::part_geostatic(s, material), ri.a, -yj.b + 0.0, ri.b - ri.a, yj.b - yj.a,
                     ri.cells, yj.cells, ri.grading, 1.0 / yj.grading);
      if (i == 0) fmt::format_to(bout, "[[boundary]]\ntype = \"axis\"\nset = \"{}.xmin\"\n\n", name);
      if (i + 1 == g.r.size())
        fmt::format_to(bout, "[[boundary]]\ntype = \"{}\"\nset = \"{}.xmax\"\n\n", far_type, name);
      if (j + 1 == g.depth.size())
        fmt::format_to(bout, "[[boundary]]\ntype = \"{}\"\nset = \"{}.ymin\"\n\n", far_type, name);
    }
  if (has_sph_zone(s)) {
    // The charge first, then the zone, which leaves the charge's disc out and
    // cuts its hole from the soil blocks (docs/case-format.md, "Joined SPH zones").
    fmt::format_to(
        out,
        "# SPH (Wang et al. 2005, Fig. 6): the charge as explosive particles, detonated at its centre;\n"
        "# the near-field soil as particles replacing the soil elements in the zone, joined to them.\n"
        "[[parts]]\nname = \"charge\"\nkind = \"sph\"\nmaterial = \"charge\"\n"
        "fill = {{ shape = \"sphere\", centre = [0.0, {:.9g}], radius = {:.12g}, spacing = {:.12g} }}\n\n",
        -s.burst_depth, L.charge_fill_radius, L.charge_spacing);
    fmt::format_to(
        out,
        "[[parts]]\nname = \"near_field\"\nkind = \"sph\"\nmaterial = \"soil\"\njoin = true\n"
        "exclude = [\"charge\"]\n"
        "fill = {{ shape = \"box\", min = [0.0, {:.9g}], max = [{:.9g}, 0.0], spacing = {:.9g} }}\n{}\n",
        -s.sph_bottom(), s.sph_radius, L.zone_spacing, buried_detail::part_geostatic(s, "soil"));
    // The three-phase soil reports its unloading (water-solid) sound speed,
    // several times the speed of the compaction wave, so the linear term
    // alpha c mu of the particle viscosity at the usual alpha = 1 damps the
    // ground shock five- to tenfold within a metre (docs/buried-structure.md,
    // "SPH viscosity"); alpha = 0.2 keeps it near the FEM bulk viscosity's.
    // Next to the axis the hoop terms from the smoothed sums, handed over to the point values
    // within half a smoothing length of it, and the viscosity's own hoop term: with them the
    // first column of particles moves as the second (coarse, with the FEM soil's treatment of
    // write_run_and_materials: 1.01 against 1.99 before; docs/theory/sph.md, "The band next to
    // the axis").
    b += "[sph]\nviscosity_alpha = 0.2  # linear term (see docs/buried-structure.md, \"SPH viscosity\")\n"
         "viscosity_beta = 2.0   # quadratic term\n"
         "smoothed_hoop = true  # the axis (docs/theory/sph.md, \"The band next to the axis\")\n"
         "smoothed_hoop_width = 0.5\n"
         "viscosity_hoop = true\n\n";
  }
  if (s.has_rebar && !s.free_field) write_rebar(s, b);
  buried_detail::write_slide_interface(s, box_parts, b);
  b += "# Boundaries: the axis r = 0; the far edges; the ground surface z = 0 is free.\n";
  b += boundaries;

  fmt::format_to(out, "[[detonation]]\nposition = [0.0, {:.9g}]  # m, the charge centre\ntime = 0.0\n\n",
                 -s.burst_depth);

  buried_detail::write_soil_gauges(s, false, b);

  b += "# Structure targets (Wang et al. 2005, Fig. 10; placement documented in docs/buried-structure.md).\n";
  b += "[[gauges]]\nname = \"structure\"\npoints = [\n";
  for (const buried_detail::StructureTarget& tg : buried_detail::structure_targets(s))
    fmt::format_to(out, "  {{ name = \"{}\", position = [{:.6g}, {:.6g}] }},  # {}\n", tg.name, tg.range,
                   -tg.depth, tg.where);
  b += "]\n";
  buried_detail::write_member_gauges(s, false, b);
  return b;
}

}  // namespace camouflet
