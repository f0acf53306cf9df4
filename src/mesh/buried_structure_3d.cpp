// The 3-D variant of the buried-structure generator (a box beside a
// charge, with a symmetry plane): x from the charge towards the box, y along
// the box's front wall, z up, the ground surface z = 0 free. The charge sits
// on the z axis; the plane y = 0 through the charge centre and the box's
// mid-width is a symmetry plane, so half the model (y >= 0) is meshed. As in
// r-z, soil, charge and the closed concrete box (front, back and side walls,
// roof, floor) are hex blocks of one tensor-product grid (fused nodes), graded
// fine near the charge and in the structure, coarse far away; the far faces
// x = -side, x = radius, y = side and the bottom are transmitting.
// docs/buried-structure.md, "3-D variant".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "mesh/buried_structure_internal.hpp"
#include "mesh/graded_axis.hpp"
#include "mesh/particle_fill.hpp"

namespace camouflet::buried_detail {

namespace {

enum class Fill { soil, charge, concrete, empty };

struct Grid {
  std::vector<Interval> x;      // from the far face behind the charge (x = -side) to x = radius
  std::vector<Interval> y;      // from the symmetry plane to the far face y = side
  std::vector<Interval> depth;  // depth = -z, from the ground down
};

double side_of(const BuriedStructureSpec& s) {
  return s.domain_side > 0.0 ? s.domain_side : s.domain_radius;
}

// Half side (m) of the cube of the charge's volume, (2h)^3 = 4/3 pi a^3: the
// 3-D charge is this cube (FEM elements or SPH particles), half of it in the model.
double cube_half_side(double a) {
  return std::cbrt(std::numbers::pi / 6.0) * a;
}

Fill fill_of(const BuriedStructureSpec& s, double h, double x, double y, double d) {
  if (!has_sph_zone(s) && std::abs(x) < h && y < h && std::abs(d - s.burst_depth) < h) return Fill::charge;
  const double x0 = s.standoff, x1 = s.standoff + s.box_length, yw = 0.5 * s.box_width;
  const double d0 = s.top_depth, d1 = s.top_depth + s.box_height, t = s.wall_thickness;
  if (x > x0 && x < x1 && y < yw && d > d0 && d < d1) {
    const bool interior = x > x0 + t && x < x1 - t && y < yw - t && d > d0 + t && d < d1 - t;
    if (s.free_field) return Fill::soil;  // the ground as it was before the box
    return interior ? Fill::empty : Fill::concrete;
  }
  return Fill::soil;
}

// What r-z does not check: the box's width and the far faces behind and beside the charge.
void check_3d(const BuriedStructureSpec& s, double a) {
  const auto fail = [&](const std::string& key, const std::string& message) {
    throw InputError(s.location(key), message);
  };
  if (!(s.box_width > 0.0) || !std::isfinite(s.box_width))
    fail("structure.width", fmt::format("must be a positive number (m), got {}", s.box_width));
  if (2.0 * s.wall_thickness >= s.box_width)
    fail("structure.width",
         fmt::format("a {} m wide box leaves no room inside its {} m walls", s.box_width, s.wall_thickness));
  if (!(s.domain_side >= 0.0) || !std::isfinite(s.domain_side) ||
      (s.where.count("domain.side") > 0 && !(s.domain_side > 0.0)))
    fail("domain.side", fmt::format("must be a positive number (m), got {}", s.domain_side));
  const double side = side_of(s);
  if (0.5 * s.box_width + s.size_structure >= side)
    fail("domain.side",
         fmt::format("{} m does not contain the structure (half width {} m)", side, 0.5 * s.box_width));
  if (s.near_extent() + s.size_near >= side)
    fail("domain.side", fmt::format("{} m does not contain the near-field zone around the charge ({} m)",
                                    side, s.near_extent()));
  if (a + s.size_near >= side) fail("domain.side", fmt::format("{} m does not contain the charge", side));
}

Grid make_grid(const BuriedStructureSpec& s, double h) {
  const double margin = 2.0 * s.size_structure;
  const double x0 = s.standoff, x1 = s.standoff + s.box_length, yw = 0.5 * s.box_width;
  const double d0 = s.top_depth, d1 = s.top_depth + s.box_height, t = s.wall_thickness;
  const double near = s.near_extent();
  std::vector<double> x_lines{x0, x0 + t, x1 - t, x1}, y_lines{yw - t, yw}, d_lines{d0, d0 + t, d1 - t, d1};
  if (has_sph_zone(s)) {
    const double R = s.sph_radius;
    x_lines.insert(x_lines.end(), {-R, R});
    y_lines.push_back(R);
    d_lines.push_back(s.sph_bottom());
  } else {
    x_lines.insert(x_lines.end(), {-h, h});
    y_lines.push_back(h);
    d_lines.insert(d_lines.end(), {s.burst_depth - h, s.burst_depth + h});
  }
  Grid g;
  g.x = layout_axis(-side_of(s), s.domain_radius, x_lines,
                    {{-near, near, s.size_near}, {x0 - margin, x1 + margin, s.size_structure}}, s.size_soil,
                    s.size_far, true);
  g.y = layout_axis(0.0, side_of(s), y_lines,
                    {{-near, near, s.size_near}, {-margin, yw + margin, s.size_structure}}, s.size_soil,
                    s.size_far);
  g.depth = layout_axis(0.0, s.domain_depth, d_lines,
                        {{s.burst_depth - near, s.burst_depth + s.near_extent_below(), s.size_near},
                         {d0 - margin, d1 + margin, s.size_structure}},
                        s.size_soil, s.size_far);
  return g;
}

double mid(const Interval& i) {
  return 0.5 * (i.a + i.b);
}

// The charge's particle spacing: charge.particles_across_radius cells along the
// cube's half side, which tiles the cube (and so the charge's volume) exactly
// at every mass; an even count across the cube puts no particle at the
// detonation point but every one within a spacing of it.
double charge_spacing(const BuriedStructureSpec& s, double h) {
  return h / s.charge_particles_across;
}

ParticleFillSpec charge_fill(const BuriedStructureSpec& s, double h) {
  ParticleFillSpec f;
  f.region.min = {-h, 0.0, -s.burst_depth - h};
  f.region.max = {h, h, -s.burst_depth + h};
  f.spacing = charge_spacing(s, h);
  return f;
}

ParticleFillSpec zone_fill(const BuriedStructureSpec& s, const ParticleFillSpec& charge) {
  ParticleFillSpec f;
  f.region.min = {-s.sph_radius, 0.0, -s.sph_bottom()};
  f.region.max = {s.sph_radius, s.sph_radius, 0.0};
  f.spacing = s.size_near;
  f.exclude.push_back(charge.region);
  return f;
}

// The particles as the case reader will fill them (mesh/particle_fill.hpp), for the counts and mass.
void layout_sph_zone(const BuriedStructureSpec& s, BuriedStructureLayout& L) {
  const ParticleFillSpec charge = charge_fill(s, L.charge_half_size);
  ParticleSet set;
  fill_particles(set, charge, GeometryMode::three_d);
  L.charge_spacing = charge.spacing;
  L.charge_particles = set.count();
  double v = 0.0;
  for (double dv : set.volume) v += dv;
  L.charge_model_mass = 2.0 * v * s.explosive_density;  // both halves
  ParticleSet zone;
  fill_particles(zone, zone_fill(s, charge), GeometryMode::three_d);
  L.zone_spacing = s.size_near;
  L.zone_particles = zone.count();
}

std::string fmt_point(double x, double y, double z) {
  return fmt::format("[{:.12g}, {:.12g}, {:.12g}]", x, y, z + 0.0);
}

void write_header(const BuriedStructureSpec& s, const BuriedStructureLayout& L, const std::string& regenerate,
                  std::string& b) {
  auto out = std::back_inserter(b);
  fmt::format_to(
      out,
      "# Generated by `camouflet generate` (src/mesh/buried_structure_3d.cpp, docs/buried-structure.md).\n"
      "# Do not edit the mesh by hand: change the parameter file and regenerate:\n#   {}\n#\n"
      "# 3-D, half model: x from the charge towards the box, y along the box's front wall, z up; the plane\n"
      "# y = 0 through the charge centre and the box's mid-width is a symmetry plane.\n",
      regenerate);
  if (has_sph_zone(s))
    fmt::format_to(
        out,
        "# {} kg of {} (sphere radius {:.3f} m, modelled as the equal-volume cube of half side {:.3f} m:\n"
        "# {} SPH particles of {:.4g} m in the half model, {} along its half side, {:.2f} kg in all) centred "
        "{} m deep, in an\n"
        "# SPH soil zone |x| <= {} m, y <= {} m, from the ground down to {} m ({} particles of {:.4g} "
        "m)\n# joined to the FEM soil;",
        s.charge_mass, s.explosive, L.charge_radius, L.charge_half_size, L.charge_particles, L.charge_spacing,
        s.charge_particles_across, L.charge_model_mass, s.burst_depth, s.sph_radius, s.sph_radius,
        s.sph_bottom(), L.zone_particles, L.zone_spacing);
  else
    fmt::format_to(
        out,
        "# {} kg of {} (sphere radius {:.3f} m, modelled as the equal-volume cube of half side {:.3f} m)\n"
        "# centred {} m deep on the z axis;",
        s.charge_mass, s.explosive, L.charge_radius, L.charge_half_size, s.burst_depth);
  fmt::format_to(
      out,
      " closed RC box {} m (x) x {} m (y) x {} m high, walls {} m,\n"
      "# front face {} m from the charge axis, roof top {} m deep; domain x {} .. {} m, y 0 .. {} m, "
      "{} m deep;\n# {} blocks, {} elements{}.\n#\n",
      s.box_length, s.box_width, s.box_height, s.wall_thickness, s.standoff, s.top_depth, -side_of(s),
      s.domain_radius, side_of(s), s.domain_depth, L.block_count, L.element_count,
      has_sph_zone(s) ? " before the zone's hole is cut" : "");
  fmt::format_to(
      out,
      "# generator: charge_mass_kg={} burst_depth_m={} standoff_m={} box_length_m={} box_height_m={} "
      "wall_thickness_m={} top_depth_m={} box_width_m={} three_d=1{}{}\n#\n",
      s.charge_mass, s.burst_depth, s.standoff, s.box_length, s.box_height, s.wall_thickness, s.top_depth,
      s.box_width, s.free_field ? " structure_kind=free_field" : "", generator_interface(s));
  if (has_sph_zone(s))
    b += "# Ejecta: no domain box is set; particles thrown above the ground fly on, none is removed.\n";
  else
    b += "# No SPH zone (sph.radius = 0): charge (JWL elements, programmed burn) and near field are FEM;\n"
         "# crater ejecta are not followed, and the run stops if elements next to the charge invert.\n";
  if (s.free_field)
    b += "# Free field (structure.kind = \"free_field\"): the box's place and its interior are soil, no box and\n"
         "# no bars; the structure targets and the members measure the ground where the box would stand.\n";
  else if (s.has_rebar)
    fmt::format_to(
        out,
        "# Reinforcement: an inner and an outer mat in every wall, roof and floor, each of bars in both\n"
        "# directions at {} m cover, steel area {:.4g} m^2 per metre per direction per mat.\n",
        s.rebar_cover, s.rebar_ratio * s.wall_thickness);
  else
    b += "# No reinforcement (plain concrete box): give [rebar] cover and ratio in the parameter file.\n";
  fmt::format_to(out,
                 "# Far faces: {}. A wave reflected there would reach the front wall after {:.1f} ms (at {} "
                 "m/s).\n\n",
                 s.transmitting ? "transmitting (Lysmer-Kuhlemeyer dashpots)" : "FIXED (not transmitting)",
                 1e3 * L.reflection_time, s.soil_wave_speed);
}

void write_gauges(const BuriedStructureSpec& s, std::string& b) {
  auto out = std::back_inserter(b);
  write_soil_gauges(s, true, b);

  b += "# Structure targets (Wang et al. 2005, Fig. 10; docs/buried-structure.md) at the box's mid-width y = "
       "0.\n";
  b += "[[gauges]]\nname = \"structure\"\npoints = [\n";
  for (const StructureTarget& tg : structure_targets(s))
    fmt::format_to(out, "  {{ name = \"{}\", position = [{:.6g}, 0.0, {:.6g}] }},  # {}\n", tg.name, tg.range,
                   -tg.depth, tg.where);
  b += "]\n";
  write_member_gauges(s, true, b);
}

}  // namespace

void check_geometry_keys(const BuriedStructureSpec& s) {
  const auto given = [&](const std::string& key, double value) {
    return s.where.count(key) > 0 || value != 0.0;
  };
  if (!s.three_d) {
    if (given("structure.width", s.box_width))
      throw InputError(
          s.location("structure.width"),
          "only in 3-D ([domain] geometry = \"3d\"): the axisymmetric box is a ring about the axis");
    if (given("domain.side", s.domain_side))
      throw InputError(s.location("domain.side"), "only in 3-D ([domain] geometry = \"3d\")");
  } else if (!given("structure.width", s.box_width)) {
    throw InputError(s.location("structure.width"),
                     "required in 3-D: the box's outer extent along its front wall (m)");
  }
}

BuriedStructureLayout layout_3d(const BuriedStructureSpec& s) {
  BuriedStructureLayout L;
  L.charge_radius = charge_radius(s);
  check_common(s, L.charge_radius);
  check_3d(s, L.charge_radius);
  L.charge_half_size = cube_half_side(L.charge_radius);
  const Grid g = make_grid(s, L.charge_half_size);
  L.r_lines = ends_of(g.x);
  L.y_lines = ends_of(g.y);
  for (double d : ends_of(g.depth)) L.z_lines.push_back(-d + 0.0);
  std::reverse(L.z_lines.begin(), L.z_lines.end());
  for (const Interval& i : g.x)
    for (const Interval& j : g.y)
      for (const Interval& k : g.depth) {
        if (fill_of(s, L.charge_half_size, mid(i), mid(j), mid(k)) == Fill::empty) continue;
        ++L.block_count;
        L.element_count += static_cast<std::size_t>(i.cells) * static_cast<std::size_t>(j.cells) *
                           static_cast<std::size_t>(k.cells);
      }
  // Image sources of the charge in the far faces (x = radius, y = side, the
  // bottom), seen from the front wall's mid-height in the symmetry plane.
  const double d9 = s.top_depth + 0.5 * s.box_height, dz = s.burst_depth - d9;
  const double via_x = std::hypot(2.0 * s.domain_radius - s.standoff, dz);
  const double via_y = std::hypot(std::hypot(s.standoff, 2.0 * side_of(s)), dz);
  const double via_bottom = std::hypot(s.standoff, 2.0 * s.domain_depth - s.burst_depth - d9);
  L.reflection_time = std::min({via_x, via_y, via_bottom}) / s.soil_wave_speed;
  if (has_sph_zone(s)) layout_sph_zone(s, L);
  return L;
}

std::string case_3d(const BuriedStructureSpec& s, const std::string& regenerate) {
  const BuriedStructureLayout L = layout_3d(s);
  const Grid g = make_grid(s, L.charge_half_size);
  std::string b;
  auto out = std::back_inserter(b);
  write_header(s, L, regenerate, b);
  write_run_and_materials(s, "3d", b);

  // One part per block of the tensor grid: adjacent blocks share nodes.
  std::string boundaries;
  auto bout = std::back_inserter(boundaries);
  std::vector<std::string> box_parts;  // the concrete blocks (a slide interface detaches them)
  const char* far_type = s.transmitting ? "transmitting" : "fixed";
  for (std::size_t i = 0; i < g.x.size(); ++i)
    for (std::size_t j = 0; j < g.y.size(); ++j)
      for (std::size_t k = 0; k < g.depth.size(); ++k) {
        const Interval &xi = g.x[i], &yj = g.y[j], &dk = g.depth[k];
        const Fill fill = fill_of(s, L.charge_half_size, mid(xi), mid(yj), mid(dk));
        if (fill == Fill::empty) continue;
        const char* material = fill == Fill::charge ? "charge" : fill == Fill::concrete ? "concrete" : "soil";
        const std::string name = fmt::format("{}_x{}_y{}_z{}", material, i, j, k);
        if (fill == Fill::concrete) box_parts.push_back(name);
        // Along z the block runs from its deep face up: the inverse of the depth grading.
        fmt::format_to(
            out,
            "[[parts]]\nname = \"{}\"\nmaterial = \"{}\"\n{}{}block = {{ origin = {}, size = [{:.12g}, "
            "{:.12g}, {:.12g}], cells = [{}, {}, {}], grading = [{:.9g}, {:.9g}, {:.9g}] }}\n\n",
            name, material, part_hourglass(s, material), part_geostatic(s, material),
            fmt_point(xi.a, yj.a, -dk.b), xi.b - xi.a, yj.b - yj.a, dk.b - dk.a, xi.cells, yj.cells, dk.cells,
            xi.grading, yj.grading, 1.0 / dk.grading);
        if (j == 0)
          fmt::format_to(bout,
                         "[[boundary]]\ntype = \"symmetry\"\nset = \"{}.ymin\"\nnormal = [0.0, 1.0, 0.0]\n\n",
                         name);
        const auto far = [&](const char* face) {
          fmt::format_to(bout, "[[boundary]]\ntype = \"{}\"\nset = \"{}.{}\"\n\n", far_type, name, face);
        };
        if (i == 0) far("xmin");
        if (i + 1 == g.x.size()) far("xmax");
        if (j + 1 == g.y.size()) far("ymax");
        if (k + 1 == g.depth.size()) far("zmin");
      }
  if (has_sph_zone(s)) {
    const ParticleFillSpec charge = charge_fill(s, L.charge_half_size);
    const ParticleFillSpec zone = zone_fill(s, charge);
    b += "# SPH (Wang et al. 2005, Fig. 6): the charge as explosive particles, detonated at its centre;\n"
         "# the near-field soil as particles replacing the soil elements in the zone, joined to them.\n";
    fmt::format_to(out,
                   "[[parts]]\nname = \"charge\"\nkind = \"sph\"\nmaterial = \"charge\"\n"
                   "fill = {{ shape = \"box\", min = {}, max = {}, spacing = {:.12g} }}\n\n",
                   fmt_point(charge.region.min[0], charge.region.min[1], charge.region.min[2]),
                   fmt_point(charge.region.max[0], charge.region.max[1], charge.region.max[2]),
                   charge.spacing);
    fmt::format_to(
        out,
        "[[parts]]\nname = \"near_field\"\nkind = \"sph\"\nmaterial = \"soil\"\njoin = true\n"
        "exclude = [\"charge\"]\nfill = {{ shape = \"box\", min = {}, max = {}, spacing = {:.9g} }}\n{}\n",
        fmt_point(zone.region.min[0], zone.region.min[1], zone.region.min[2]),
        fmt_point(zone.region.max[0], zone.region.max[1], zone.region.max[2]), zone.spacing,
        buried_detail::part_geostatic(s, "soil"));
    // The same particle viscosity as r-z (docs/buried-structure.md, "SPH viscosity").
    b += "[sph]\nviscosity_alpha = 0.2  # linear term (see docs/buried-structure.md, \"SPH viscosity\")\n"
         "viscosity_beta = 2.0   # quadratic term\n\n";
  }
  if (s.has_rebar && !s.free_field) write_rebar_3d(s, b);
  write_slide_interface(s, box_parts, b);
  b += "# Boundaries: the symmetry plane y = 0; the far faces; the ground surface z = 0 is free.\n";
  b += boundaries;
  fmt::format_to(out, "[[detonation]]\nposition = {}  # m, the charge centre\ntime = 0.0\n\n",
                 fmt_point(0.0, 0.0, -s.burst_depth));
  write_gauges(s, b);
  return b;
}

}  // namespace camouflet::buried_detail
