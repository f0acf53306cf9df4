#pragma once
#include <algorithm>
// Buried-structure case generator: from a handful of physical
// parameters (charge, depth of burst, standoff, box, soil, domain, mesh sizes)
// it writes a complete 2-D axisymmetric case file of the paper's example
// (Wang, Lu, Hao, Chong 2005, §5.1 and Fig. 6): axis through the charge,
// free ground surface z = 0, soil, charge and concrete box as structured
// blocks of one tensor-product grid (so every block shares its nodes with its
// neighbours: the fused soil-structure interface of the paper), graded fine
// near the charge and in the structure, coarse far away; transmitting far
// edges; gauges of the paper's Figs. 8a and 10. With `three_d` it writes a 3-D
// half model instead (buried_structure_3d.cpp). docs/buried-structure.md.
#include <map>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace camouflet {

struct BuriedStructureSpec {
  std::string title = "Buried RC box under a side burst (Wang et al. 2005, section 5)";
  // Geometry: false = 2-D axisymmetric (r, z), the paper's model; true = 3-D
  // (x towards the box, y along its front wall, z up; the charge on the z
  // axis, symmetry plane y = 0 through the charge and the box's mid-width):
  // buried_structure_3d.cpp. In 3-D "r" below reads "x".
  // 3-D only: the box's outer extent along its front wall (y, whole box), and
  // the distance from the charge axis to the far faces behind (x = -side) and
  // beside (y = side) the charge, 0 = domain_radius.
  bool three_d = false;
  double box_width = 0.0;    // m
  double domain_side = 0.0;  // m
  // Charge: a sphere of `charge_mass` kg of `explosive` (a material preset),
  // centre `burst_depth` m below the ground surface, on the axis.
  double charge_mass = 100.0;  // kg
  std::string explosive = "tnt_wang2005";
  double explosive_density = 1630.0;  // kg/m^3 (sizes the charge)
  double burst_depth = 0.5;           // m
  // SPH charge: particles along its radius (r-z: the cell-centred lattice of
  // spacing a'/N, a' the region radius that makes the lattice hold the asked
  // mass; 3-D: along the half side of the equal-volume cube). The same for
  // every mass, so a sweep over mass compares sources of one resolution.
  int charge_particles_across = 8;
  // Box: its front (outer) face `standoff` m from the axis.
  double standoff = 6.0;        // m
  double box_length = 4.0;      // m, radial
  double box_height = 1.0;      // m
  double wall_thickness = 0.1;  // m
  double top_depth = 0.0;       // m, depth of the roof's top face
  std::string concrete = "concrete_35mpa_wang2005";
  // The soil-structure interface: false = fused (the box's nodes shared with the soil, the paper's
  // model, section 4.13: a rough interface); true = a slide surface ([[slide_surfaces]],
  // coupling/slide_surface.hpp) that lets the soil separate, recontact and slide on the box with
  // Coulomb friction `interface_friction`.
  bool slide_interface = false;
  double interface_friction = 0.0;
  std::string soil = "sandy_clay_wang2005";
  double soil_wave_speed = 1400.0;  // m/s, loading wave speed for the reflection estimate (Table 1)
  // Domain: r in [0, domain_radius], z in [-domain_depth, 0].
  double domain_radius = 16.0;  // m
  double domain_depth = 10.0;   // m
  bool transmitting = true;     // far edges transmitting (else fixed)
  // Mesh sizes (m): near the charge (within `near_radius` of its centre), in
  // and around the structure, in the soil between them, and at the far edges.
  double near_radius = 1.0;  // m
  double size_near = 0.05;
  double size_structure = 0.05;
  double size_soil = 0.25;
  double size_far = 1.0;
  // SPH zone (Wang et al. 2005, Fig. 6): the soil in r <= sph_radius, from the
  // ground down to sph_depth (0: burst_depth + sph_radius), is SPH particles of
  // spacing mesh.near joined to the FEM soil around, and the charge is a
  // sphere (an r-z disc) of SPH explosive particles. 0: no SPH zone (charge
  // and near field as FEM elements). A crater is wide and shallow: the zone
  // should hold it (the paper's point of the SPH zone, section 5.2), which
  // sph_depth allows without a zone as deep as it is wide.
  double sph_radius = 0.0;  // m
  double sph_depth = 0.0;   // m below the ground; 0 = burst_depth + sph_radius
  // Hourglass control of the soil (and an FEM charge) and of the box: form
  // "stiffness" or "viscous", coefficient 0 = `hourglass_coefficient`. The
  // soil's is the case's [run.hourglass]; the box's parts carry their own
  // when it differs (docs/buried-structure.md, "Hourglass form in the structure").
  double hourglass_coefficient = 0.1;
  std::string soil_hourglass = "stiffness", structure_hourglass = "stiffness";
  double soil_hourglass_coefficient = 0.0, structure_hourglass_coefficient = 0.0;
  // Geometric-strain erosion of the FEM soil (`soil.erosion = { geometric_strain = ... }`; 0: none),
  // written on [materials.soil]: elements thrown clear with the crater's ejecta and stretched past
  // it stop setting the time step (docs/buried-structure.md, "coarse3d").
  double soil_erosion_strain = 0.0;
  // [structure] kind = "free_field": the box's place and its interior are soil, as the ground
  // there was before the box was built; no box, no bars (a [rebar] block is ignored, and the
  // header says so). The structure targets and the members then measure the free field at the
  // box's position: the reference that the box's motion is weighed against (docs/buried-structure.md).
  bool free_field = false;
  double soil_hourglass_kappa() const {
    return soil_hourglass_coefficient > 0.0 ? soil_hourglass_coefficient : hourglass_coefficient;
  }
  double structure_hourglass_kappa() const {
    return structure_hourglass_coefficient > 0.0 ? structure_hourglass_coefficient : hourglass_coefficient;
  }
  // r-z with an SPH zone: the case gets the axis treatment (buried_case_tables.cpp,
  // write_run_and_materials; docs/buried-structure.md, "The axis without soil erosion").
  bool axis_treatment() const { return !three_d && sph_radius > 0.0; }
  // The depth of the SPH zone's bottom face below the ground (m).
  double sph_bottom() const { return sph_depth > 0.0 ? sph_depth : burst_depth + sph_radius; }
  // Extent of the uniform near-field mesh around the charge centre (m), sideways and below: it
  // covers the SPH zone and two cells beyond, so the elements beside the hole have the particles'
  // size (join spacing ratio 1).
  double near_extent() const {
    return sph_radius > 0.0 ? std::max(near_radius, sph_radius + 2.0 * size_near) : near_radius;
  }
  double near_extent_below() const {
    return sph_radius > 0.0 ? std::max(near_radius, sph_bottom() - burst_depth + 2.0 * size_near)
                            : near_radius;
  }
  // Reinforcement: an inner and an outer mat in every wall, roof and floor, as
  // embedded bars (fem/embedded_bars.hpp) at `rebar_cover` (m, clear distance
  // from the face to the bar line) with steel area per metre of circumference
  // rebar_ratio x wall_thickness per mat.
  bool has_rebar = false;
  double rebar_cover = 0.0;
  double rebar_ratio = 0.0;
  std::string steel = "steel_1006_wang2005";
  // Run control: the [run] and [output] keys of the generated case.
  struct Run {
    double end_time = 0.07;         // s
    double field_interval = 0.005;  // s
    double gauge_interval = 2e-5;   // s
    double cfl = 0.6;
    // Gravity (m/s^2, 0: none): with it every FEM soil part starts in its geostatic state
    // (Jaky's K0) and a dynamic relaxation of period `relaxation_period` (s) settles the box in
    // it before t = 0 (docs/theory/gravity.md).
    double gravity = 0.0;
    double relaxation_period = 0.0;
  };
  Run run;
  int gauge_count = 10;  // gauges per soil group (A and B)

