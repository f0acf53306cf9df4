#include "coupling/sph_fem_join.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "core/sym_tensor_vec.hpp"
#include "coupling/element_faces.hpp"
#include "sph/artificial_stress.hpp"

namespace camouflet {
namespace {

// Cell key of a point on a grid of edge `cell`.
template <int D>
std::int64_t cell_key(const Vec<D>& x, double cell, const std::array<int, 3>& offset = {0, 0, 0}) {
  std::int64_t key = 0;
  for (int i = 0; i < D; ++i)
    key = key * 2000003 + static_cast<std::int64_t>(std::floor(x[i] / cell)) +
          offset[static_cast<std::size_t>(i)];
  return key;
}

}  // namespace

template <int D>
Vec<D> SphFemJoin<D>::element_centre(std::size_t e, const double* x) const {
  constexpr int N = FemElements<D>::nodes;
  Vec<D> c{};
  for (int a = 0; a < N; ++a) {
    const std::int64_t n = fem_->elements.connectivity[e * N + static_cast<std::size_t>(a)];
    for (int i = 0; i < D; ++i) c[i] += x[n * D + i] / N;
  }
  return c;
}

template <int D>
Vec<D> SphFemJoin<D>::interpolate(const double* field, const Point& point) const {
  // Bilinear (trilinear) shape functions N_a = prod_i (1 + xi_i xi_ai) / 2 of quad4 (hex8): node
  // natural coordinates in the order of fem/shape.hpp (counter-clockwise, bottom face then top).
  constexpr int N = FemElements<D>::nodes;
  static constexpr double corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  Vec<D> u{};
  for (int a = 0; a < N; ++a) {
    double shape = 1.0;
    for (int i = 0; i < D; ++i) shape *= 0.5 * (1.0 + point.xi[static_cast<std::size_t>(i)] * corner[a][i]);
    const std::int64_t n = fem_->elements.connectivity[point.element * N + static_cast<std::size_t>(a)];
    for (int i = 0; i < D; ++i) u[i] += shape * field[n * D + i];
  }
  return u;
}

template <int D>
Vec<D> SphFemJoin<D>::image(Vec<D> x, const Point& point) const {
  for (int k = 0; k < point.image_count; ++k)
    x = sph::mirror_position(x, planes_[point.planes[static_cast<std::size_t>(k)]]);
  return x;
}

template <int D>
SphFemJoin<D>::SphFemJoin(const Model& model, const FemPackage<D>& fem, sph::SphSystem<D>& particles,
                          std::vector<sph::MirrorPlane> planes)
    : fem_(&fem),
      planes_(std::move(planes)),
      options_(particles.options()),
      axisymmetric_(model.run.mode == GeometryMode::axisymmetric) {
  const FemElements<D>& elements = fem.elements;
  if (model.joins.empty()) return;
  std::vector<char> joined(model.parts.size(), 0);
  for (const Join& join : model.joins)
    for (int p : join.fem_parts) joined[static_cast<std::size_t>(p)] = 1;
  const auto& pa = particles.particles();
  double h_max = 0.0;
  for (std::size_t i = 0; i < pa.real; ++i) h_max = std::max(h_max, pa.smoothing_length[i]);

  // Candidates: every element of a joined part, then its mirror images (as make_ghosts does for particles).
  std::vector<Point> candidates;
  std::vector<Vec<D>> where;
  double h_element_max = 0.0;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (!joined[static_cast<std::size_t>(model.mesh.element_part[e])]) continue;
    const Vec<D> c = element_centre(e);
    double planar_volume = elements.volume[e];
    if (axisymmetric_) planar_volume /= 2.0 * std::numbers::pi * std::max(std::abs(c[0]), 1e-300);
    Point p;
    p.element = e;
    p.rho0 = elements.density[e];
    p.h0 = options_.smoothing_factor * std::pow(planar_volume, 1.0 / D);
    p.planar_volume = planar_volume;
    h_element_max = std::max(h_element_max, p.h0);
    candidates.push_back(p);
    where.push_back(c);
  }
  // Reach: the kernel support of the largest pair smoothing length, with room for h to grow.
  const double reach = sph::support_factor * std::max(h_max, h_element_max) * 1.25;
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    const std::size_t n_now = candidates.size();
    for (std::size_t c = 0; c < n_now; ++c) {
      if (std::abs(where[c][planes_[k].axis] - planes_[k].position) >= reach ||
          candidates[c].image_count >= 3)
        continue;
      Point p = candidates[c];
      p.planes[p.image_count++] = static_cast<std::uint8_t>(k);
      if (planes_[k].kind == sph::PlaneKind::axis) p.across_axis = !p.across_axis;
      candidates.push_back(p);
      where.push_back(sph::mirror_position(where[c], planes_[k]));
    }
  }
  // Particles binned on a grid of edge `reach`.
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> bins;
  for (std::size_t i = 0; i < pa.real; ++i)
    bins[cell_key<D>(pa.position[i], reach)].push_back(static_cast<std::uint32_t>(i));
  // The particle nearest to x within `range` cells of the grid (-1: none within range * reach).
  auto nearest_particle = [&](const Vec<D>& x, int range) {
    std::int64_t best = -1;
    double best_d2 = std::pow(range * reach, 2);
    for (int a = -range; a <= range; ++a)
      for (int b = -range; b <= range; ++b)
        for (int d = (D == 3 ? -range : 0); d <= (D == 3 ? range : 0); ++d) {
          const auto it = bins.find(cell_key<D>(x, reach, {a, b, d}));
          if (it == bins.end()) continue;
          for (std::uint32_t i : it->second) {
            const Vec<D> dx = pa.position[i] - x;
            if (dot(dx, dx) < best_d2) best_d2 = dot(dx, dx), best = i;
          }
        }
    return best;
  };
  // An element coarser than the particles beside it enters as k^D sub-points on a k x k (x k)
  // grid of its natural coordinates, k the spacing ratio rounded (up from 1.3): the particles
  // then see the elements continue their own lattice (spacing and smoothing length), as with
  // equal spacing. With one coarse point per element the pair smoothing length (h_p + h_e) / 2
  // under-resolves the coarse lattice and differs from the particles' own h, so the kernel sums
  // of a particle at the join are not exact and a uniform stress pushes it: 9 % of a pulse's
  // energy was lost at ratio 2 (0.5 % with sub-points; docs/theory/coupling.md). Sub-points
  // carry the element's stress, its velocity field (shape functions) and their share of its area.
  std::unordered_set<std::int64_t> near_cells;  // grid cells within 2 cells of a particle
  for (const auto& [key, members] : bins)
    for (int a = -2; a <= 2; ++a)
      for (int b = -2; b <= 2; ++b)
        for (int d = (D == 3 ? -2 : 0); d <= (D == 3 ? 2 : 0); ++d)
          near_cells.insert(cell_key<D>(pa.position[members.front()], reach, {a, b, d}));
  std::vector<Point> subs;
  std::vector<Vec<D>> sub_where;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!near_cells.contains(cell_key<D>(where[c], reach))) continue;
    const std::int64_t i = nearest_particle(where[c], 2);  // every neighbour of a coupling point
    if (i < 0) continue;
    const double size = std::pow(candidates[c].planar_volume, 1.0 / D);
    const double ratio = size / pa.spacing[static_cast<std::size_t>(i)];
    const int k = std::clamp(static_cast<int>(std::lround(ratio + 0.2)), 1, 4);
    int total = 1;
    for (int d = 0; d < D; ++d) total *= k;
    for (int m = 0; m < total; ++m) {
      Point p = candidates[c];
      for (int d = 0, rest = m; d < D; ++d, rest /= k)
        p.xi[static_cast<std::size_t>(d)] = -1.0 + (2.0 * (rest % k) + 1.0) / k;
      p.planar_volume /= total;
      // The particle's own h: both sides of the join then have the same pair h (equal to h0 / k at
      // an integer ratio). At k = 1 the element keeps its own, as with equal spacing.
      if (k > 1) p.h0 = pa.reference_smoothing_length[static_cast<std::size_t>(i)];
      p.share = 1.0 / total;
      subs.push_back(p);
      sub_where.push_back(image(interpolate(x(), p), p));
    }
  }
  // Keep the sub-points within reach of a particle.
  for (std::size_t c = 0; c < subs.size(); ++c)
    if (nearest_particle(sub_where[c], 1) >= 0) points_.push_back(subs[c]);
  compute_normalisation(particles, subs, sub_where, reach);
  // Interface faces: boundary faces of the joined elements with a particle just outside them.
  reach_ = reach;
  find_interface_faces(model, elements, particles, bins, reach);
  update_face_geometry(x());
  find_corner_faces(x());
  if (points_.empty() || faces_.empty()) {
    const Join& join = model.joins.front();
    throw InputError(join.where,
                     fmt::format("join: no element of the joined FEM parts lies within {:.4g} m of the "
                                 "particles of part '{}': the parts are not adjacent",
                                 reach, model.parts[static_cast<std::size_t>(join.sph_part)].name));
  }
  keep_setup_interface();
  particles.set_external_points(points_.size(),
                                [this](sph::ParticleArrays<D>& p, std::size_t begin) { fill(p, begin); });
}

