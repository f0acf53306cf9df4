#include "boundary/boundary_conditions.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <unordered_map>

#include "core/parameters.hpp"

namespace camouflet {

namespace {

template <class Map>
const std::vector<std::int64_t>& find_set(const Map& sets, const BoundaryCondition& bc, const char* what) {
  const auto it = sets.find(bc.set);
  if (it != sets.end()) return it->second;
  std::vector<std::string> names;
  for (const auto& [k, v] : sets) names.push_back(k);
  const std::string guess = nearest(bc.set, names);
  throw InputError(bc.where, guess.empty()
                                 ? fmt::format("unknown {} '{}'", what, bc.set)
                                 : fmt::format("unknown {} '{}'; did you mean '{}'?", what, bc.set, guess));
}

}  // namespace

template <int D>
BoundaryConditions<D>::BoundaryConditions(const Model& model)
    : axisymmetric_(model.run.mode == GeometryMode::axisymmetric) {
  for (const auto& bc : model.boundaries) {
    int history = -1;
    if (bc.history) {
      histories_.push_back(*bc.history);
      history = static_cast<int>(histories_.size()) - 1;
    }
    switch (bc.kind) {
      case BoundaryKind::fixed:
        for (auto n : find_set(model.mesh.node_sets, bc, "node set"))
          for (int i = 0; i < D; ++i) components_.push_back({n, i, 0.0, -1});
        break;
      case BoundaryKind::velocity:
        for (auto n : find_set(model.mesh.node_sets, bc, "node set"))
          for (int i = 0; i < D; ++i)
            if (bc.components[static_cast<std::size_t>(i)])
              components_.push_back({n, i, bc.value[static_cast<std::size_t>(i)], history});
        break;
      case BoundaryKind::axis:
        if (!axisymmetric_) throw InputError(bc.where, "an axis boundary needs geometry mode 'axisymmetric'");
        for (auto n : find_set(model.mesh.node_sets, bc, "node set")) components_.push_back({n, 0, 0.0, -1});
        break;
      case BoundaryKind::symmetry: {
        std::array<double, D> normal{};
        double len = 0.0;
        for (int i = 0; i < D; ++i) {
          normal[static_cast<std::size_t>(i)] = bc.normal[static_cast<std::size_t>(i)];
          len += normal[static_cast<std::size_t>(i)] * normal[static_cast<std::size_t>(i)];
        }
        if (!(len > 0.0)) throw InputError(bc.where, "a symmetry plane needs a non-zero normal");
        len = std::sqrt(len);
        int axis = -1, nonzero = 0;
        for (int i = 0; i < D; ++i) {
          normal[static_cast<std::size_t>(i)] /= len;
          if (normal[static_cast<std::size_t>(i)] != 0.0) {
            axis = i;
            ++nonzero;
          }
        }
        for (auto n : find_set(model.mesh.node_sets, bc, "node set")) {
          if (nonzero == 1)
            components_.push_back({n, axis, 0.0, -1});  // plane normal to an axis: one component
          else
            planes_.push_back({n, normal});
        }
        break;
      }
      case BoundaryKind::pressure: {
        Load load;
        load.faces = find_set(model.mesh.face_sets, bc, "face set");
        load.pressure = bc.value[0];
        load.history = history;
        loads_.push_back(std::move(load));
        break;
      }
      case BoundaryKind::transmitting:
        break;  // dashpots on faces: boundary/transmitting_boundary.hpp
    }
  }
  orthogonalise_planes();
}

// constrain() removes the planes' normal components one after another and then
// sets the components. That is the projection onto the intersection of the
// constraints only if the normals of one node are orthonormal and orthogonal to
// its constrained axes: a node on two planes at an angle other than 90 degrees
// (the edge of a conical sector) would otherwise leave the first plane again.
// So each node's normals are replaced by their Gram-Schmidt basis, taken after
// the axes it has components on; a normal in the span of the earlier ones adds
// no constraint and is dropped.
template <int D>
void BoundaryConditions<D>::orthogonalise_planes() {
  std::unordered_map<std::int64_t, std::vector<std::array<double, D>>> basis;
  for (const Component& c : components_) {
    std::array<double, D> axis{};
    axis[static_cast<std::size_t>(c.component)] = 1.0;
    basis[c.node].push_back(axis);
  }
  std::vector<Plane> kept;
  kept.reserve(planes_.size());
  for (Plane p : planes_) {
    auto& earlier = basis[p.node];
    for (const auto& b : earlier) {
      double dot = 0.0;
      for (int i = 0; i < D; ++i) dot += p.normal[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(i)];
      for (int i = 0; i < D; ++i) p.normal[static_cast<std::size_t>(i)] -= dot * b[static_cast<std::size_t>(i)];
    }
    double len = 0.0;
    for (int i = 0; i < D; ++i) len += p.normal[static_cast<std::size_t>(i)] * p.normal[static_cast<std::size_t>(i)];
    len = std::sqrt(len);
    if (len < 1e-9) continue;  // already constrained by the earlier ones
    for (int i = 0; i < D; ++i) p.normal[static_cast<std::size_t>(i)] /= len;
    earlier.push_back(p.normal);
    kept.push_back(p);
  }
  planes_ = std::move(kept);
}

template <int D>
double BoundaryConditions<D>::scale(int history, double time) const {
  return history < 0 ? 1.0 : histories_[static_cast<std::size_t>(history)].at(time);
}

template <int D>
void BoundaryConditions<D>::add_loads(const double* x, double time, double* f, const double* ring_factor) {
  load_forces_.swap(load_forces_previous_);
  load_forces_.clear();
  for (const auto& load : loads_) {
    const double p = load.pressure * scale(load.history, time);
    if constexpr (D == 2) {
      for (std::size_t k = 0; k + 1 < load.faces.size(); k += 2) {
        const std::int64_t a = load.faces[k], b = load.faces[k + 1];
        const double ra = x[a * 2], za = x[a * 2 + 1], rb = x[b * 2], zb = x[b * 2 + 1];
        // Outward normal times face length, (dy, -dx) for faces oriented counter-clockwise.
        const double nx = zb - za, ny = -(rb - ra);
        double wa = 0.5, wb = 0.5;
        if (axisymmetric_) {
          // Consistent ring weights for r varying linearly along the face: 2 pi (2 r_a + r_b) / 6.
          wa = 2.0 * std::numbers::pi * (2.0 * ra + rb) / 6.0;
          wb = 2.0 * std::numbers::pi * (ra + 2.0 * rb) / 6.0;
          if (ring_factor) {
            wa = 0.5 * ring_factor[a];
            wb = 0.5 * ring_factor[b];
          }
        }
        load_forces_.push_back({a, {-p * nx * wa, -p * ny * wa}});
        load_forces_.push_back({b, {-p * nx * wb, -p * ny * wb}});
      }
    } else {
      for (std::size_t k = 0; k + 3 < load.faces.size(); k += 4) {
        const std::int64_t* q = &load.faces[k];
        double d1[3], d2[3];
        for (int i = 0; i < 3; ++i) {
          d1[i] = x[q[2] * 3 + i] - x[q[0] * 3 + i];
          d2[i] = x[q[3] * 3 + i] - x[q[1] * 3 + i];
        }
        // Area vector of the (possibly warped) quad: half the cross product of its diagonals.
        const std::array<double, 3> s{0.5 * (d1[1] * d2[2] - d1[2] * d2[1]),
                                      0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                                      0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
        for (int a = 0; a < 4; ++a)
          load_forces_.push_back({q[a], {-0.25 * p * s[0], -0.25 * p * s[1], -0.25 * p * s[2]}});
      }
    }
  }
  for (const auto& lf : load_forces_)
    for (int i = 0; i < D; ++i) f[lf.node * D + i] += lf.force[static_cast<std::size_t>(i)];
}

template <int D>
double BoundaryConditions<D>::load_work(const double* v_old, double dt_old) const {
  double work = 0.0;
  for (std::size_t j = 0; j < load_forces_.size(); ++j) {
    const LoadForce& now = load_forces_[j];
    const bool has_previous = j < load_forces_previous_.size();
    for (int i = 0; i < D; ++i) {
      const double f_prev = has_previous ? load_forces_previous_[j].force[static_cast<std::size_t>(i)] : 0.0;
      work += 0.5 * (f_prev + now.force[static_cast<std::size_t>(i)]) * v_old[now.node * D + i] * dt_old;
    }
  }
  return work;
}

template <int D>
double BoundaryConditions<D>::constrain(double* v, const double* v_old, const double* node_mass, double time,
                                        double dt_old, double dt_mean, const char* owned) {
  const std::size_t n_reactions = components_.size() + planes_.size() * D;
  if (reaction_previous_.size() != n_reactions) reaction_previous_.assign(n_reactions, 0.0);
  double work = 0.0;
  std::size_t r = components_.size();
  for (const auto& p : planes_) {
    double vn = 0.0;
    for (int i = 0; i < D; ++i) vn += v[p.node * D + i] * p.normal[static_cast<std::size_t>(i)];
    for (int i = 0; i < D; ++i, ++r) {
      const std::int64_t k = p.node * D + i;
      const double dv = -vn * p.normal[static_cast<std::size_t>(i)];
      v[k] += dv;
      const double reaction = dt_mean > 0.0 ? node_mass[p.node] * dv / dt_mean : 0.0;
      if (!owned || owned[p.node]) work += 0.5 * (reaction_previous_[r] + reaction) * v_old[k] * dt_old;
      reaction_previous_[r] = reaction;
    }
  }
  r = 0;
  for (const auto& c : components_) {
    const std::int64_t k = c.node * D + c.component;
    const double target = c.value * scale(c.history, time);
    const double reaction = dt_mean > 0.0 ? node_mass[c.node] * (target - v[k]) / dt_mean : 0.0;
    v[k] = target;
    if (!owned || owned[c.node]) work += 0.5 * (reaction_previous_[r] + reaction) * v_old[k] * dt_old;
    reaction_previous_[r++] = reaction;
  }
  return work;
}

template <int D>
void BoundaryConditions<D>::constrain(double* v, double time) const {
  for (const auto& p : planes_) {
    double vn = 0.0;
    for (int i = 0; i < D; ++i) vn += v[p.node * D + i] * p.normal[static_cast<std::size_t>(i)];
    for (int i = 0; i < D; ++i) v[p.node * D + i] -= vn * p.normal[static_cast<std::size_t>(i)];
  }
  for (const auto& c : components_) v[c.node * D + c.component] = c.value * scale(c.history, time);
}

template class BoundaryConditions<2>;
template class BoundaryConditions<3>;

}  // namespace camouflet
