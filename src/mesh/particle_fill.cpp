#include "mesh/particle_fill.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camouflet {

namespace {

SourceLocation at_key(const SourceLocation& block, const std::string& key) {
  SourceLocation w = block;
  w.key = block.key.empty() ? key : block.key + "." + key;
  return w;
}

// Appends the cell centres of a tiling of [lo, hi] (per axis round(L / s) cells, at least one).
template <class Emit>
void tile_box(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double s, int dim,
              Emit&& emit) {
  std::array<long, 3> n{1, 1, 1};
  std::array<double, 3> step{0, 0, 1};
  for (int d = 0; d < dim; ++d) {
    const double len = hi[d] - lo[d];
    if (len <= 0.0) return;
    n[d] = std::max(1L, std::lround(len / s));
    step[d] = len / static_cast<double>(n[d]);
  }
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i) {
        std::array<double, 3> c{lo[0] + (i + 0.5) * step[0], lo[1] + (j + 0.5) * step[1],
                                dim == 3 ? lo[2] + (k + 0.5) * step[2] : 0.0};
        emit(c, step);
      }
}

bool boxes_overlap(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                   const std::array<double, 3>& blo, const std::array<double, 3>& bhi, int dim) {
  for (int d = 0; d < dim; ++d)
    if (hi[d] < blo[d] || lo[d] > bhi[d]) return false;
  return true;
}

}  // namespace

bool ParticleRegion::contains(const double* x, int dim) const {
  switch (shape) {
    case Shape::box:
      for (int d = 0; d < dim; ++d)
        if (x[d] < min[d] || x[d] > max[d]) return false;
      return true;
    case Shape::sphere: {
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) r2 += (x[d] - centre[d]) * (x[d] - centre[d]);
      return r2 <= radius * radius;
    }
    case Shape::cylinder: {
      if (dim == 2)  // meridian section of an upright cylinder: |x - cx| <= R, cy <= y <= cy + L
        return std::abs(x[0] - centre[0]) <= radius && x[1] >= centre[1] && x[1] <= centre[1] + length;
      const double an = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      double t = 0.0, r2 = 0.0;
      for (int d = 0; d < 3; ++d) t += (x[d] - centre[d]) * axis[d] / an;
      if (t < 0.0 || t > length) return false;
      for (int d = 0; d < 3; ++d) {
        const double e = x[d] - centre[d] - t * axis[d] / an;
        r2 += e * e;
      }
      return r2 <= radius * radius;
    }
    case Shape::polygon: {
      bool inside = false;  // even-odd ray casting
      const std::size_t n = polygon.size();
      for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const auto& a = polygon[i];
        const auto& b = polygon[j];
        if ((a[1] > x[1]) != (b[1] > x[1]) && x[0] < (b[0] - a[0]) * (x[1] - a[1]) / (b[1] - a[1]) + a[0])
          inside = !inside;
      }
      return inside;
    }
    case Shape::mesh:
      return mesh && mesh->contains(x);
  }
  return false;
}

std::pair<std::array<double, 3>, std::array<double, 3>> ParticleRegion::bounds(int dim) const {
  std::array<double, 3> lo{}, hi{};
  switch (shape) {
    case Shape::box:
      return {min, max};
    case Shape::sphere:
      for (int d = 0; d < dim; ++d) lo[d] = centre[d] - radius, hi[d] = centre[d] + radius;
      return {lo, hi};
    case Shape::cylinder:
      if (dim == 2) return {{centre[0] - radius, centre[1], 0}, {centre[0] + radius, centre[1] + length, 0}};
      {
        // Bounding box of the two end discs.
        const double an = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        for (int d = 0; d < 3; ++d) {
          const double a = axis[d] / an;
          const double ext = radius * std::sqrt(std::max(0.0, 1.0 - a * a));
          const double e0 = centre[d], e1 = centre[d] + length * a;
          lo[d] = std::min(e0, e1) - ext;
          hi[d] = std::max(e0, e1) + ext;
        }
      }
      return {lo, hi};
    case Shape::polygon:
      lo = {polygon.empty() ? 0 : polygon[0][0], polygon.empty() ? 0 : polygon[0][1], 0};
      hi = lo;
      for (const auto& v : polygon)
        for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], v[d]), hi[d] = std::max(hi[d], v[d]);
      return {lo, hi};
    case Shape::mesh:
      if (mesh) return {mesh->lower(), mesh->upper()};
      return {lo, hi};
  }
  return {lo, hi};
}

