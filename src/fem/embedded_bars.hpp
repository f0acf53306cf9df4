#pragma once
// Embedded reinforcement bars (the LS-DYNA "beam in solid" / constrained-bar
// idea): 2-node truss segments whose end points are fixed at t = 0 in
// host elements by their isoparametric coordinates. A bar node has no degrees
// of freedom of its own: its position and velocity are interpolated from the
// host nodes, and its mass and force are spread back to them with the same
// shape functions, so momentum is conserved and the work the bar force does
// on the host is exactly the bar's internal power.
//
// Each segment is one material point in uniaxial stress along the bar: the
// ordinary Material::update runs on a strain-rate tensor diag(d, d_l, d_l) in
// the bar's own frame, with the lateral rate d_l found by a secant iteration
// so that the lateral stress vanishes. docs/theory/reinforcement.md, section 2.
#include "core/state_visitor.hpp"
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "materials/material_points.hpp"
#include "model/bar_hosts.hpp"
#include "model/model.hpp"

namespace camouflet {

template <int D>
class EmbeddedBars {
 public:
  static constexpr int host_nodes = D == 2 ? 4 : 8;

  EmbeddedBars() = default;
  // Locates every bar node in an element of its host part in the initial
  // coordinates x0 (model/bar_hosts.hpp). Throws InputError (naming the bar set) for a node outside
  // its host part, a degenerate segment or a hoop bar outside axisymmetric mode.
  EmbeddedBars(const Model& model, const std::vector<double>& x0);
  // One rank's share of the bars in a run across ranks (docs/parallel.md), from the bar nodes
  // located in the whole mesh: with `hosted_here` (per bar node: this rank's elements host it) the
  // rank steps the segments whose first node it hosts and counts the mass of the bar nodes it
  // hosts; host nodes are renumbered by `global_nodes` (this rank's local node -> the whole mesh's,
  // ascending), which must hold every host node of those segments. Without it: every bar, the
  // whole mesh's numbering.
  EmbeddedBars(const Model& model, const BarHosts& hosts, const std::vector<char>* hosted_here,
               std::span<const std::int64_t> global_nodes);

  // Nothing held here: no segment stepped and no bar node's mass counted.
  bool empty() const { return node_mass_.empty(); }
  std::size_t segment_count() const { return segment_set_.size(); }  // stepped here
  std::size_t whole_segment_count() const { return total_segments_; }  // of the whole model
  // Segment s (stepped here) in the whole model's segments (set after set), and within its set.
  std::size_t whole_segment(std::size_t s) const { return segment_whole_[s]; }
  std::size_t segment_in_set(std::size_t s) const { return segment_in_set_[s]; }

  // node_mass (per host node) += N_a m_b for every bar node b.
  void add_masses(std::vector<double>& node_mass) const;
  // Bar forces at t_n (from the stresses of the last update) onto the host nodes.
  void add_forces(const double* x, double* f) const;
  // Kinematics at mid-step from x (t_{n+1}) and v (t_{n+1/2}), then the
  // uniaxial-stress material update of every segment.
  void update(const double* x, const double* v, double dt, double time);

  double internal_energy() const;  // J, sum m e over the segments stepped here
  // Smallest segment length / longitudinal wave speed (s) and its segment (0-based).
  double stable_time_step(const double* x, std::size_t& segment) const;
  // Every array a restart needs (checkpoints): the bars' material
  // points, strains and the lateral-rate guesses of the last step.
  void visit_state(StateVisitor& visitor);

  // --- per segment, for gauges and tests ---
  const std::string& set_name(std::size_t s) const;
  double axial_strain(std::size_t s) const { return axial_strain_[s]; }  // log strain, since t = 0
  double axial_stress(std::size_t s) const;                              // Pa, sigma along the bar
  double axial_force(std::size_t s) const;  // N (plane strain: per metre of depth; axisymmetric: whole ring)
  double plastic_strain(std::size_t s) const;
  double plastic_strain_rate(std::size_t s) const;
  double temperature(std::size_t s) const;
  const MaterialPoints& points_of(std::size_t s, std::size_t& point) const;

 private:
  struct Set {
    std::string name;
    const Material* material = nullptr;
    MaterialPoints points;
    std::vector<double> lateral_ratio;               // d_l / d of the last step, the first guess of the next
    double bulk_modulus = 0.0, shear_modulus = 0.0;  // Pa, reference (for the lateral stiffness)
    bool hoop = false;
  };

  void bar_node_position(const double* x, std::size_t b, double* out) const;
  void bar_node_velocity(const double* v, std::size_t b, double* out) const;
  // Uniaxial-stress update of one set given each point's axial rate.
  void update_set(Set& set, const std::vector<double>& axial_rate, double dt, double time);

  bool axisymmetric_ = false;
  // Bar nodes: host element nodes and shape-function weights.
  std::vector<std::int64_t> host_node_;  // b * host_nodes + a
  std::vector<double> weight_;           // b * host_nodes + a
  std::vector<double> node_mass_;        // kg, per bar node (0 where another rank counts it)
  // Segments.
  std::vector<std::size_t> segment_node_;  // 2 per segment
  std::vector<std::size_t> segment_set_;
  std::vector<std::size_t> segment_point_;  // index in its set's points
  std::vector<std::size_t> segment_in_set_;  // 0-based, along its set from `from`
  std::vector<std::size_t> segment_whole_;   // 0-based, in the whole model's segments
  std::size_t total_segments_ = 0;
  std::vector<double> segment_mass_;        // kg
  std::vector<double> reference_length_;    // m, L0 (hoop: r0)
  std::vector<double> axial_strain_;
  std::vector<Set> sets_;
};

extern template class EmbeddedBars<2>;
extern template class EmbeddedBars<3>;

}  // namespace camouflet