  // Where each key was read (for errors naming it); keys absent fall back to `source`.
  std::string source = "parameters";
  std::map<std::string, SourceLocation> where;
  SourceLocation location(const std::string& key) const;
};

// Derived geometry, also printed by `camouflet generate`.
struct BuriedStructureLayout {
  double charge_radius = 0.0;     // m, sphere of the given mass
  double charge_half_size = 0.0;  // m, half side of the equal-volume r-z square (cylinder h = 2 a; 3-D: cube)
  std::vector<double> r_lines;    // block boundaries along r (3-D: x) (m)
  std::vector<double> z_lines;    // block boundaries along z (m, increasing: -depth .. 0)
  std::vector<double> y_lines;    // 3-D only: block boundaries along y (m, 0 .. domain side)
  std::size_t element_count = 0;
  std::size_t block_count = 0;
  double reflection_time = 0.0;  // s, earliest arrival at the front wall of a wave reflected at a far edge
  // SPH zone (sph_radius > 0): particle spacings (m) and counts, the modelled charge mass (kg).
  // charge_fill_radius (r-z): the radius of the charge's particle region (m), within 1.8 % of
  // charge_radius for 4 or more particles across, chosen so the particles' volumes add up to the charge's.
  double zone_spacing = 0.0, charge_spacing = 0.0, charge_fill_radius = 0.0;
  std::size_t zone_particles = 0, charge_particles = 0;
  double charge_model_mass = 0.0;
};

// Checks the spec (InputError naming the key) and lays out the grid.
BuriedStructureLayout layout_buried_structure(const BuriedStructureSpec& spec);

// The complete case file (TOML) for `spec`; `regenerate` is the command line
// printed in its header.
std::string buried_structure_case(const BuriedStructureSpec& spec, const std::string& regenerate);

}  // namespace camouflet