template <int D>
void SphFemJoin<D>::find_interface_faces(
    const Model& model, const FemElements<D>& elements, const sph::SphSystem<D>& particles,
    const std::unordered_map<std::int64_t, std::vector<std::uint32_t>>& bins, double reach) {
  constexpr int FN = face_nodes;
  constexpr int faces_per_element = join_faces::per_element<D>;
  // The element across each face: also what follow_erosion() walks (keep_setup_interface).
  neighbour_ = join_faces::neighbours(elements);
  std::vector<char> joined(model.parts.size(), 0);
  for (const Join& join : model.joins)
    for (int p : join.fem_parts) joined[static_cast<std::size_t>(p)] = 1;
  const auto& pa = particles.particles();
  std::vector<Vec<D>> centres;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (!joined[static_cast<std::size_t>(model.mesh.element_part[e])]) continue;
    const Vec<D> ce = element_centre(e);
    for (int f = 0; f < faces_per_element; ++f) {
      if (neighbour_[e * faces_per_element + static_cast<std::size_t>(f)] >= 0) continue;  // not on the boundary
      const auto q = join_faces::nodes<D>(elements, e, f);
      Vec<D> cf{};
      for (int a = 0; a < FN; ++a)
        for (int i = 0; i < D; ++i) cf[i] += x()[q[static_cast<std::size_t>(a)] * D + i] / FN;
      const Vec<D> out = cf - ce;  // points out of the element through this face
      const double half = std::sqrt(dot(out, out));
      // A particle within one element half-size (or its own spacing) beyond the face, on its outer side.
      bool faces_particles = false;
      for (int a = -1; a <= 1 && !faces_particles; ++a)
        for (int b = -1; b <= 1 && !faces_particles; ++b)
          for (int c = (D == 3 ? -1 : 0); c <= (D == 3 ? 1 : 0) && !faces_particles; ++c) {
            const auto it = bins.find(cell_key<D>(cf, reach, {a, b, c}));
            if (it == bins.end()) continue;
            for (std::uint32_t i : it->second) {
              const Vec<D> d = pa.position[i] - cf;
              const double along = dot(d, out) / half;
              const double limit = 0.75 * std::max(2.0 * half, pa.spacing[i]);
              if (along > 0.0 && dot(d, d) < limit * limit) {
                faces_particles = true;
                break;
              }
            }
          }
      if (!faces_particles) continue;
      faces_.push_back(q);
      face_element_.push_back(static_cast<std::int64_t>(e));
      centres.push_back(cf);
    }
  }
  // Each coupling point sends its reactions to the interface face nearest to its element.
  for (Point& pt : points_) {
    const Vec<D> ce = interpolate(x(), pt);
    double best = 1e300;
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const Vec<D> d = centres[k] - ce;
      if (dot(d, d) < best) best = dot(d, d), pt.face = k;
    }
  }
}

