#pragma once
// The model a case file describes, in plain data: what the case reader builds
// (case/), what the solver runs (solver/) and what `camouflet check` validates.
// Dimension is a run-time value here; the solver instantiates Solver<2> or
// Solver<3> from it. Units are SI throughout.
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/parameters.hpp"
#include "materials/material.hpp"
#include "model/reinforcement.hpp"
#include "model/sph_options.hpp"

namespace camouflet {

enum class GeometryMode { plane_strain, axisymmetric, three_d };
const char* to_string(GeometryMode mode);
inline int dimension_of(GeometryMode mode) { return mode == GeometryMode::three_d ? 3 : 2; }

enum class HourglassForm { viscous, stiffness, none };
// The FEM artificial viscosity ([run.viscosity] form).
enum class ViscosityForm { acceleration, volumetric, edge };

// Flanagan-Belytschko hourglass control of the one-point elements: the run's
// default ([run.hourglass]) or a part's own (`hourglass` of a [[parts]] entry).
struct HourglassControl {
  HourglassForm form = HourglassForm::viscous;
  double coefficient = 0.1;  // dimensionless (FB 1981 kappa)
};

struct RunControl {
  double end_time = 0.0;     // s
  double cfl = 0.6;          // time step = cfl * min(length / (c + |v|))
  double initial_dt = 0.0;   // s; 0 = from the CFL condition
  double max_dt = std::numeric_limits<double>::infinity();  // s
  double min_dt = 0.0;       // s; a step below it stops the run (time step collapse)
  std::int64_t max_cycles = std::numeric_limits<std::int64_t>::max();
  double dt_growth = 1.1;    // largest ratio dt(n+1)/dt(n)
  GeometryMode mode = GeometryMode::plane_strain;
  // Artificial bulk viscosity q = rho l (c_quadratic^2 l |tr D| - c_linear c) tr D, compression only.
  double viscosity_quadratic = 1.5;
  double viscosity_linear = 0.06;
  // q on the strain rate along the acceleration (Wilkins 1980, the default: a smooth
  // convergence takes no q), on tr D (the classic form), or a force on each closing edge
  // (Caramana, Shashkov and Whalen 1998): docs/theory-fem.md.
  ViscosityForm viscosity_form = ViscosityForm::acceleration;
  // The edge form's limiter (CSW 1998, fem/edge_viscosity.hpp): no edge force in a linear
  // velocity field, the full force across a jump.
  bool viscosity_limiter = false;
  // r-z momentum in area-weighted form (Wilkins 1964) instead of the volume form
  // (the default): keeps converging spherical flow spherical; docs/theory-fem.md.
  bool area_weighted_momentum = false;
  HourglassForm hourglass = HourglassForm::viscous;
  double hourglass_coefficient = 0.1;
  // Subzonal pressures (Caramana and Shashkov 1998) with this coefficient on every FEM element,
  // besides the hourglass form; 0 = none (fem/subzonal_pressure.hpp, docs/theory-fem.md).
  double subzonal_pressure = 0.0;
  // Gravitational acceleration (m/s^2; axisymmetric: (r, z), only along z): a body force m g on
  // every node and particle, its work booked in the energy balance (docs/theory/gravity.md).
  std::array<double, 3> gravity{};
  bool has_gravity() const { return gravity[0] != 0.0 || gravity[1] != 0.0 || gravity[2] != 0.0; }
  // Dynamic relaxation before t = 0 ([run.dynamic_relaxation]; docs/theory/gravity.md): the
  // model is brought to rest under gravity and its t = 0 loads with a damping at the critical
  // rate of its fundamental period, then the transient starts from that state at rest.
  struct DynamicRelaxation {
    double period = 0.0;      // s, the model's fundamental period (an estimate); damping rate 4 pi / period
    double tolerance = 1e-4;  // rest: kinetic energy at most this fraction of its peak for a whole period
    double max_time = 0.0;    // s of relaxation after which an unsettled model stops the run
    SourceLocation where;
  };
  std::optional<DynamicRelaxation> relaxation;
  double energy_error_limit = 0.05;  // relative; warn past half, stop when exceeded (solver/energy_guard.hpp)
  // Domain box (m; axisymmetric r, z): a node or particle leaving it stops the run. Unbounded by default.
  std::array<double, 3> domain_min{-std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity()};
  std::array<double, 3> domain_max{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                                   std::numeric_limits<double>::infinity()};
  SourceLocation where;
};

struct OutputControl {
  double field_interval = 0.0;   // s between field snapshots; 0 = first and last only
  double gauge_interval = 0.0;   // s between gauge rows; 0 = every cycle
  double log_interval_s = 5.0;   // wall seconds between plain log lines when not on a terminal
};

// Checkpoints (the case's [checkpoint] block; docs/reliability.md).
struct CheckpointControl {
  std::int64_t interval_cycles = 0;  // cycles between checkpoints; 0 = none by cycles
  double interval_wall_s = 0.0;      // wall seconds between checkpoints; 0 = none by wall time
  int keep = 2;                      // checkpoints kept (the oldest are removed)
  bool enabled() const { return interval_cycles > 0 || interval_wall_s > 0.0; }
};

// A FEM mesh: quad4 in 2-D, hex8 in 3-D. Node and element ids are 0-based
// indices here; user-facing ids (messages, output) are 1-based.
struct FemMesh {
  int dimension = 2;
  int nodes_per_element = 4;
  std::vector<double> coordinates;           // n_nodes * dimension, m
  std::vector<std::int64_t> connectivity;    // n_elements * nodes_per_element, counter-clockwise (2-D)
  std::vector<int> element_part;             // index into Model::parts
  std::map<std::string, std::vector<std::int64_t>> node_sets;  // named boundaries / groups of nodes
  // Named sets of boundary faces (2 nodes in 2-D, 4 in 3-D), outward normal by node order.
  std::map<std::string, std::vector<std::int64_t>> face_sets;

