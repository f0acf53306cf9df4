// FEM element set-up and bookkeeping: reference geometry, wave speeds, ring
// factors, hourglass control per element, the colour blocks of the force
// assembly. The per-cycle loops are in fem_forces.cpp, element_forces.cpp and
// fem_kinematics.cpp.
#include "fem/fem_elements.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "fem/element_gather.hpp"
#include "fem/subzonal_pressure.hpp"

namespace camouflet {

template <int D>
FemElements<D>::FemElements(const FemMesh& mesh, GeometryMode mode, const std::vector<double>& coordinates)
    : connectivity(mesh.connectivity), axisymmetric_(mode == GeometryMode::axisymmetric) {
  const std::size_t n = mesh.element_count();
  material.assign(n, 0);
  point.assign(n, 0);
  mass.assign(n, 0.0);
  volume.assign(n, 0.0);
  stress.assign(n, SymTensor{});
  viscosity.assign(n, 0.0);
  density.assign(n, 0.0);
  wave_speed.assign(n, 0.0);
  stable_wave_speed.assign(n, 0.0);
  length.assign(n, 0.0);
  speed.assign(n, 0.0);
  hourglass_displacement.assign(n * modes * D, 0.0);
  eroded.assign(n, 0);
  for (std::size_t e = 0; e < n; ++e) {
    NodeValues<D> x, b;
    gather<D>(coordinates.data(), &connectivity[e * nodes], x);
    const double measure = Shape<D>::gradients(x, b);
    double r_bar = 0.0;
    const double w = ring_weight<D>(axisymmetric_, x, r_bar);
    volume[e] = measure * w;
    if (!(measure > 0.0) || !std::isfinite(measure) || (axisymmetric_ && !(r_bar > 0.0)))
      throw InputError(
          SourceLocation{{}, 0, 0, "mesh"},
          fmt::format("element {} is inverted or degenerate ({} {:.6g}{}); {}", e + 1,
                      D == 2 ? "area" : "volume", measure,
                      axisymmetric_ && !(r_bar > 0.0) ? ", centre at r <= 0" : "",
                      D == 2 ? "quad nodes must run counter-clockwise"
                             : "hex nodes: bottom face counter-clockwise seen from above, then top"));
    const double l = Shape<D>::length(x, measure);
    length[e] = l;
  }
  node_count_ = coordinates.size() / D;
  colour_if_needed();
}

template <int D>
double FemElements<D>::volume_of(const double* x, std::size_t e) const {
  NodeValues<D> xe, b;
  gather<D>(x, &connectivity[e * nodes], xe);
  double r_bar = 0.0;
  const double w = ring_weight<D>(axisymmetric_, xe, r_bar);
  return Shape<D>::gradients(xe, b) * w;
}

template <int D>
void FemElements<D>::set_subzonal_pressure(const std::vector<double>& kappa, const double* x) {
  const std::size_t n = size();
  if (kappa.size() != n)
    throw std::logic_error(fmt::format("set_subzonal_pressure: {} coefficients for {} elements", kappa.size(), n));
  if (std::none_of(kappa.begin(), kappa.end(), [](double k) { return k > 0.0; })) {
    subzonal_coefficient.clear();
    subzone_fraction.clear(), subzone_pressure.clear(), subzone_volume.clear();
    return;
  }
  subzonal_coefficient = kappa;
  subzone_fraction.assign(n * nodes, 0.0);
  subzone_pressure.assign(n * nodes, 0.0);
  subzone_volume.assign(n * nodes, 0.0);
  for (std::size_t e = 0; e < n; ++e) {
    if (!(kappa[e] > 0.0)) continue;
    NodeValues<D> xe;
    gather<D>(x, &connectivity[e * nodes], xe);
    double v[nodes];
    subzone_volumes<D>(xe, axisymmetric_ && !area_form(e), v);  // the r-z area form: areas
    double total = 0.0;
    for (int s = 0; s < nodes; ++s) total += v[s];
    for (int s = 0; s < nodes; ++s) {
      if (!(v[s] > 0.0))
        throw InputError(SourceLocation{{}, 0, 0, "mesh"},
                         fmt::format("element {}: the subzone of its node {} has volume {:.6g} at the start "
                                     "(subzonal pressures need every corner of every element convex)",
                                     e + 1, s + 1, v[s]));
      subzone_fraction[e * nodes + static_cast<std::size_t>(s)] = v[s] / total;
      subzone_volume[e * nodes + static_cast<std::size_t>(s)] = v[s];
    }
  }
}

template <int D>
void FemElements<D>::set_viscosity_forms(std::vector<ViscosityForm> per_element) {
  if (per_element.size() != size())
    throw std::logic_error(
        fmt::format("set_viscosity_forms: {} forms for {} elements", per_element.size(), size()));
  viscosity_form = std::move(per_element);
  edge_form_anywhere =
      std::find(viscosity_form.begin(), viscosity_form.end(), ViscosityForm::edge) != viscosity_form.end();
}

template <int D>
void FemElements<D>::set_speeds(const double* v) {
  for (std::size_t e = 0; e < size(); ++e) {
    double s2 = 0.0;
    for (int a = 0; a < nodes; ++a) {
      const double* va = &v[static_cast<std::size_t>(connectivity[e * nodes + static_cast<std::size_t>(a)]) * D];
      double n2 = 0.0;
      for (int i = 0; i < D; ++i) n2 += va[i] * va[i];
      s2 = std::max(s2, n2);
    }
    speed[e] = std::sqrt(s2);
  }
}

template <int D>
void FemElements<D>::colour_if_needed() {
  const std::size_t block = colour_block_size(size());
  if (colouring_.block != block || colouring_.begin.back() * block < size())
    colouring_ = colour_elements(connectivity, nodes, node_count_, block);
}

template <int D>
void FemElements<D>::set_area_forms(std::vector<char> per_element) {
  const bool any = std::any_of(per_element.begin(), per_element.end(), [](char a) { return a != 0; });
  const bool all = std::all_of(per_element.begin(), per_element.end(), [](char a) { return a != 0; });
  area_weighted_ = any;
  if (all || !any)
    area_form_.clear();
  else
    area_form_ = std::move(per_element);
}

template <int D>
void FemElements<D>::update_ring_factors(const double* x) {
  constexpr int N = nodes;
  // m_a / M_a: the node's mass over its area mass sum_e m_e / (N 2 pi r_bar_e),
  // the mass-weighted harmonic mean of its elements' ring weights 2 pi r_bar.
  std::vector<double>& area_mass = area_mass_;  // kept between cycles: no allocation in the cycle
  area_mass.assign(node_count_, 0.0);
  ring_factor_.assign(node_count_, 0.0);
  for (std::size_t e = 0; e < size(); ++e) {
    if (eroded[e]) continue;
    const std::int64_t* c = connectivity.data() + e * N;
    double r = 0.0;
    for (int a = 0; a < N; ++a) r += x[c[a] * D];
    const double ring = two_pi * r / N;
    for (int a = 0; a < N; ++a) {
      ring_factor_[static_cast<std::size_t>(c[a])] += mass[e] / N;
      area_mass[static_cast<std::size_t>(c[a])] += mass[e] / (N * ring);
    }
  }
  for (std::size_t n = 0; n < node_count_; ++n)
    ring_factor_[n] = area_mass[n] > 0.0 ? ring_factor_[n] / area_mass[n] : 0.0;
}

template <int D>
void FemElements<D>::set_hourglass(const std::vector<HourglassControl>& per_element) {
  if (per_element.size() != size())
    throw std::logic_error(
        fmt::format("set_hourglass: {} controls for {} elements", per_element.size(), size()));
  hourglass_coefficient.resize(size());
  hourglass_stiffness.resize(size());
  for (std::size_t e = 0; e < size(); ++e) {
    const HourglassControl& h = per_element[e];
    hourglass_coefficient[e] = h.form == HourglassForm::none ? 0.0 : h.coefficient;
    hourglass_stiffness[e] = h.form == HourglassForm::stiffness ? 1 : 0;
  }
  stiffness_anywhere = false;
  for (std::size_t e = 0; e < size(); ++e)
    stiffness_anywhere = stiffness_anywhere || (hourglass_stiffness[e] && hourglass_coefficient[e] > 0.0);
}

template <int D>
bool FemElements<D>::any_viscous_hourglass(const HourglassControl& hg) const {
  if (hourglass_coefficient.empty()) return hg.form == HourglassForm::viscous && hg.coefficient > 0.0;
  for (std::size_t e = 0; e < size(); ++e)
    if (hourglass_coefficient[e] > 0.0 && !hourglass_stiffness[e]) return true;
  return false;
}

template class FemElements<2>;
template class FemElements<3>;

}  // namespace camouflet
