// Whole-model checks before the first cycle (style.md #4, "everything is
// checked before the first cycle"): what no single section can see alone.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "case/sections.hpp"
#include "model/detonation_check.hpp"
#include "model/element_locator.hpp"
#include "model/isoparametric.hpp"

namespace camouflet::case_detail {

namespace {

void check_densities(const Model& model) {
  for (const auto& m : model.materials) {
    const double rho = m.material->reference_density();
    if (!(rho > 0.0) || !std::isfinite(rho)) {
      SourceLocation w = m.where;
      w.key += ".eos.density";
      throw InputError(
          w, fmt::format("material '{}' has reference density {} kg/m^3; it must be positive", m.name, rho));
    }
  }
}

// An element is usable only when its Jacobian is positive at every corner:
// a negative corner value means a folded (inverted or re-entrant) element, a
// (near) zero one a collapsed edge or face; either breaks the one-point
// integration and the time step.
void check_elements(const Model& model) {
  const FemMesh& mesh = model.mesh;
  const int dim = mesh.dimension, npe = mesh.nodes_per_element;
  double nodes[24];
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    gather_element(dim, mesh.coordinates, mesh.connectivity, static_cast<std::int64_t>(e), nodes);
    double extent = 0.0;
    for (int i = 0; i < dim; ++i) {
      double lo = nodes[i], hi = nodes[i];
      for (int a = 1; a < npe; ++a) {
        lo = std::min(lo, nodes[a * dim + i]);
        hi = std::max(hi, nodes[a * dim + i]);
      }
      extent = std::max(extent, hi - lo);
    }
    // Corner Jacobians scale like (size/2)^dim; below 1e-8 of that the element is degenerate.
    const double scale = std::pow(0.5 * extent, dim);
    const std::span<const double> x(nodes, static_cast<std::size_t>(npe * dim));
    const Part& part = model.parts[static_cast<std::size_t>(mesh.element_part[e])];
    for (int a = 0; a < npe; ++a) {
      const double j = jacobian_determinant(dim, x, corner_natural(dim, a));
      const auto node =
          mesh.connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(a)] + 1;
      if (!std::isfinite(j))
        throw InputError(part.where, fmt::format("element {} of part '{}' has non-finite node coordinates",
                                                 e + 1, part.name));
      if (!(extent > 0.0) || std::abs(j) <= 1e-8 * scale)
        throw InputError(
            part.where,
            fmt::format("element {} of part '{}' is degenerate: zero Jacobian at its corner node {} "
                        "(collapsed edge or face)",
                        e + 1, part.name, node));
      if (j < 0.0)
        throw InputError(
            part.where,
            fmt::format("element {} of part '{}' is inverted: negative Jacobian {:.3e} at its corner "
                        "node {} (nodes out of order or a re-entrant corner)",
                        e + 1, part.name, j, node));
    }
  }
}

// A gauge outside every element may still follow a particle (output/gauges):
// accept it within two initial spacings of one, a radius inside any kernel
// support (2h with h >= spacing).
bool near_particle(const Model& model, std::span<const double> x) {
  const ParticleSet& p = model.particles;
  const auto dim = static_cast<std::size_t>(model.dimension());
  const std::size_t n = std::min({p.count(), p.spacing.size(), p.coordinates.size() / dim});
  for (std::size_t i = 0; i < n; ++i) {
    double d2 = 0.0;
    for (std::size_t k = 0; k < dim; ++k) {
      const double d = p.coordinates[i * dim + k] - x[k];
      d2 += d * d;
    }
    if (std::sqrt(d2) <= 2.0 * p.spacing[i]) return true;
  }
  return false;
}