void fill_particles(ParticleSet& particles, const ParticleFillSpec& spec, GeometryMode mode) {
  const int dim = dimension_of(mode);
  const bool axisymmetric = mode == GeometryMode::axisymmetric;
  const auto& region = spec.region;
  if (!(spec.spacing > 0.0)) throw InputError(at_key(spec.where, "spacing"), "spacing must be positive");
  if (region.shape == ParticleRegion::Shape::polygon && (dim != 2 || region.polygon.size() < 3))
    throw InputError(at_key(spec.where, "polygon"), "a polygon region needs at least 3 vertices in 2-D");
  if ((region.shape == ParticleRegion::Shape::sphere || region.shape == ParticleRegion::Shape::cylinder) &&
      !(region.radius > 0.0))
    throw InputError(at_key(spec.where, "radius"), "radius must be positive");
  if (region.shape == ParticleRegion::Shape::cylinder && !(region.length > 0.0))
    throw InputError(at_key(spec.where, "length"), "length must be positive");
  if (spec.graded) {
    if (!(spec.grading_ratio >= 1.0))
      throw InputError(at_key(spec.where, "grading_ratio"), "grading ratio must be at least 1");
    if (!(spec.max_spacing >= spec.spacing))
      throw InputError(at_key(spec.where, "max_spacing"), "max_spacing must not be below spacing");
  }
  auto [blo, bhi] = region.bounds(dim);
  for (int d = 0; d < dim; ++d)
    if (!(bhi[d] > blo[d])) throw InputError(spec.where, "the particle region is empty (zero extent)");
  if (axisymmetric && blo[0] < -1e-12 * (bhi[0] - blo[0])) {
    // A sphere or cylinder centred on the axis is a body of revolution: its
    // meridian half r >= 0 is filled. Anything else must lie at r >= 0.
    const bool on_axis =
        (region.shape == ParticleRegion::Shape::sphere || region.shape == ParticleRegion::Shape::cylinder) &&
        std::abs(region.centre[0]) <= 1e-12 * region.radius;
    if (!on_axis) throw InputError(spec.where, "an axisymmetric particle region must lie at r >= 0");
    blo[0] = 0.0;
  }

  const std::size_t before = particles.count();
  auto emit = [&](const std::array<double, 3>& c, const std::array<double, 3>& step) {
    if (!region.contains(c.data(), dim)) return;
    if (axisymmetric && c[0] <= 0.0) return;
    for (const ParticleRegion& hole : spec.exclude)
      if (hole.contains(c.data(), dim)) return;
    double cell = 1.0;
    for (int d = 0; d < dim; ++d) cell *= step[d];
    for (int d = 0; d < dim; ++d) particles.coordinates.push_back(c[d]);
    particles.volume.push_back(axisymmetric ? 2.0 * std::numbers::pi * c[0] * cell : cell);
    particles.spacing.push_back(std::pow(cell, 1.0 / dim));
    particles.particle_part.push_back(spec.part);
  };

  if (!spec.graded) {
    if (region.shape == ParticleRegion::Shape::box) {
      tile_box(blo, bhi, spec.spacing, dim, emit);
    } else {
      // Lattice anchored at the bounding box, ceil(L / s) cells of exactly s.
      std::array<double, 3> hi = blo;
      for (int d = 0; d < dim; ++d) {
        const double n = std::ceil((bhi[d] - blo[d]) / spec.spacing - 1e-9);
        hi[d] = blo[d] + n * spec.spacing;
      }
      tile_box(blo, hi, spec.spacing, dim, emit);
    }
  } else {
    const auto& p = spec.grading_point;
    double reach = 0.0;  // infinity-norm distance from the grading point to the farthest box corner
    for (int d = 0; d < dim; ++d) reach = std::max({reach, std::abs(bhi[d] - p[d]), std::abs(blo[d] - p[d])});
    double a = 0.0, s = spec.spacing;
    while (a < reach) {
      const double b = a + s;
      // The shell a <= |x - p|_inf < b as 2 D boxes: along axis d the two slabs
      // a <= |x_d - p_d| < b, limited to |x_e - p_e| < a on the axes e < d
      // (already covered by their slabs) and < b on the axes e > d.
      for (int d = 0; d < dim; ++d)
        for (int side = -1; side <= 1; side += 2) {
          std::array<double, 3> lo{}, hi{};
          bool empty = false;
          for (int e = 0; e < dim; ++e) {
            if (e == d) {
              lo[e] = side < 0 ? p[e] - b : p[e] + a;
              hi[e] = side < 0 ? p[e] - a : p[e] + b;
            } else {
              const double w = e < d ? a : b;
              lo[e] = p[e] - w;
              hi[e] = p[e] + w;
              if (w <= 0.0) empty = true;
            }
          }
          if (empty || !boxes_overlap(lo, hi, blo, bhi, dim)) continue;
          tile_box(lo, hi, s, dim, emit);
        }
      a = b;
      s = std::min(s * spec.grading_ratio, spec.max_spacing);
    }
  }
  if (particles.count() == before)
    throw InputError(spec.where, "the particle region holds no particle at this spacing (empty region)");
}

}  // namespace camouflet
