#pragma once
// Transmitting (non-reflecting) boundaries on FEM face sets: the viscous
// dashpots of Lysmer & Kuhlemeyer (1969), J. Eng. Mech. Div. ASCE 95(EM4),
// 859-877. On a boundary face with outward unit normal n the traction is
//   t = -rho c_p (v . n) n - rho c_s (v - (v . n) n),
// with rho, c_p = sqrt(c^2 + 4G/(3 rho)) (MaterialPoints::wave_speed) and
// c_s = sqrt(G / rho) of the element behind the face at its current state.
// The traction is lumped to the face nodes with the face-area weights of the
// pressure loads (axisymmetric: the ring weights 2 pi (2 r_a + r_b) / 6 L,
// which sum to 2 pi r_mean L), each node using its own velocity v(n-1/2).
// The explicit dashpot is stable for rho c A dt / m < 2, i.e. for a CFL number
// below 1 on the boundary element. The dissipated work enters the energy
// balance as boundary work, centred like the load work (boundary_conditions.hpp).
// docs/theory/coupling.md gives the limits (oblique incidence).
// Under gravity the boundary also carries the static load of the soil it
// replaces: a constant nodal force, fixed at t = 0, equal to the reaction that
// holds each boundary node in the initial (geostatic) state; the dashpots act on
// the motion only (docs/theory/gravity.md).
#include <array>
#include <cstdint>
#include <vector>

#include "core/state_visitor.hpp"
#include "core/vec.hpp"
#include "fem/fem_elements.hpp"
#include "materials/material_points.hpp"
#include "model/model.hpp"
#include "model/node_sharing.hpp"

namespace camouflet {

template <int D>
class TransmittingBoundary {
 public:
  TransmittingBoundary() = default;
  // Resolves every `transmitting` boundary of the model onto faces of the
  // mesh and the element behind each face. Throws InputError (at the
  // condition's `where`) for an unknown face set or a face that is not the
  // face of one element.
  TransmittingBoundary(const Model& model, const FemElements<D>& elements);

  // On one of several MPI ranks (model/node_sharing.hpp; before the first stage): a node on a
  // cut takes the damping of every rank's faces that hold it (their dashpot matrices added up over
  // the ranks), and its dashpot work and static hold's work count at its owner. Every rank then
  // takes part in each stage whenever the model has a transmitting boundary, faces here or not.
  void share_nodes(const NodeSharing* sharing, std::size_t node_count);

  // No transmitting boundary to act (on ranks: none anywhere in the model).
  bool empty() const { return !active_; }
  std::size_t face_count() const { return faces_.size(); }

  // After the velocity update: v (n*D) holds v_free, v_old = v(n-1/2); x the
  // geometry at t_n. Replaces v by v(n+1/2) with the centred dashpot forces of
  // the elements' latest impedance (their work: work(), after the constraints).
  void damp(const double* x, const double* v_old, double* v, const double* node_mass,
              const FemElements<D>& elements, const std::vector<MaterialPoints>& batches, double dt);
  // The work of the last damp's dashpot forces over dt against the velocities the nodes move with
  // after every constraint has acted, (v_old + v) / 2 (J, <= 0 where no constraint interferes).
  double work(const double* v_old, const double* v, double dt) const;

  // During a dynamic relaxation (solver/dynamic_relaxation.cpp): the boundary nodes held at
  // rest in place of the dashpots, as the soil beyond them is. A boundary that carried its t = 0
  // static load while the structure settled would let the whole model drift at the dashpots'
  // terminal speed wherever the structure's weight differs from the soil's it replaces.
  void hold_still(double* v);
  // At t = 0: `unbalanced` (n*D, N) is each node's internal force plus its weight in the initial
  // state; the boundary nodes keep -unbalanced as their static force from then on.
  void hold_initial_state(const double* unbalanced);
  // Adds the static forces to f (n*D) at t_n and returns their work from t_(n-1) to t_n,
  // f . v(n-1/2) dt(n-1/2) (J; constant forces: exact).
  double add_static_forces(const double* v_old, double dt_old, double* f) const;
  // The static forces for checkpoints: after a dynamic relaxation they are the relaxed state's,
  // which a restarted run cannot rebuild from the mesh.
  void visit_state(StateVisitor& v);

 private:
  struct Face {
    std::array<std::int64_t, D == 2 ? 2 : 4> nodes;
    std::size_t element;
  };
  std::vector<Face> faces_;
  std::vector<std::int64_t> nodes_;                 // boundary nodes, sorted
  std::vector<std::array<double, D * D>> damping_;  // N s/m, per entry of nodes_
  std::vector<Vec<D>> static_force_;                // N, per entry of nodes_ (empty: none)
  std::vector<Vec<D>> force_;                       // N, the last damp's dashpot forces, per entry of nodes_
  void collect_nodes();  // nodes_ from the faces (on ranks, with the shared nodes other ranks' faces hold)
  bool collected_ = false;
  bool active_ = false;  // the model has transmitting faces (on ranks: on some rank)
  bool axisymmetric_ = false;
  const NodeSharing* sharing_ = nullptr;
  std::vector<double> shared_damping_;  // on ranks: per local node, D * D (zero but at nodes_ in damp)
};

extern template class TransmittingBoundary<2>;
extern template class TransmittingBoundary<3>;

}  // namespace camouflet
