#include "coupling/joined_zone.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

namespace camouflet {

namespace {

std::array<double, 3> centre_of(const FemMesh& mesh, std::size_t e) {
  std::array<double, 3> c{};
  const int npe = mesh.nodes_per_element, d = mesh.dimension;
  for (int a = 0; a < npe; ++a) {
    const auto n = static_cast<std::size_t>(
        mesh.connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(a)]);
    for (int i = 0; i < d; ++i)
      c[static_cast<std::size_t>(i)] +=
          mesh.coordinates[n * static_cast<std::size_t>(d) + static_cast<std::size_t>(i)] / npe;
  }
  return c;
}

// Edge of the element's cell: the largest node-to-node distance over sqrt(d).
double size_of(const FemMesh& mesh, std::size_t e) {
  const int npe = mesh.nodes_per_element, d = mesh.dimension;
  double longest = 0.0;
  for (int a = 0; a < npe; ++a)
    for (int b = a + 1; b < npe; ++b) {
      double s = 0.0;
      for (int i = 0; i < d; ++i) {
        const auto na = static_cast<std::size_t>(
            mesh.connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(a)]);
        const auto nb = static_cast<std::size_t>(
            mesh.connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(b)]);
        const double dx = mesh.coordinates[na * static_cast<std::size_t>(d) + static_cast<std::size_t>(i)] -
                          mesh.coordinates[nb * static_cast<std::size_t>(d) + static_cast<std::size_t>(i)];
        s += dx * dx;
      }
      longest = std::max(longest, std::sqrt(s));
    }
  return longest / std::sqrt(static_cast<double>(d));
}

}  // namespace

