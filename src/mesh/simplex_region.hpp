#pragma once
// A region given as a set of simplices (triangles in 2-D, tetrahedra in 3-D),
// e.g. a Gmsh physical surface/volume cut into simplices (mesh/gmsh_import.hpp),
// for filling with particles (mesh/particle_fill.hpp). Point location goes
// through a uniform bucket grid over the bounding box, so contains() costs a
// few barycentric tests whatever the number of simplices.
#include <array>
#include <cstdint>
#include <vector>

namespace camouflet {

class SimplexRegion {
 public:
  // `vertices`: dim + 1 corners per simplex, each 3 numbers (z = 0 in 2-D).
  SimplexRegion(int dimension, std::vector<std::array<double, 3>> vertices);

  int dimension() const { return dim_; }
  std::size_t size() const { return corners_.size() / static_cast<std::size_t>(dim_ + 1); }
  // Inside or on the boundary of some simplex (relative tolerance 1e-10 on the barycentric coordinates).
  bool contains(const double* x) const;
  const std::array<double, 3>& lower() const { return lo_; }
  const std::array<double, 3>& upper() const { return hi_; }
  double measure() const;  // total area (2-D) or volume (3-D) of the simplices, m^2 or m^3

 private:
  bool in_simplex(std::size_t s, const double* x) const;
  std::array<long, 3> cell_of(const double* x) const;

  int dim_;
  std::vector<std::array<double, 3>> corners_;
  std::array<double, 3> lo_{}, hi_{};
  std::array<long, 3> cells_{1, 1, 1};
  std::array<double, 3> cell_size_{1, 1, 1};
  std::vector<std::size_t> bucket_offset_;
  std::vector<std::uint32_t> bucket_;  // simplex indices by grid cell
};

}  // namespace camouflet
