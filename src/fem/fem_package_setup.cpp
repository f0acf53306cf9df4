// FemPackage set-up (fem_package.hpp): nodes, elements, material batches, the
// geostatic state, masses and initial velocities, bars, erosion and the
// hourglass and viscosity controls, from the model.
#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "core/error.hpp"
#include "fem/edge_continuation.hpp"
#include "fem/edge_viscosity.hpp"
#include "fem/fem_package.hpp"
#include "model/geostatic_stress.hpp"

namespace camouflet {

namespace {

// Element centre (m, padded to 3 components) for EquationOfState::place.
template <int D>
std::array<double, 3> centre(const std::vector<double>& x, const std::int64_t* conn) {
  constexpr int N = FemElements<D>::nodes;
  std::array<double, 3> c{};
  for (int a = 0; a < N; ++a)
    for (int i = 0; i < D; ++i) c[static_cast<std::size_t>(i)] += x[conn[a] * D + i] / N;
  return c;
}

}  // namespace

template <int D>
FemPackage<D>::FemPackage(const Model& model, const NodeSharing* sharing) : model_(&model), sharing_(sharing) {
  const FemMesh& mesh = model.mesh;
  const GeometryMode mode = model.run.mode;
  const bool has_mesh = mesh.node_count() > 0;
  if ((has_mesh && mesh.dimension != D) || model.dimension() != D)
    throw InputError(model.run.where, fmt::format("mesh dimension {} does not match geometry mode '{}'",
                                                  mesh.dimension, to_string(model.run.mode)));
  if (has_mesh && mesh.nodes_per_element != FemElements<D>::nodes)
    throw InputError(model.run.where, fmt::format("{}-D meshes need {}-node elements, got {}", D,
                                                  FemElements<D>::nodes, mesh.nodes_per_element));
  const std::size_t nn = mesh.node_count();
  position = mesh.coordinates;
  for (auto* v : {&velocity, &velocity_old, &acceleration, &force, &displacement}) v->assign(nn * D, 0.0);
  node_mass.assign(nn, 0.0);

  try {
    elements = FemElements<D>(mesh, mode, position);
    if (mode == GeometryMode::axisymmetric) {
      // Each element its part's momentum form (Model::area_weighted_momentum_of, the run's unless
      // the part has its own), stored only where they differ.
      std::vector<char> area(elements.size());
      for (std::size_t e = 0; e < area.size(); ++e)
        area[e] = model.area_weighted_momentum_of(static_cast<std::size_t>(mesh.element_part[e])) ? 1 : 0;
      elements.set_area_forms(std::move(area));
    }
  } catch (const InputError& e) {  // name the case file the mesh came from
    throw InputError(SourceLocation{model.case_file, 0, 0, "mesh"}, e.message());
  }
  const std::size_t ne = elements.size();

  // Elements -> material batches.
  batches.resize(model.materials.size());
  std::vector<std::size_t> count(model.materials.size(), 0);
  for (std::size_t e = 0; e < ne; ++e) {
    const int part_index = mesh.element_part[e];
    if (part_index < 0 || static_cast<std::size_t>(part_index) >= model.parts.size())
      throw InputError(model.run.where, fmt::format("element {} belongs to no part", e + 1));
    const Part& part = model.parts[static_cast<std::size_t>(part_index)];
    if (part.material < 0 || static_cast<std::size_t>(part.material) >= model.materials.size())
      throw InputError(part.where, fmt::format("part '{}' has no material", part.name));
    elements.material[e] = part.material;
    elements.point[e] = count[static_cast<std::size_t>(part.material)]++;
  }
  std::vector<std::vector<std::array<double, 3>>> centres(model.materials.size());
  for (std::size_t e = 0; e < ne; ++e)
    centres[static_cast<std::size_t>(elements.material[e])].push_back(
        centre<D>(position, &elements.connectivity[e * FemElements<D>::nodes]));
  for (std::size_t m = 0; m < batches.size(); ++m) {
    const Material& mat = *model.materials[m].material;
    mat.setup(batches[m], count[m]);
    mat.eos().place(batches[m], centres[m], model.detonations);
  }
  set_geostatic_state();  // before the masses: they follow from the density that carries the overburden

  // Masses and initial velocities (mass-weighted where parts meet).
  std::vector<double> momentum(nn * D, 0.0);
  for (std::size_t e = 0; e < ne; ++e) {
    const MaterialPoints& pts = batches[static_cast<std::size_t>(elements.material[e])];
    const double rho0 = pts.density[elements.point[e]];
    elements.mass[e] = rho0 * elements.volume[e];
    elements.density[e] = rho0;
    const Part& part = model.parts[static_cast<std::size_t>(mesh.element_part[e])];
    const double m_node = elements.mass[e] / FemElements<D>::nodes;
    for (int a = 0; a < FemElements<D>::nodes; ++a) {
      const std::int64_t n = elements.connectivity[e * FemElements<D>::nodes + static_cast<std::size_t>(a)];
      node_mass[static_cast<std::size_t>(n)] += m_node;
      for (int i = 0; i < D; ++i)
        momentum[static_cast<std::size_t>(n * D + i)] += m_node * part.initial_velocity[static_cast<std::size_t>(i)];
    }
  }
  if (sharing) {  // each holder of a shared node has its own elements' share of both
    sharing->sum_shared(node_mass, 1);
    sharing->sum_shared(momentum, D);
  }
  for (std::size_t n = 0; n < nn; ++n)
    for (int i = 0; i < D; ++i)
      velocity[n * D + static_cast<std::size_t>(i)] =
          node_mass[n] > 0.0 ? momentum[n * D + static_cast<std::size_t>(i)] / node_mass[n] : 0.0;

  // Bars take their hosts' velocity: their mass joins the nodes after the
  // initial velocities are set, so the parts' initial velocities stay exact.
  // On ranks each rank spreads the bar nodes its elements host, and the shares of shared nodes
  // are added up (the same sums on one rank as serially).
  if (const BarShare* share = sharing ? sharing->bar_share() : nullptr)
    bars = EmbeddedBars<D>(model, share->hosts, &share->hosted_here, sharing->global_nodes());
  else
    bars = EmbeddedBars<D>(model, position);
  if (!model.bars.empty()) {
    std::vector<double> bar_mass(nn, 0.0);
    bars.add_masses(bar_mass);
    if (sharing) sharing->sum_shared(bar_mass, 1);
    for (std::size_t n = 0; n < nn; ++n) node_mass[n] += bar_mass[n];
  }
  for (const auto& criteria : model.erosion) {
    erosion = erosion || criteria.enabled();
    if (criteria.geometric_strain > 0.0) total_strain.assign(ne, SymTensor{});
  }

  hourglass = {model.run.hourglass, model.run.hourglass_coefficient};
  // Parts with their own hourglass control: every element gets its part's.
  if (std::any_of(model.parts.begin(), model.parts.end(), [](const Part& p) { return p.hourglass.has_value(); })) {
    std::vector<HourglassControl> per_element(ne);
    for (std::size_t e = 0; e < ne; ++e)
      per_element[e] = model.hourglass_of(static_cast<std::size_t>(mesh.element_part[e]));
    elements.set_hourglass(per_element);
  }
  // The viscous form's work is charged from its nodal forces; the stiffness
  // form holds its energy as a state (1/2 k q^2), like the internal energy.
  if (elements.any_viscous_hourglass(hourglass)) {
    hourglass_force.assign(nn * D, 0.0);
    hourglass_force_previous.assign(nn * D, 0.0);
  }
  // Subzonal pressures and the viscosity form: each element its part's (Model::subzonal_of,
  // viscosity_form_of); the forms stored per element only where the parts differ.
  viscosity = {model.run.viscosity_quadratic, model.run.viscosity_linear, model.run.viscosity_form,
               model.run.viscosity_limiter};
  std::vector<double> subzonal(ne);
  std::vector<ViscosityForm> forms(ne);
  bool mixed_forms = false;
  for (std::size_t e = 0; e < ne; ++e) {
    const auto part = static_cast<std::size_t>(mesh.element_part[e]);
    subzonal[e] = model.subzonal_of(part);
    forms[e] = model.viscosity_form_of(part);
    mixed_forms = mixed_forms || forms[e] != viscosity.form;
  }
  elements.set_subzonal_pressure(subzonal, position.data());
  if (mixed_forms) elements.set_viscosity_forms(std::move(forms));
  const bool edges = mixed_forms ? elements.edge_form_anywhere : viscosity.form == ViscosityForm::edge;
  if (edges) elements.edge_force.assign(ne * ElementEdges<D>::count * D, 0.0);
  if (edges && viscosity.limiter)
    elements.edge_continuation = edge_continuations<D>(elements.connectivity, nn, position.data());
}

// The geostatic initial state of the FEM soil parts under gravity (docs/theory/gravity.md): each
// element's point takes its part's overburden state at the element's centre
// (model/geostatic_stress.hpp, which the SPH package uses for its particles too).
template <int D>
void FemPackage<D>::set_geostatic_state() {
  constexpr int N = FemElements<D>::nodes;
  const Model& model = *model_;
  const std::size_t ne = elements.size();
  set_geostatic_states(
      model, PartKind::fem, "element", batches,
      [&](std::size_t part, std::vector<GeostaticPoint>& points, std::vector<std::size_t>& ids) {
        for (std::size_t e = 0; e < ne; ++e) {
          if (static_cast<std::size_t>(model.mesh.element_part[e]) != part) continue;
          GeostaticPoint point{elements.point[e], {}};
          for (int a = 0; a < N; ++a)
            for (int i = 0; i < D; ++i)
              point.centre[static_cast<std::size_t>(i)] +=
                  position[static_cast<std::size_t>(elements.connectivity[e * N + a] * D + i)] / N;
          points.push_back(point);
          ids.push_back(e + 1);
        }
      });
}

template FemPackage<2>::FemPackage(const Model&, const NodeSharing*);
template FemPackage<3>::FemPackage(const Model&, const NodeSharing*);
template void FemPackage<2>::set_geostatic_state();
template void FemPackage<3>::set_geostatic_state();

}  // namespace camouflet
