// The geostatic initial state (docs/theory/gravity.md): the overburden's vertical stress, K0
// times it horizontally, the density at which the EOS carries the mean stress, the rest as the
// initial deviator, checked against the strength before the first step.
#include "model/geostatic_stress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "materials/density_at_pressure.hpp"

namespace camouflet {

namespace {

// K0 of a part: its own, or Jaky's (1944) 1 - sin(phi) from the material's friction angle.
double earth_pressure_coefficient(const Part& part, const NamedMaterial& material) {
  const GeostaticState& geo = *part.geostatic;
  if (geo.k0) return *geo.k0;
  const StrengthModel* strength = material.material->strength();
  const std::optional<double> phi = strength ? strength->friction_angle() : std::nullopt;
  if (!phi)
    throw InputError(geo.where,
                     fmt::format("part '{}': k0 = \"jaky\" needs a friction angle, and material '{}' "
                                 "({}) has none; give k0 as a number",
                                 part.name, material.name, strength ? strength->type() : "no strength"));
  return 1.0 - std::sin(*phi);
}

// The overburden's vertical stress magnitude (Pa) at depths 0 ... depth_max below the part's
// surface, on `nodes` equally spaced depths: s_v(d) = q + g int_0^d rho(p(s_v)) dd with
// p = (1 + 2 K0) s_v / 3 and rho the EOS's density at p. The density changes the weight by
// p / K (below 1e-3 in 10 m of soil), so a few fixed-point sweeps converge.
std::vector<double> overburden_table(const Material& material, double gravity, double surcharge, double k0,
                                     double depth_max, int nodes) {
  MaterialPoints table;
  material.setup(table, static_cast<std::size_t>(nodes));
  const double step = depth_max / (nodes - 1);
  std::vector<double> stress(static_cast<std::size_t>(nodes), surcharge), pressure(stress.size());
  const std::vector<char> active(stress.size(), 1);
  for (int sweep = 0; sweep < 30; ++sweep) {
    double change = 0.0;
    for (std::size_t k = 1; k < stress.size(); ++k) {
      const double next = stress[k - 1] + 0.5 * (table.density[k - 1] + table.density[k]) * gravity * step;
      change = std::max(change, std::abs(next - stress[k]));
      stress[k] = next;
    }
    if (sweep > 0 && change <= 1e-12 * stress.back()) break;
    for (std::size_t k = 0; k < stress.size(); ++k) pressure[k] = (1.0 + 2.0 * k0) * stress[k] / 3.0;
    if (set_density_for_pressure(material.eos(), table, pressure, active).failed_point >= 0) break;
  }
  return stress;
}

}  // namespace

bool GeostaticRequest::any() const {
  return std::any_of(active.begin(), active.end(), [](char a) { return a; });
}

void ask_geostatic_stress(const Model& model, std::size_t part_index,
                          const std::vector<GeostaticPoint>& points,
                          const std::function<std::string(std::size_t)>& name, GeostaticRequest& request) {
  const Part& part = model.parts[part_index];
  const GeostaticState& geo = *part.geostatic;
  const std::array<double, 3>& g = model.run.gravity;
  const double g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (!(g_norm > 0.0))
    throw InputError(geo.where,
                     fmt::format("part '{}' has a geostatic state but [run] gravity is not set", part.name));
  const std::array<double, 3> up{-g[0] / g_norm, -g[1] / g_norm, -g[2] / g_norm};
  const NamedMaterial& material = model.materials[static_cast<std::size_t>(part.material)];
  const double k0 = earth_pressure_coefficient(part, material);

  // Depth of each point below the surface, along gravity.
  std::vector<double> depth(points.size());
  double depth_max = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::array<double, 3>& c = points[k].centre;
    const double d = geo.surface - (c[0] * up[0] + c[1] * up[1] + c[2] * up[2]);
    if (d < 0.0)
      throw InputError(geo.where, fmt::format("part '{}': {} lies {:.6g} m above the geostatic surface "
                                              "{} m (its centre's elevation along -gravity)",
                                              part.name, name(k), -d, geo.surface));
    depth[k] = d;
    depth_max = std::max(depth_max, d);
  }
  // Overburden on a depth table about 100 times finer than 10 points; linear in between.
  const int nodes = 1001;
  const std::vector<double> table =
      overburden_table(*material.material, g_norm, geo.surcharge, k0, std::max(depth_max, 1e-9), nodes);
  const double step = std::max(depth_max, 1e-9) / (nodes - 1);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t p = points[k].slot;
    const double x = depth[k] / step;
    const std::size_t j = std::min(static_cast<std::size_t>(x), static_cast<std::size_t>(nodes - 2));
    const double s_v = table[j] + (x - static_cast<double>(j)) * (table[j + 1] - table[j]);
    // sigma = sigma_h I + (sigma_v - sigma_h) n n, compression negative.
    const double sigma_v = -s_v, sigma_h = -k0 * s_v, d_vh = sigma_v - sigma_h;
    request.stress[p] = {sigma_h + d_vh * up[0] * up[0], sigma_h + d_vh * up[1] * up[1],
                         sigma_h + d_vh * up[2] * up[2], d_vh * up[0] * up[1],
                         d_vh * up[1] * up[2],           d_vh * up[2] * up[0]};
    request.depth[p] = depth[k];
    request.active[p] = 1;
    request.part[p] = part_index;
  }
}

