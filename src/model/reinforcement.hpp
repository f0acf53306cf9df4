#pragma once
// Reinforced-concrete additions to the model: embedded bar
// elements and per-material element erosion. Plain data, filled by the case
// reader (case/read_reinforcement.cpp) or by tests, used by
// the solver. docs/theory/reinforcement.md.
#include <array>
#include <string>

#include "core/error.hpp"

namespace camouflet {

// Erosion of a material's elements (off when both thresholds are 0). An
// eroded element stops contributing forces, its stress is zeroed, its mass
// stays on its nodes and the internal energy it held is moved to
// EnergyBalance::eroded.
struct ErosionCriteria {
  double geometric_strain = 0.0;  // equivalent total strain sqrt(2/3 eps:eps) at erosion; 0 = off
  double damage = 0.0;            // damage at erosion (0 < D <= 1); 0 = off
  bool enabled() const { return geometric_strain > 0.0 || damage > 0.0; }
};

// How a bar segment strains in axisymmetric mode (ignored in plane strain and 3-D).
enum class BarOrientation {
  along,  // strain along the segment: bars spread around the circumference (a "shell of bars")
  hoop    // rings about the axis: strain v_r / r (hoop reinforcement, stirrups of a round column)
};

// A straight line of 2-node truss bars embedded in the elements of a host
// part. `area` is the bar cross-section in 3-D (m^2); in 2-D it is the steel
// area per metre of the out-of-plane direction (plane strain: per metre of
// depth; axisymmetric: per metre of circumference for `along`, per metre of
// segment length for `hoop`), in m^2/m.
struct BarSet {
  std::string name;
  std::array<double, 3> from{}, to{};  // m, end points at t = 0
  int segments = 1;
  double area = 0.0;
  int material = -1;   // index into Model::materials
  int host_part = -1;  // index into Model::parts; -1 = any FEM part
  BarOrientation orientation = BarOrientation::along;
  SourceLocation where;
};

}  // namespace camouflet