template <int D>
void SphFemJoin<D>::compute_normalisation(const sph::SphSystem<D>& particles,
                                          const std::vector<Point>& candidates,
                                          const std::vector<Vec<D>>& where, double reach) {
  // n = -(1/d) sum_k V_k r_jk^2 W'(r_jk)/r_jk over every point k around coupling point j:
  // the elements (all candidates, images included) and the particles with their mirror images.
  // In the continuum n = 1; on a lattice it is 0.991 (2-D) and 0.982 (3-D) for the cubic
  // spline at h = 1.2 spacings, and a uniform stress sigma crosses any plane of the lattice as
  // the traction n sigma (the plane sum of the momentum pairs is n/2 of sigma on each side).
  struct Neighbour {
    Vec<D> x;
    double volume, h;
  };
  std::vector<Neighbour> around;
  for (std::size_t c = 0; c < candidates.size(); ++c)
    around.push_back({where[c], candidates[c].planar_volume, candidates[c].h0});
  const auto& pa = particles.particles();
  const std::size_t first_particle = around.size();
  for (std::size_t i = 0; i < pa.real; ++i)
    around.push_back({pa.position[i], pa.mass[i] / pa.planar_density[i], pa.smoothing_length[i]});
  for (const sph::MirrorPlane& plane : planes_) {
    const std::size_t n_now = around.size();
    for (std::size_t k = first_particle; k < n_now; ++k)
      if (std::abs(around[k].x[plane.axis] - plane.position) < reach)
        around.push_back({sph::mirror_position(around[k].x, plane), around[k].volume, around[k].h});
  }
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> bins;
  for (std::size_t k = 0; k < around.size(); ++k)
    bins[cell_key<D>(around[k].x, reach)].push_back(static_cast<std::uint32_t>(k));
  const auto& kernel = particles.kernel();
  for (Point& pt : points_) {
    // An image has the neighbourhood of its element mirrored: the same n.
    const Vec<D> xj = interpolate(x(), pt);
    double sum = 0.0;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int d = (D == 3 ? -1 : 0); d <= (D == 3 ? 1 : 0); ++d) {
          const auto it = bins.find(cell_key<D>(xj, reach, {a, b, d}));
          if (it == bins.end()) continue;
          for (std::uint32_t k : it->second) {
            const Vec<D> dx = xj - around[k].x;
            const double r2 = dot(dx, dx);
            if (r2 <= 0.0) continue;
            const double h = sph::pair_smoothing_length(pt.h0, around[k].h);
            sum -= around[k].volume * r2 * kernel.gradient_factor(std::sqrt(r2), h);
          }
        }
    // A point with a thin neighbourhood (a corner of the mesh) keeps n = 1.
    const double n = sum / D;
    pt.normalisation = n > 0.8 && n < 1.25 ? n : 1.0;
  }
}

