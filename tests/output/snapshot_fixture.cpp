#include "snapshot_fixture.hpp"

#include <cmath>

namespace camouflet::test {

SnapshotFixture SnapshotFixture::distorted(int dim, int n) {
  SnapshotFixture f;
  f.dim = dim;
  const int nz = dim == 3 ? n : 0;
  auto id = [&](int i, int j, int k) { return static_cast<std::int64_t>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double h = 1.0 / n;
        const bool interior = i > 0 && i < n && j > 0 && j < n && (dim == 2 || (k > 0 && k < nz));
        // Deterministic, non-symmetric displacement of interior nodes (a third of a cell at most).
        const double dx = interior ? 0.3 * h * std::sin(1.7 * i + 2.3 * j + 0.7 * k) : 0.0;
        const double dy = interior ? 0.25 * h * std::cos(2.9 * i + 1.1 * j + 1.3 * k) : 0.0;
        const double dz = interior ? 0.2 * h * std::sin(0.9 * i + 1.9 * j + 2.1 * k) : 0.0;
        f.position.push_back(i * h + dx);
        f.position.push_back(j * h + dy);
        if (dim == 3) f.position.push_back(k * h + dz);
      }
  for (int k = 0; k < std::max(nz, 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        for (int layer = 0; layer < (dim == 3 ? 2 : 1); ++layer) {
          const int kk = k + layer;
          f.connectivity.insert(f.connectivity.end(),
                                {id(i, j, kk), id(i + 1, j, kk), id(i + 1, j + 1, kk), id(i, j + 1, kk)});
        }
        const std::size_t e = f.density.size();
        f.density.push_back(1000.0 + static_cast<double>(e));
        f.pressure.push_back(1e5 * static_cast<double>(e + 1));
        f.stress.push_back(SymTensor{-1.0 * static_cast<double>(e), 2.0, 3.0, 4.0, 5.0, 6.0});
        f.plastic.push_back(0.01 * static_cast<double>(e));
        f.damage.push_back(0.0);
        f.temperature.push_back(300.0);
        f.material.push_back(static_cast<int>(e % 2));
      }
  f.displacement.assign(f.position.size(), 0.0);
  f.velocity.assign(f.position.size(), 0.0);
  f.acceleration.assign(f.position.size(), 0.0);
  return f;
}

std::array<double, 3> SnapshotFixture::velocity_at(const std::array<double, 3>& x) {
  return {1.0 + 2.0 * x[0] - 3.0 * x[1] + 0.5 * x[2], -4.0 + 0.25 * x[0] + 5.0 * x[1] - 1.5 * x[2],
          2.0 - x[0] + x[1] + 3.0 * x[2]};
}

void SnapshotFixture::set_linear_fields(double time) {
  const std::size_t n = position.size() / static_cast<std::size_t>(dim);
  for (std::size_t a = 0; a < n; ++a) {
    std::array<double, 3> x{};
    for (int i = 0; i < dim; ++i)
      x[static_cast<std::size_t>(i)] = position[a * dim + static_cast<std::size_t>(i)];
    const auto v = velocity_at(x);
    for (int i = 0; i < dim; ++i) {
      velocity[a * dim + static_cast<std::size_t>(i)] = v[static_cast<std::size_t>(i)];
      displacement[a * dim + static_cast<std::size_t>(i)] = time * v[static_cast<std::size_t>(i)];
      acceleration[a * dim + static_cast<std::size_t>(i)] = -v[static_cast<std::size_t>(i)];
    }
  }
}

FieldSnapshot SnapshotFixture::view(double time, std::int64_t cycle) const {
  FieldSnapshot s;
  s.dimension = dim;
  s.mode = dim == 3 ? GeometryMode::three_d : GeometryMode::plane_strain;
  s.time = time;
  s.cycle = cycle;
  s.node_position = position;
  s.node_displacement = displacement;
  s.node_velocity = velocity;
  s.node_acceleration = acceleration;
  s.nodes_per_element = dim == 3 ? 8 : 4;
  s.connectivity = connectivity;
  s.element_density = density;
  s.element_pressure = pressure;
  s.element_stress = stress;
  s.element_plastic_strain = plastic;
  s.element_damage = damage;
  s.element_temperature = temperature;
  s.element_material = material;
  return s;
}

}  // namespace camouflet::test
