#pragma once
// A read-only view of the solver state at one instant: what gauges, field
// snapshots and checkpoints read. The solver fills it; output/ never sees the
// solver's own types. Per-node vectors are flat, n * dimension.
#include <cstdint>
#include <span>

#include "core/sym_tensor.hpp"
#include "model/model.hpp"

namespace camouflet {

struct FieldSnapshot {
  int dimension = 2;
  GeometryMode mode = GeometryMode::plane_strain;
  double time = 0.0;  // s
  std::int64_t cycle = 0;

  // FEM nodes
  std::span<const double> node_position;      // m
  std::span<const double> node_displacement;  // m
  std::span<const double> node_velocity;      // m/s
  std::span<const double> node_acceleration;  // m/s^2

  // FEM elements (one integration point each)
  int nodes_per_element = 4;
  std::span<const std::int64_t> connectivity;
  std::span<const double> element_density;         // kg/m^3
  std::span<const double> element_pressure;        // Pa (compression positive)
  std::span<const SymTensor> element_stress;       // Pa, Cauchy sigma = s - p I (tension positive)
  std::span<const double> element_plastic_strain;  // -
  std::span<const double> element_damage;          // -
  std::span<const double> element_temperature;     // K; 0 where the material carries no temperature
  std::span<const int> element_material;           // index into Model::materials

  // SPH particles (empty without an SPH part)
  std::span<const double> particle_position;
  std::span<const double> particle_displacement;
  std::span<const double> particle_velocity;
  std::span<const double> particle_acceleration;
  std::span<const double> particle_density;
  std::span<const double> particle_pressure;
  std::span<const SymTensor> particle_stress;
  std::span<const double> particle_plastic_strain;
  std::span<const double> particle_damage;
  std::span<const double> particle_temperature;  // K; 0 where the material carries no temperature
  std::span<const int> particle_material;
  std::span<const double> particle_smoothing_length;  // m
  std::span<const double> particle_mass;              // kg (axisymmetric: mass of the ring)
  std::span<const int> particle_neighbour_count;

  std::size_t node_count() const { return node_position.size() / static_cast<std::size_t>(dimension); }
  std::size_t element_count() const {
    return nodes_per_element ? connectivity.size() / static_cast<std::size_t>(nodes_per_element) : 0;
  }
  std::size_t particle_count() const {
    return particle_position.size() / static_cast<std::size_t>(dimension);
  }
};

}  // namespace camouflet