void make_joined_zone(Model& model, const ParticleFillSpec& spec, const std::vector<int>& cut_parts,
                      const SourceLocation& cut_where) {
  FemMesh& mesh = model.mesh;
  const int d = mesh.dimension;
  const std::size_t npe = static_cast<std::size_t>(mesh.nodes_per_element);
  const std::size_t ne = mesh.element_count();
  const std::string& part_name = model.parts.at(static_cast<std::size_t>(spec.part)).name;

  // The hole: elements of FEM parts whose centre lies in the region.
  std::vector<char> removed(ne, 0);
  std::set<std::int64_t> hole_nodes;
  std::size_t cut = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    if (model.parts[static_cast<std::size_t>(mesh.element_part[e])].kind != PartKind::fem) continue;
    if (!cut_parts.empty() &&
        std::find(cut_parts.begin(), cut_parts.end(), mesh.element_part[e]) == cut_parts.end())
      continue;
    const auto c = centre_of(mesh, e);
    if (!spec.region.contains(c.data(), d)) continue;
    removed[e] = 1;
    ++cut;
    for (std::size_t a = 0; a < npe; ++a) hole_nodes.insert(mesh.connectivity[e * npe + a]);
  }
  if (cut == 0)
    throw InputError(cut_parts.empty() ? spec.where : cut_where,
                     fmt::format("region: the SPH region of part '{}' cuts no element of a FEM part, so "
                                 "there is nothing to join it to (the parts are not adjacent)",
                                 part_name));

  // Elements beside the hole (sharing a node with it) and their parts.
  Join join;
  join.sph_part = spec.part;
  join.where = spec.where;
  std::set<int> fem_parts;
  std::vector<std::size_t> beside;
  for (std::size_t e = 0; e < ne; ++e) {
    if (removed[e]) continue;
    for (std::size_t a = 0; a < npe; ++a)
      if (hole_nodes.count(mesh.connectivity[e * npe + a])) {
        beside.push_back(e);
        fem_parts.insert(mesh.element_part[e]);
        break;
      }
  }
  if (beside.empty())
    throw InputError(spec.where,
                     fmt::format("region: the SPH region of part '{}' covers the whole FEM mesh: no FEM "
                                 "part is left to join",
                                 part_name));
  join.fem_parts.assign(fem_parts.begin(), fem_parts.end());
  // Every part named to be cut must meet the zone: cut, or beside the hole.
  for (int p : cut_parts) {
    bool meets = fem_parts.count(p) > 0;
    for (std::size_t e = 0; e < ne && !meets; ++e) meets = removed[e] && mesh.element_part[e] == p;
    if (!meets)
      throw InputError(cut_where,
                       fmt::format("part '{}' is not adjacent to the SPH zone of part '{}': none of its "
                                   "elements lies in or beside the zone, so there is nothing to join",
                                   model.parts.at(static_cast<std::size_t>(p)).name, part_name));
  }

  // Fill the hole. A box region is snapped to the hole's bounding box, so the
  // particles tile exactly the cells that were cut (no gap, no overlap).
  ParticleFillSpec snapped = spec;
  if (spec.region.shape == ParticleRegion::Shape::box) {
    for (int i = 0; i < d; ++i) {
      double lo = 1e300, hi = -1e300;
      for (std::int64_t n : hole_nodes) {
        lo = std::min(lo, mesh.coordinates[static_cast<std::size_t>(n * d + i)]);
        hi = std::max(hi, mesh.coordinates[static_cast<std::size_t>(n * d + i)]);
      }
      snapped.region.min[static_cast<std::size_t>(i)] = lo;
      snapped.region.max[static_cast<std::size_t>(i)] = hi;
    }
  }
  const std::size_t first_particle = model.particles.count();
  fill_particles(model.particles, snapped, model.run.mode);

  // Spacing ratio at the interface: each element beside the hole against the particles within two of its
  // sizes.
  double size_max = 0.0;
  for (std::size_t e : beside) size_max = std::max(size_max, size_of(mesh, e));
  const double cell = 2.0 * size_max;
  auto key = [&](const double* x, int a, int b, int c) {
    std::int64_t k = 0;
    const int off[3] = {a, b, c};
    for (int i = 0; i < d; ++i) k = k * 2000003 + static_cast<std::int64_t>(std::floor(x[i] / cell)) + off[i];
    return k;
  };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> bins;
  const auto& px = model.particles.coordinates;
  for (std::size_t i = first_particle; i < model.particles.count(); ++i)
    bins[key(&px[i * static_cast<std::size_t>(d)], 0, 0, 0)].push_back(i);
  double worst = 1.0, worst_particle = 0.0, worst_element = 0.0;
  for (std::size_t e : beside) {
    const double s_e = size_of(mesh, e);
    const auto c = centre_of(mesh, e);
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int cc = (d == 3 ? -1 : 0); cc <= (d == 3 ? 1 : 0); ++cc) {
          const auto it = bins.find(key(c.data(), a, b, cc));
          if (it == bins.end()) continue;
          for (std::size_t i : it->second) {
            double r2 = 0.0;
            for (int k = 0; k < d; ++k) {
              const double dx = px[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)] -
                                c[static_cast<std::size_t>(k)];
              r2 += dx * dx;
            }
            const double s_p = model.particles.spacing[i];
            if (r2 > 4.0 * std::max(s_e, s_p) * std::max(s_e, s_p)) continue;
            const double ratio = std::max(s_p / s_e, s_e / s_p);
            if (ratio > worst) worst = ratio, worst_particle = s_p, worst_element = s_e;
          }
        }
  }
  if (worst > join_spacing_ratio_limit * (1.0 + 1e-6)) {
    SourceLocation at_spacing = spec.where;
    if (!at_spacing.key.empty()) at_spacing.key += ".spacing";
    throw InputError(
        at_spacing,
        fmt::format("spacing: particle spacing {:.4g} m against elements of {:.4g} m at the join of part "
                    "'{}' is a ratio of {:.3g}, beyond the limit {:g} (docs/theory/coupling.md)",
                    worst_particle, worst_element, part_name, worst, join_spacing_ratio_limit));
  }

  // Remove the hole's elements, and the faces of sets that no remaining element carries.
  std::vector<std::int64_t> connectivity;
  std::vector<int> element_part;
  for (std::size_t e = 0; e < ne; ++e) {
    if (removed[e]) continue;
    connectivity.insert(connectivity.end(), mesh.connectivity.begin() + static_cast<std::ptrdiff_t>(e * npe),
                        mesh.connectivity.begin() + static_cast<std::ptrdiff_t>((e + 1) * npe));
    element_part.push_back(mesh.element_part[e]);
  }
  mesh.connectivity = std::move(connectivity);
  mesh.element_part = std::move(element_part);
  std::vector<std::vector<std::size_t>> node_elements(mesh.node_count());
  for (std::size_t e = 0; e < mesh.element_count(); ++e)
    for (std::size_t a = 0; a < npe; ++a)
      node_elements[static_cast<std::size_t>(mesh.connectivity[e * npe + a])].push_back(e);
  const std::size_t fn = d == 2 ? 2 : 4;
  for (auto& [name, faces] : mesh.face_sets) {
    std::vector<std::int64_t> kept;
    for (std::size_t k = 0; k + fn - 1 < faces.size(); k += fn) {
      bool carried = false;
      for (std::size_t e : node_elements[static_cast<std::size_t>(faces[k])]) {
        bool all = true;
        for (std::size_t a = 1; a < fn && all; ++a) {
          const auto* conn = &mesh.connectivity[e * npe];
          all = std::find(conn, conn + npe, faces[k + a]) != conn + npe;
        }
        if (all) carried = true;
      }
      if (carried)
        kept.insert(kept.end(), faces.begin() + static_cast<std::ptrdiff_t>(k),
                    faces.begin() + static_cast<std::ptrdiff_t>(k + fn));
    }
    faces = std::move(kept);
  }
  model.joins.push_back(std::move(join));
}

}  // namespace camouflet