void commit_geostatic_state(const Model& model, std::size_t m, MaterialPoints& pts,
                            const GeostaticRequest& request) {
  const Material& material = *model.materials[m].material;
  std::vector<double> pressure(pts.size(), 0.0);
  bool used = false;
  for (std::size_t p = 0; p < pts.size(); ++p)
    if (request.active[p]) pressure[p] = -request.stress[p].trace() / 3.0, used = true;
  if (!used) return;
  const DensityInversion inv = set_density_for_pressure(material.eos(), pts, pressure, request.active);
  if (inv.failed_point >= 0) {
    const std::size_t p = static_cast<std::size_t>(inv.failed_point);
    throw InputError(
        model.run.where,
        fmt::format("material '{}': no density between rho0 and 2 rho0 carries the geostatic "
                    "pressure {:.6g} Pa at depth {:.6g} m (the EOS gives {:.6g} Pa at the bracket's end)",
                    model.materials[m].name, pressure[p], request.depth[p], inv.bracket_pressure));
  }
  for (std::size_t p = 0; p < pts.size(); ++p) {
    if (!request.active[p]) continue;
    SymTensor s = request.stress[p];
    const double mean = s.trace() / 3.0;
    s.xx -= mean, s.yy -= mean, s.zz -= mean;
    pts.deviator[p] = s;
  }
  // The K0 state must lie inside the strength: one return map at zero strain rate leaves an
  // admissible deviator unchanged and moves any other onto the surface, which is refused here
  // (clamping it would start the model out of equilibrium).
  const StrengthModel* strength = material.strength();
  if (!strength) return;
  const std::vector<SymTensor> before(pts.deviator.begin(), pts.deviator.end());
  strength->update(pts, MaterialContext{1e-9, 0.0});
  for (std::size_t p = 0; p < pts.size(); ++p) {
    if (!request.active[p]) continue;
    const SymTensor& a = before[p];
    const SymTensor& b = pts.deviator[p];
    const double asked_j2 = std::sqrt(j2(a));
    const double moved = std::abs(a.xx - b.xx) + std::abs(a.yy - b.yy) + std::abs(a.zz - b.zz) +
                         std::abs(a.xy - b.xy) + std::abs(a.yz - b.yz) + std::abs(a.zx - b.zx);
    if (moved <= 1e-9 * (asked_j2 + 1.0)) continue;
    const double limit_j2 = std::sqrt(j2(b));
    const Part& part = model.parts[request.part[p]];
    throw InputError(
        part.geostatic->where,
        fmt::format("part '{}': the geostatic K0 state at depth {:.6g} m lies outside the "
                    "strength of material '{}': sqrt(J2) = {:.6g} Pa against a limit of {:.6g} Pa "
                    "at pressure {:.6g} Pa (a smaller |1 - k0| or a stronger material)",
                    part.name, request.depth[p], model.materials[m].name, asked_j2, limit_j2,
                    pts.pressure[p]));
  }
}

void set_geostatic_states(const Model& model, PartKind kind, const char* noun,
                          std::vector<MaterialPoints>& batches,
                          const std::function<void(std::size_t, std::vector<GeostaticPoint>&,
                                                   std::vector<std::size_t>&)>& points_of) {
  std::vector<GeostaticRequest> request;
  for (const MaterialPoints& pts : batches) request.emplace_back(pts.size());
  bool any = false;
  for (std::size_t part_index = 0; part_index < model.parts.size(); ++part_index) {
    const Part& part = model.parts[part_index];
    if (!part.geostatic || part.kind != kind) continue;
    std::vector<GeostaticPoint> points;
    std::vector<std::size_t> ids;
    points_of(part_index, points, ids);
    any = true;
    ask_geostatic_stress(
        model, part_index, points, [&](std::size_t k) { return fmt::format("{} {}", noun, ids[k]); },
        request[static_cast<std::size_t>(part.material)]);
  }
  if (!any) return;
  // A batch without geostatic points is left as it is (commit_geostatic_state returns at once).
  for (std::size_t m = 0; m < batches.size(); ++m) commit_geostatic_state(model, m, batches[m], request[m]);
}

}  // namespace camouflet