template <int D>
void SphFemJoin<D>::fill(sph::ParticleArrays<D>& p, std::size_t begin) const {
  constexpr int N = FemElements<D>::nodes;
  const FemElements<D>& el = fem_->elements;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const Point& pt = points_[k];
    const std::size_t e = pt.element;
    const std::size_t j = begin + k;
    if (el.eroded[e]) {
      // Out of the sums: no mass, so no pair with it has a force, a density or a volume. It
      // stays where it was set up, so that its node's flight does not renew the neighbour lists.
      p.position[j] = image(interpolate(x_setup_.data(), pt), pt);
      p.velocity[j] = Vec<D>{};
      p.mass[j] = 0.0;
      p.planar_density[j] = pt.rho0;
      p.smoothing_length[j] = pt.h0;
      p.stress_term[j] = SymTensor{};
      p.tensile_term[j] = SymTensor{};
      p.wave_speed[j] = 0.0;
      p.viscosity_alpha[j] = options_.viscosity_alpha_min;
      p.correction[j] = SymTensor::identity();
      continue;
    }
    Vec<D> c = interpolate(x(), pt), vel = interpolate(v(), pt);
    // The stress the element's own nodal forces use: sigma - q I (fem_forces.cpp). Without q
    // the particles would see a different traction than the FEM transmits.
    SymTensor sigma = el.stress[e];
    sigma.xx -= el.viscosity[e];
    sigma.yy -= el.viscosity[e];
    sigma.zz -= el.viscosity[e];
    // The ring weight of the element itself: an image carries its element's planar density, as a
    // particle's ghost carries its particle's (SphSystem::refresh_ghosts), so that its volume
    // m / eta is the element's planar area also across a roller r = R, where 2 pi r at the image
    // would not be the element's (it cost 3 % of the energy of a pulse crossing an r-z column).
    const double w = axisymmetric_ ? 2.0 * std::numbers::pi * std::abs(c[0]) : 1.0;
    // Its share of the element's planar area: mass / eta = share x area (the element's ring
    // mass over its centre's ring weight is rho x area, N_a = 1/N at the centre).
    double mass = el.mass[e] * pt.share;
    if (axisymmetric_) {
      double r_centre = 0.0;
      for (int a = 0; a < N; ++a)
        r_centre += x()[el.connectivity[e * N + static_cast<std::size_t>(a)] * D] / N;
      mass *= std::abs(c[0]) / r_centre;
    }
    for (int m = 0; m < pt.image_count; ++m) {
      const sph::MirrorPlane& plane = planes_[pt.planes[static_cast<std::size_t>(m)]];
      c = sph::mirror_position(c, plane);
      vel = sph::mirror_velocity(vel, plane);
      sigma = sph::mirror_tensor(sigma, plane.axis);
    }
    const double rho = el.density[e];
    const double eta = w * rho;
    double h = pt.h0;
    if (options_.variable_smoothing_length && rho > 0.0)
      h = std::clamp(pt.h0 * std::pow(pt.rho0 / rho, 1.0 / D), options_.h_min_factor * pt.h0,
                     options_.h_max_factor * pt.h0);
    p.position[j] = c;
    p.velocity[j] = vel;
    p.mass[j] = mass;
    p.planar_density[j] = eta;
    p.smoothing_length[j] = h;
    // The lattice transmits n sigma across a plane (normalisation in the header): the element's
    // stress enters as sigma / n, or, with the kernel-gradient correction, through B = I / n.
    const double n = options_.kernel_correction ? 1.0 : pt.normalisation;
    p.stress_term[j] = sigma * (1.0 / (rho * n));
    p.tensile_term[j] =
        options_.artificial_stress
            ? sph::artificial_stress<D>(sigma, options_.artificial_stress_epsilon, w / (eta * eta * n))
            : SymTensor{};
    if (pt.across_axis && options_.volume_form) {
      // As the particles' images (SphSystem::refresh_ghosts): across the axis the ring weight
      // 2 pi r is negative, so that r sigma continues linearly through r = 0.
      p.stress_term[j] = p.stress_term[j] * -1.0;
      p.tensile_term[j] = p.tensile_term[j] * -1.0;
    }
    p.wave_speed[j] = el.wave_speed[e];
    // The element has no switch of its own (its shocks are the FEM's q): the least alpha.
    p.viscosity_alpha[j] =
        options_.viscosity_switch ? options_.viscosity_alpha_min : options_.viscosity_alpha;
    p.correction[j] =
        options_.kernel_correction ? SymTensor::identity() * (1.0 / pt.normalisation) : SymTensor::identity();
  }
}

