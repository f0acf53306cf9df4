#pragma once
// The Lagrangian elements of a model as structure-of-arrays, and the two
// element stages of the explicit cycle (architecture.md):
//   add_internal_forces  f_a -= V sigma b_a (+ hoop term) + hourglass resistance, at t_n
//   kinematics           V, rho = m/V at t_{n+1}; D, W at mid-step; artificial viscosity q
// One integration point per element (quad4 plane strain / axisymmetric, hex8).
// Node arrays are flat, n * D, owned by the solver; material state lives in
// each material's MaterialPoints, found through (material, point).
#include <cstdint>
#include <vector>

#include "core/sym_tensor.hpp"
#include "fem/element_colouring.hpp"
#include "materials/material_points.hpp"
#include "model/model.hpp"

namespace camouflet {

template <int D>
class ElementForceKernel;

struct ViscosityControl {
  double quadratic = 1.5;  // c_quadratic
  double linear = 0.06;    // c_linear
  // The compression q acts on: the strain rate along the element's
  // acceleration (Wilkins 1980), or the volumetric rate tr D; or no q but a
  // force on each closing edge (edge_viscosity.hpp).
  ViscosityForm form = ViscosityForm::volumetric;
  // The edge form's limiter (edge_viscosity.hpp, edge_limiter); it needs the elements'
  // edge_continuation.
  bool limiter = false;
};

// add_internal_forces assembles the nodal forces on several threads without
// write conflicts by colour blocks: blocks of colour_block_size() consecutive
// elements coloured so that no two blocks of a colour share a node
// (element_colouring.hpp), one colour after the other. Each node adds its
// elements' forces in the same order on any thread count (the same bits), and
// the blocks keep the element order's memory locality: as fast as per-thread
// buffers on one thread, faster on two (docs/performance.md, "Colouring against
// per-thread buffers"; bench/fem_assemblies.hpp keeps the other assemblies).

// Elements per colour block: 512 (64 packs of 8), fewer in small meshes so that there are at
// least 64 blocks to share among the threads; a multiple of 8. Depends on the mesh only, so
// that the sums do not depend on the thread count.
inline std::size_t colour_block_size(std::size_t elements) {
  const std::size_t block = elements / 64 / 8 * 8;
  return block < 8 ? 8 : (block > 512 ? 512 : block);
}

struct KinematicsResult {
  std::int64_t bad_element = -1;  // 0-based; first element with non-positive or non-finite volume
  double bad_volume = 0.0;
  // 2-D: first element (0-based) whose edges cross (a "bow-tie"): two or more of its corner
  // Jacobians negative while its area is still positive; -1 if none. A concave quad (one
  // negative corner) is not flagged: it still has a valid one-point integral.
  std::int64_t tangled_element = -1;
  int tangled_corners = 0;
  double viscous_work = 0.0;  // J, -sum q dV (or the edge forces' work) over this step
};

template <int D>
class FemElements {
 public:
  static constexpr int nodes = D == 2 ? 4 : 8;
  static constexpr int modes = D == 2 ? 1 : 4;

  FemElements() = default;
  // Geometry and connectivity only; material, point, mass and the state
  // arrays are filled by the solver. Throws InputError naming the first
  // inverted or degenerate element.
  FemElements(const FemMesh& mesh, GeometryMode mode, const std::vector<double>& coordinates);

  std::size_t size() const { return material.size(); }
  // The colour blocks of the force assembly (computed when first needed).
  const ElementColouring& colouring() {
    colour_if_needed();
    return colouring_;
  }
  bool axisymmetric() const { return axisymmetric_; }

  // f (n*D) += internal forces at the positions x (t_n), stresses `stress`
  // less q, and hourglass resistance from the velocities v (t_{n-1/2}), with
  // each element's own control when set_hourglass gave them one, else `hg`
  // for all. dt_previous advances the stiffness-form hourglass displacements.
  // The viscous-form hourglass forces alone are also added to f_hourglass
  // (n*D) when it is not null, so the solver can charge their work
  // time-centred. Returns the energy held by the stiffness form at t_n (J).
  double add_internal_forces(const double* x, const double* v, double* f, double* f_hourglass,
                             const HourglassControl& hg, double dt_previous);

  // Per-element hourglass control (a part's own, docs/case-format.md): one
  // entry per element; afterwards add_internal_forces ignores its `hg`.
  void set_hourglass(const std::vector<HourglassControl>& per_element);
  // Whether any element has the viscous form with a positive coefficient
  // (the solver then keeps the hourglass forces for the work integral).
  bool any_viscous_hourglass(const HourglassControl& hg) const;

  // From x (t_{n+1}) and v (t_{n+1/2}): new volume and density, strain rate
  // and spin at mid-step, q, characteristic length and speed; written into
  // the element arrays and the material batches.
  // v_previous: the velocities at t_(n-1/2) (n*D); v - v_previous, the
  // velocity change the step applied (constraints included), orients q
  // (ViscosityControl).
  KinematicsResult kinematics(const double* x, const double* v, const double* v_previous, double dt,
                              const ViscosityControl& viscosity, std::vector<MaterialPoints>& batches);

  // The largest node speed of each element from the velocities v (n*D): the
  // |v| of the first step's l/(c+|v|) vote, before any kinematics has run.
  void set_speeds(const double* v);