  std::size_t node_count() const { return coordinates.size() / static_cast<std::size_t>(dimension); }
  std::size_t element_count() const {
    return connectivity.size() / static_cast<std::size_t>(nodes_per_element);
  }
};

// SPH particles (filled by the case reader's particle fills, mesh/particle_fill.hpp).
struct ParticleSet {
  std::vector<double> coordinates;        // n * dimension, m
  std::vector<double> volume;             // m^3 (axisymmetric: ring volume 2 pi r A)
  std::vector<double> spacing;            // m, initial particle spacing
  std::vector<int> particle_part;         // index into Model::parts
  std::size_t count() const { return volume.size(); }
};

enum class PartKind { fem, sph };

// The geostatic initial state of a soil part (a part's `geostatic` key; docs/theory/gravity.md):
// vertical stress from the overburden of the part itself below `surface` plus `surcharge`,
// horizontal stress k0 times the vertical one. "Vertical" is the direction of [run] gravity.
struct GeostaticState {
  double surface = 0.0;           // m, elevation of the part's top along -gravity
  std::optional<double> k0;       // lateral earth-pressure coefficient; none: Jaky, 1 - sin(phi)
  double surcharge = 0.0;         // Pa, vertical stress at `surface` (the weight of the layers above)
  SourceLocation where;
};

struct Part {
  std::string name;
  PartKind kind = PartKind::fem;
  int material = -1;                        // index into Model::materials
  std::array<double, 3> initial_velocity{};  // m/s
  SourceLocation where;
  // The part's own hourglass control (FEM parts); none: the run's [run.hourglass].
  std::optional<HourglassControl> hourglass;
  std::optional<GeostaticState> geostatic;  // FEM parts: initial stress from the overburden
  // The part's own subzonal-pressure coefficient (`hourglass.subzonal` of a FEM part) and FEM
  // viscosity form (`viscosity = { form = ... }`); none: the run's. A buried structure's soil
  // takes them where the charge's flow tangles its elements, its concrete keeps the point q
  // (docs/buried-structure.md, "The axis without soil erosion").
  std::optional<double> subzonal;
  std::optional<ViscosityForm> viscosity_form;
  // The part's own r-z momentum form (`axisymmetric_momentum`: true for "area"); none: the run's.
  // A buried structure's concrete keeps the volume form where its soil takes the area form: the
  // area form's forces are not the gradient of an energy, and under a standing load a structure
  // in it does not come to rest (docs/theory-fem.md, "Axisymmetric momentum").
  std::optional<bool> area_weighted_momentum;
};

struct NamedMaterial {
  std::string name;
  std::shared_ptr<const Material> material;
  SourceLocation where;
};

// A piecewise-linear function of time (load or velocity histories).
struct TimeHistory {
  std::vector<double> time;   // s, increasing
  std::vector<double> value;  // scale factor or value
  double at(double t) const;  // linear interpolation; constant beyond the ends
};

enum class BoundaryKind {
  fixed,        // all velocity components zero
  velocity,     // prescribed velocity components (others free)
  symmetry,     // zero normal velocity on a plane
  axis,         // axis of revolution r = 0 (axisymmetric): zero radial velocity
  pressure,     // pressure load on a face set (compression positive, acts against the outward normal)
  transmitting  // non-reflecting viscous boundary on a face set (boundary/transmitting_boundary.hpp)
};

struct BoundaryCondition {
  BoundaryKind kind = BoundaryKind::fixed;
  std::string set;                        // node set (fixed/velocity/symmetry/axis) or face set
  std::array<bool, 3> components{};       // velocity: which components are prescribed
  std::array<double, 3> value{};          // velocity (m/s) or, for pressure, the magnitude (Pa) in value[0]
  std::array<double, 3> normal{};         // symmetry: plane normal
  std::optional<TimeHistory> history;     // scale factor over time (1 when absent)
  SourceLocation where;
};

struct GaugePoint {
  std::string name;
  std::array<double, 3> position{};  // m, initial (Lagrangian: it moves with the material)
  SourceLocation where;
  // Among particles: false = follow the nearest particle (Lagrangian); true =
  // stay at `position` and interpolate the particles there with the kernel
  // (Shepard-normalised; output/gauges.hpp). Set by the group's `particles` key.
  bool interpolate = false;
  // A member average instead of a point (group key `members`): the mass-weighted mean over the
  // elements of material `member_material` (any when -1) whose initial centre lies in the box
  // [region_min, region_max] (output/gauges.hpp).
  bool member = false;
  int member_material = -1;
  std::array<double, 3> region_min{}, region_max{};  // m
};

struct GaugeGroup {
  std::string name;
  std::vector<GaugePoint> points;
  SourceLocation where;
};

// A joined SPH-FEM interface (Wang et al. 2005 section 3.3):
// the particles of `sph_part` and the elements of `fem_parts` meet along the
// boundary of the hole the SPH zone was cut from (coupling/joined_zone.hpp)
// and interact as one continuum (coupling/sph_fem_join.hpp).
struct Join {
  int sph_part = -1;           // index into Model::parts
  std::vector<int> fem_parts;  // indices into Model::parts
  SourceLocation where;
};

// A sliding interface: the particles of `sph_part` against the
// FEM faces of `face_set`, penalty contact with Coulomb friction
// (coupling/sliding_contact.hpp).
struct Contact {
  int sph_part = -1;             // index into Model::parts
  std::string face_set;          // FemMesh::face_sets key
  double friction = 0.0;         // Coulomb coefficient
  double penalty_scale = 0.1;    // stiffness k = penalty_scale m / dt^2 per particle
  SourceLocation where;
};

// A slide surface between FEM parts ([[slide_surfaces]]; coupling/slide_surface.hpp): the parts
// of side A are detached from the rest of the mesh along the faces they share with it (the nodes
// there doubled, mesh/detach_parts.hpp) and the two sides meet through a symmetric penalty contact
// with Coulomb friction, separation and recontact.
struct SlideSurface {
  std::vector<int> parts;      // index into Model::parts: side A; side B is every other FEM part
  double friction = 0.0;       // Coulomb coefficient
  double penalty_scale = 0.3;  // stiffness k = penalty_scale m_eff / dt^2 per node-face pair
  // The interface as detached: faces (2 or 4 nodes, outward from their element) of side A and of
  // side B, and the element each face bounds (0-based).
  std::vector<std::int64_t> faces_a, faces_b, elements_a, elements_b;
  SourceLocation where;
};

struct Model {
  std::string case_file;  // path as given
  std::string title;
  RunControl run;
  OutputControl output;
  CheckpointControl checkpoint;
  std::vector<NamedMaterial> materials;
  std::vector<Part> parts;
  FemMesh mesh;
  ParticleSet particles;
  sph::SphOptions sph;  // numerical SPH settings (the case's [sph] block)
  std::vector<BoundaryCondition> boundaries;
  std::vector<Join> joins;        // SPH-FEM joins (coupling/)
  std::vector<Contact> contacts;  // SPH-FEM sliding interfaces (coupling/)
  std::vector<SlideSurface> slide_surfaces;  // FEM-FEM sliding interfaces (coupling/)
  std::vector<GaugeGroup> gauges;
  std::vector<DetonationPoint> detonations;
  std::vector<SourceLocation> detonation_where;  // same order as detonations
  std::vector<BarSet> bars;                      // embedded reinforcement bars
  // Erosion of each material, by index into `materials`; a
  // material beyond the end of this list does not erode.
  std::vector<ErosionCriteria> erosion;
  ErosionCriteria erosion_of(std::size_t material) const {
    return material < erosion.size() ? erosion[material] : ErosionCriteria{};
  }

  int dimension() const { return dimension_of(run.mode); }
  // The hourglass control of the elements of part `part`: its own, else the run's.
  HourglassControl hourglass_of(std::size_t part) const {
    const auto& own = parts[part].hourglass;
    return own ? *own : HourglassControl{run.hourglass, run.hourglass_coefficient};
  }
  double subzonal_of(std::size_t part) const { return parts[part].subzonal.value_or(run.subzonal_pressure); }
  bool area_weighted_momentum_of(std::size_t part) const {
    return parts[part].area_weighted_momentum.value_or(run.area_weighted_momentum);
  }
  ViscosityForm viscosity_form_of(std::size_t part) const {
    return parts[part].viscosity_form.value_or(run.viscosity_form);
  }
};

}  // namespace camouflet