template <int D>
void SphFemJoin<D>::add_reactions(const sph::SphSystem<D>& particles, double* f) {
  // The pair force of sph_forces.cpp (force_pass), term by term.
  const auto& p = particles.particles();
  const auto& kernel = particles.kernel();
  const std::size_t begin = particles.external_begin(), end = begin + points_.size();
  pairs_.clear();
  if (!corner_faces_.empty()) update_face_geometry(x());  // read only by split_reaction at corners
  // r-z: the ring radius of each point's element at the point (an image keeps its element's).
  if (axisymmetric_) {
    ring_.resize(points_.size());
    for (std::size_t k = 0; k < points_.size(); ++k) ring_[k] = std::abs(interpolate(x(), points_[k])[0]);
  }
  for (std::size_t i = 0; i < p.real; ++i) {
    for (const std::uint32_t j : particles.neighbours().neighbours(i)) {
      if (j < begin || j >= end || p.mass[j] == 0.0) continue;  // massless: an eroded element's point
      const Vec<D> dx = p.position[i] - p.position[j];
      const double r2 = dot(dx, dx);
      const double hij = sph::pair_smoothing_length(p.smoothing_length[i], p.smoothing_length[j]);
      if (r2 >= sph::support_factor * sph::support_factor * hij * hij) continue;
      const double r = std::sqrt(r2);
      const Vec<D> grad = particles.corrected_gradient(i, j, dx * kernel.gradient_factor(r, hij));
      const Vec<D> dv = p.velocity[i] - p.velocity[j];
      const double vr = dot(dv, dx);
      // The pair weights of the sums (SphSystem::quadrature_density), so that the reaction matches.
      const double eta_i = particles.quadrature_density(i), eta_j = particles.quadrature_density(j);
      double pi_ij = 0.0;
      if (vr < 0.0) {
        const double mu = hij * vr / (r2 + 0.01 * hij * hij);
        const double c_mean = 0.5 * (p.wave_speed[i] + p.wave_speed[j]);
        const sph::PairViscosity q =
            sph::pair_viscosity(options_, p.viscosity_alpha[i], p.viscosity_alpha[j]);
        pi_ij = (-q.alpha * c_mean * mu + q.beta * mu * mu) / (0.5 * (eta_i + eta_j));
      }
      const SymTensor own =
          options_.volume_form ? p.stress_term[i] * (1.0 / eta_j) : p.stress_term[i] * (1.0 / eta_i);
      SymTensor other =
          options_.volume_form ? p.stress_term[j] * (1.0 / eta_i) : p.stress_term[j] * (1.0 / eta_j);
      // The stress part weighted by the particle's ring radius r_i (r-z, below): m_i m_j / eta_j in
      // the volume form (own: 2 pi r_i A_i A_j sigma_i), in the density form other (m_i A_j sigma_j / rho_j).
      const SymTensor ring_part = options_.volume_form ? own : other;
      // The point's own terms as the sums see them: an image across the axis carries them with its
      // signed ring weight (fill()); the element behind it transmits them with its own, positive one.
      SymTensor signed_part = other;
      if (options_.artificial_stress) {
        const double dp = hij / options_.smoothing_factor;
        const double fr = kernel.value(r, hij) / kernel.value(dp, hij);
        const double fn = std::pow(fr, options_.artificial_stress_power);
        other += (p.tensile_term[i] + p.tensile_term[j]) * fn;
        signed_part += p.tensile_term[j] * fn;
      }
      const double mm = p.mass[i] * p.mass[j];
      const Vec<D> force = (apply<D>(own + other, grad) - grad * pi_ij) * mm;  // on particle i
      const Point& pt = points_[j - begin];
      Vec<D> reaction = force * -1.0;
      if (axisymmetric_) {
        // The r-z ring weights. With ring masses the pair force is 2 pi A_i A_j (r_i sigma_i + r_j sigma_j)
        // . grad W (volume form; A the planar areas). The face takes it with the point's own ring
        // radius r_j in both terms, R = -2 pi r_j A_i A_j (sigma_i + sigma_j) . grad W, the force an
        // element of ring radius r_j transmits (docs/theory/coupling.md):
        // * radially, the part weighted by r_i holds besides the traction the point's share of the
        //   geometric source sigma_rr / r e_r of div(r sigma) / r, a radial force that does not shrink
        //   with the spacing. A particle needs it (its hoop term balances it), the element does not
        //   (its nodal forces hold sigma_rr and sigma_tt exactly); on the face it pulled the nodes
        //   next to the axis inwards, across it;
        // * axially, next to the axis the particles around a point (with their mirror images) have
        //   ring radii |r_i| larger than r_j on average (up to 2x at r_j = dx/2), so the part
        //   weighted by r_i overloaded the first faces off the axis: the nodes there were driven
        //   down through the elements below them (5 m by 50 ms in the default buried case).
        // The particles keep the symmetric pair force (balanced among themselves), so momentum is
        // conserved pair by pair only away from the axis; the work of the difference R + F is
        // booked with the face offset work (settle()), so the energy balance still closes.
        const double ratio = ring_[j - begin] / std::max(std::abs(p.position[i][0]), 1e-300);
        reaction += apply<D>(ring_part, grad) * ((1.0 - ratio) * mm);
        // An image across the axis: the face takes the element's terms with its positive ring
        // weight, R = -2 pi r_j A_i A_j (sigma_i + sigma_j) . grad W as for any point; the particle
        // felt them with the image's negative one (the difference is booked like the one above).
        if (pt.across_axis && options_.volume_form) reaction += apply<D>(signed_part, grad) * (2.0 * mm);
      }
      // To the real frame (an image's reaction acts mirrored on its element), then onto the faces.
      for (int m = 0; m < pt.image_count; ++m) {
        const int axis = planes_[pt.planes[static_cast<std::size_t>(m)]].axis;
        reaction[axis] = -reaction[axis];
      }
      const ReactionParts parts = split_reaction(pt, reaction);
      double power = dot(force, p.velocity[j]);
      for (int k = 0; k < parts.count; ++k) {
        const std::size_t face = parts.face[static_cast<std::size_t>(k)];
        const Vec<D>& part = parts.force[static_cast<std::size_t>(k)];
        power += dot(part, face_velocity(face));
        // Equal shares, also in r-z: the one-point element's own nodal forces on a face are equal
        // (ring volume at the centre x shape gradient), and so are its lumped node masses.
        for (const std::int64_t n : faces_[face])
          for (int d = 0; d < D; ++d) f[n * D + d] += part[d] / face_nodes;
      }
      pairs_.push_back({i, j, apply<D>(other, grad) * mm, grad * (mm * pi_ij), dv, force, parts, power});
    }
  }
}