  // r-z only: the momentum in area-weighted form (Wilkins 1964; the default
  // is the volume form): each node's internal force is the planar
  // divergence of sigma over the area plus the hoop sources, times its ring
  // factor m_a / M_a (update_ring_factors), so the acceleration is that force
  // over the node's area mass M_a. Keeps a spherical flow spherical on rays
  // from a centre; conserves energy only to the mesh's truncation error
  // (docs/theory-fem.md, "Axisymmetric momentum").
  // Per element (the run's `axisymmetric_momentum` or a part's own): nonzero for the area form.
  // Nodes shared by elements of both forms take each element's force in its own form (the area
  // form's times the node's ring factor, so both are forces on the ring).
  void set_area_forms(std::vector<char> per_element);
  // Whether any element is in the area form.
  bool area_weighted_momentum() const { return area_weighted_; }
  bool area_form(std::size_t e) const { return area_form_.empty() ? area_weighted_ : area_form_[e] != 0; }
  // The ring factors m_a / M_a from positions x, before this step's forces
  // (boundary loads use them too); empty unless area-weighted.
  void update_ring_factors(const double* x);
  const std::vector<double>& ring_factors() const { return ring_factor_; }

  // Element volume (m^3; per unit depth in plane strain, the full ring in
  // axisymmetric mode) of one element at positions x.
  double volume_of(const double* x, std::size_t e) const;

  // --- element arrays (SoA), index e ---
  std::vector<std::int64_t> connectivity;      // e * nodes + a
  std::vector<int> material;                   // index into Model::materials (and the solver's batches)
  std::vector<std::size_t> point;              // index into that material's MaterialPoints
  std::vector<double> mass;                    // kg (plane strain: per metre of depth)
  std::vector<double> volume;                  // m^3, at the latest kinematics
  std::vector<SymTensor> stress;               // Pa, sigma = s - p I at the latest material update
  std::vector<double> viscosity;               // Pa, artificial bulk viscosity q
  // N, e * edges * D: the edge viscosity's force on each edge's first node (its second takes the
  // opposite) from the latest kinematics; empty unless [run.viscosity] form = "edge".
  std::vector<double> edge_force;
  // The edge viscosity's limiter: the node beyond each end of each edge (edge_continuation.hpp),
  // (e * edges + k) * 2 + end; empty unless [run.viscosity] limiter with the edge form.
  std::vector<std::int64_t> edge_continuation;
  // Subzonal pressures (subzonal_pressure.hpp), e * nodes each; empty unless some element's
  // part has subzonal > 0 ([run.hourglass] or its own): each corner subzone's share of the
  // element's mass, its pressure difference dp_s (Pa) and volume V_s (m^3) at the latest
  // kinematics (dp_s stays 0 in an element of coefficient 0).
  std::vector<double> subzone_fraction, subzone_pressure, subzone_volume;
  std::vector<double> subzonal_coefficient;  // per element: kappa in dp_s = kappa c^2 (rho_s - rho_z)
  // Subzonal pressures with coefficient kappa[e] from the positions x at set-up (each subzone
  // keeps the mass of its initial volume).
  void set_subzonal_pressure(const std::vector<double>& kappa, const double* x);
  // Each element's viscosity form where the parts differ (set_viscosity_forms); empty: the
  // form of the ViscosityControl passed to kinematics() for all.
  std::vector<ViscosityForm> viscosity_form;
  bool edge_form_anywhere = false;  // some element of viscosity_form has the edge form
  void set_viscosity_forms(std::vector<ViscosityForm> per_element);
  std::vector<double> density;                 // kg/m^3
  std::vector<double> wave_speed;              // m/s, sqrt(c^2 + 4G/3rho) of the latest update
  std::vector<double> stable_wave_speed;       // m/s, the same with the stable sound speed (the dt vote's)
  std::vector<double> length;                  // m, characteristic length for dt and q
  std::vector<double> speed;                   // m/s, largest node speed of the element
  std::vector<double> hourglass_displacement;  // m, e * modes * D: stiffness-form generalised modes
  std::vector<char> eroded;                    // 1: eroded (no forces, no kinematics)
  // Own hourglass control (set_hourglass; empty: the `hg` of add_internal_forces for all).
  std::vector<double> hourglass_coefficient;  // FB 1981 kappa; 0 = no control
  std::vector<char> hourglass_stiffness;      // 1: stiffness form, 0: viscous
  bool stiffness_anywhere = false;            // some element has the stiffness form (set_hourglass)

 private:
  bool axisymmetric_ = false;
  std::size_t node_count_ = 0;
  friend class ElementForceKernel<D>;  // reads the geometry mode and the ring factors
  void colour_if_needed();
  // The colour blocks, and the stiffness-form energy of each block (added in their order after
  // the loop, so that it too does not depend on the thread count).
  ElementColouring colouring_;
  std::vector<double> pack_stored_;
  bool area_weighted_ = false;
  std::vector<char> area_form_;      // per element where the forms differ (set_area_forms)
  std::vector<double> ring_factor_;  // r-z area-weighted momentum: m_a / M_a per node
  std::vector<double> area_mass_;    // scratch of update_ring_factors: sum_e m_e / (N 2 pi r_bar_e) per node
};

extern template class FemElements<2>;
extern template class FemElements<3>;

}  // namespace camouflet