// A member gauge needs at least one element of its material centred in its box.
void check_member(const Model& model, const GaugePoint& g, const std::string& group) {
  const FemMesh& mesh = model.mesh;
  for (std::size_t e = 0; e < mesh.element_count(); ++e) {
    const int part = mesh.element_part.empty() ? -1 : mesh.element_part[e];
    const int material = part >= 0 ? model.parts[static_cast<std::size_t>(part)].material : -1;
    if (g.member_material >= 0 && material != g.member_material) continue;
    if (element_centre_in_box(mesh.dimension, mesh.coordinates, mesh.connectivity, static_cast<std::int64_t>(e),
                              g.region_min, g.region_max))
      return;
  }
  throw InputError(g.where, fmt::format("member '{}' of gauge group '{}': no element centre{} lies in its box",
                                        g.name, group,
                                        g.member_material >= 0
                                            ? " of material '" + model.materials[static_cast<std::size_t>(g.member_material)].name + "'"
                                            : std::string()));
}

void check_gauges(const Model& model) {
  const FemMesh& mesh = model.mesh;
  const ElementLocator locator(mesh.dimension, mesh.coordinates, mesh.connectivity);
  for (const auto& group : model.gauges)
    for (const auto& g : group.points) {
      if (g.member) {
        check_member(model, g, group.name);
        continue;
      }
      const std::span<const double> x(g.position.data(), static_cast<std::size_t>(model.dimension()));
      if (!locator.locate(x) && !near_particle(model, x))
        throw InputError(g.where, fmt::format("gauge '{}' of group '{}' at ({}) lies outside the mesh",
                                              g.name, group.name, fmt::join(x.begin(), x.end(), ", ")));
    }
}

void check_axisymmetric(const Model& model) {
  if (model.run.mode != GeometryMode::axisymmetric) return;
  const FemMesh& mesh = model.mesh;
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    if (mesh.coordinates[2 * n] < -1e-12) {
      for (std::size_t e = 0; e < mesh.element_count(); ++e)
        for (int a = 0; a < 4; ++a)
          if (mesh.connectivity[4 * e + static_cast<std::size_t>(a)] == static_cast<std::int64_t>(n)) {
            const Part& part = model.parts[static_cast<std::size_t>(mesh.element_part[e])];
            throw InputError(part.where, fmt::format("element {} of part '{}' has node {} at r = {} < 0; an "
                                                     "axisymmetric mesh lies in r >= 0",
                                                     e + 1, part.name, n + 1, mesh.coordinates[2 * n]));
          }
    }
}

}  // namespace

// Particles inside FEM elements would double the material there: without a
// join or contact that is refused. Only particles inside the
// mesh's bounding box are located.
static void check_particle_overlap(const Model& model) {
  const FemMesh& mesh = model.mesh;
  const ParticleSet& p = model.particles;
  if (p.count() == 0 || mesh.element_count() == 0) return;
  const auto dim = static_cast<std::size_t>(model.dimension());
  std::array<double, 3> lo{}, hi{};
  for (std::size_t k = 0; k < dim; ++k) lo[k] = hi[k] = mesh.coordinates[k];
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    for (std::size_t k = 0; k < dim; ++k) {
      lo[k] = std::min(lo[k], mesh.coordinates[n * dim + k]);
      hi[k] = std::max(hi[k], mesh.coordinates[n * dim + k]);
    }
  const ElementLocator locator(mesh.dimension, mesh.coordinates, mesh.connectivity);
  for (std::size_t i = 0; i < p.count(); ++i) {
    const std::span<const double> x(&p.coordinates[i * dim], dim);
    bool inside_box = true;
    for (std::size_t k = 0; k < dim; ++k) inside_box = inside_box && x[k] > lo[k] && x[k] < hi[k];
    if (!inside_box || !locator.locate(x)) continue;
    const Part& part = model.parts[static_cast<std::size_t>(p.particle_part[i])];
    SourceLocation w = part.where;
    w.key += ".fill";
    throw InputError(w, fmt::format("particles of SPH part '{}' overlap the finite elements at ({}); declare "
                                    "`join = true` (or `cut_from`) to replace those elements by the zone",
                                    part.name, fmt::join(x.begin(), x.end(), ", ")));
  }
}

void check_model(const Model& model) {
  check_densities(model);
  check_particle_overlap(model);
  check_elements(model);
  check_axisymmetric(model);
  check_gauges(model);
  check_detonation_points(model);  // a charge lit outside every explosive would never burn
}

}  // namespace camouflet::case_detail