template <int D>
Vec<D> SphFemJoin<D>::face_velocity(std::size_t face) const {
  const double* velocity = v();
  Vec<D> mean{};
  for (const std::int64_t n : faces_[face])
    for (int d = 0; d < D; ++d) mean[d] += velocity[n * D + d] / face_nodes;
  return mean;
}

template <int D>
double SphFemJoin<D>::settle(const sph::SphSystem<D>& particles, double dt,
                             std::vector<MaterialPoints>& batches) {
  // After the kick: the pair velocities v(n+1/2) are known, so the work of the pair forces of
  // t_n is taken with the mean (v(n-1/2) + v(n+1/2)) / 2 of each pair's relative velocity, the
  // centring of the kinetic energy and of the particles' own viscous heating (sph_motion.cpp, kick).
  const auto& p = particles.particles();
  const std::size_t begin = particles.external_begin();
  double join_work = 0.0;
  face_offset_work_ = 0.0;
  for (const Pair& pair : pairs_) {
    const Vec<D> dv = (pair.dv_old + (p.velocity[pair.i] - p.velocity[pair.j])) * 0.5;
    // The element-side part of the conservative pair work: no internal energy books it. Nor the
    // work of the pair force on the coupling point (v_j, which the sums see) and of its reaction on
    // the face (v_face, which the FEM moves): F . v_j + R . v_face, with R = -F the offset work
    // F . (v_j - v_face), in r-z also the work of the difference of the ring weights (R + F).
    join_work += dot(pair.other, dv) * dt;
    double power_new = dot(pair.force, p.velocity[pair.j]);
    for (int k = 0; k < pair.reaction.count; ++k)
      power_new += dot(pair.reaction.force[static_cast<std::size_t>(k)],
                       face_velocity(pair.reaction.face[static_cast<std::size_t>(k)]));
    face_offset_work_ += 0.5 * (pair.power_old + power_new) * dt;
    // Viscous heat: the particle took half (kick); the element behind the coupling point takes
    // the other half, so the viscosity converts kinetic into internal energy without loss.
    const double heat = 0.5 * dot(pair.viscous, dv) * dt;  // J, >= 0 for an approaching pair
    const std::size_t e = points_[pair.j - begin].element;
    batches[static_cast<std::size_t>(fem_->elements.material[e])].specific_energy[fem_->elements.point[e]] +=
        heat / fem_->elements.mass[e];
  }
  return join_work + face_offset_work_;
}

template class SphFemJoin<2>;
template class SphFemJoin<3>;

}  // namespace camouflet
