#pragma once
// Boundary conditions of Model::boundaries, resolved onto nodes once:
// velocity constraints (fixed, prescribed velocity with optional history,
// symmetry plane, axis of revolution) applied to v(n+1/2) each cycle, and
// pressure loads on face sets added to the nodal forces. Both report the
// work they do, for the energy balance.
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/state_visitor.hpp"
#include "model/model.hpp"

namespace camouflet {

template <int D>
class BoundaryConditions {
 public:
  BoundaryConditions() = default;
  // Throws InputError (at the condition's `where`) for an unknown set, a
  // zero symmetry normal, an axis outside axisymmetric mode, or a kind not
  // available yet.
  explicit BoundaryConditions(const Model& model);

  // f (n*D) += pressure loads at time t on the current geometry x.
  // ring_factor: r-z in area-weighted momentum (FemElements::ring_factors),
  // each node's share of a face's planar force times its factor, as the
  // element forces it meets; nullptr: the volume form's consistent ring weights.
  void add_loads(const double* x, double time, double* f, const double* ring_factor = nullptr);
  // Work of the loads from t_(n-1) to t_n (J): the trapezoid of the load
  // forces of the last two add_loads against v(n-1/2) = v_old over dt_old,
  // the centring of the internal energy (solver.cpp, account_energy).
  double load_work(const double* v_old, double dt_old) const;

  // Imposes the constraints on v (n*D) for the half step centred on `time`;
  // the reaction force is m (v_constrained - v_free) / dt_mean. Returns the
  // work of the reactions from t_(n-1) to t_n, centred like load_work (J), over the nodes
  // `owned` flags (every node when null: on ranks, a shared node's reaction counts once).
  double constrain(double* v, const double* v_old, const double* node_mass, double time, double dt_old,
                   double dt_mean, const char* owned = nullptr);

  // The constraints alone (no work): used for the initial velocities.
  void constrain(double* v, double time) const;

  // The forces of earlier cycles kept for the boundary work (checkpoints; boundary_state.cpp).
  void visit_state(StateVisitor& visitor);

 private:
  struct Component {
    std::int64_t node;
    int component;
    double value;      // m/s
    int history = -1;  // index into histories_, scale factor
  };
  struct Plane {
    std::int64_t node;
    std::array<double, D> normal;  // unit
  };
  struct Load {
    std::vector<std::int64_t> faces;  // nodes per face: 2 (2-D) or 4 (3-D)
    double pressure = 0.0;            // Pa
    int history = -1;
  };
  struct LoadForce {
    std::int64_t node;
    std::array<double, D> force;  // N
  };
  double scale(int history, double time) const;
  void orthogonalise_planes();

  std::vector<Component> components_;
  std::vector<Plane> planes_;
  std::vector<Load> loads_;
  std::vector<TimeHistory> histories_;
  std::vector<LoadForce> load_forces_;           // N, of the latest add_loads (t_n)
  std::vector<LoadForce> load_forces_previous_;  // N, of the one before (t_(n-1))
  std::vector<double> reaction_previous_;        // N, per component, then per plane and direction
  bool axisymmetric_ = false;
};

extern template class BoundaryConditions<2>;
extern template class BoundaryConditions<3>;

}  // namespace camouflet
