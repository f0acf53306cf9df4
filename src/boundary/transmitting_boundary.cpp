#include "boundary/transmitting_boundary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camouflet {

namespace {

// Index of the element holding all nodes of a face, or -1.
std::int64_t element_of_face(const std::vector<std::vector<std::size_t>>& node_elements,
                             const std::int64_t* face, int face_nodes,
                             const std::vector<std::int64_t>& connectivity, int nodes_per_element) {
  for (std::size_t e : node_elements[static_cast<std::size_t>(face[0])]) {
    const auto* conn = &connectivity[e * static_cast<std::size_t>(nodes_per_element)];
    bool all = true;
    for (int a = 1; a < face_nodes && all; ++a)
      all = std::find(conn, conn + nodes_per_element, face[a]) != conn + nodes_per_element;
    if (all) return static_cast<std::int64_t>(e);
  }
  return -1;
}

}  // namespace

template <int D>
TransmittingBoundary<D>::TransmittingBoundary(const Model& model, const FemElements<D>& elements)
    : axisymmetric_(model.run.mode == GeometryMode::axisymmetric) {
  constexpr int F = D == 2 ? 2 : 4;
  constexpr int N = FemElements<D>::nodes;
  std::vector<std::vector<std::size_t>> node_elements;
  for (const BoundaryCondition& bc : model.boundaries) {
    if (bc.kind != BoundaryKind::transmitting) continue;
    const auto set = model.mesh.face_sets.find(bc.set);
    if (set == model.mesh.face_sets.end()) {
      bool particles = false;  // a name of an SPH part: no faces to put dashpots on
      for (const Part& p : model.parts)
        if (p.kind == PartKind::sph && bc.set.rfind(p.name, 0) == 0) particles = true;
      throw InputError(bc.where,
                       particles ? fmt::format("set '{}': transmitting boundaries are not supported on "
                                               "SPH particle parts (only on FEM face sets)",
                                               bc.set)
                                 : fmt::format("unknown face set '{}' for a transmitting boundary", bc.set));
    }
    if (node_elements.empty()) {
      node_elements.resize(model.mesh.node_count());
      for (std::size_t e = 0; e < elements.size(); ++e)
        for (int a = 0; a < N; ++a)
          node_elements[static_cast<std::size_t>(elements.connectivity[e * N + static_cast<std::size_t>(a)])]
              .push_back(e);
    }
    const auto& list = set->second;
    for (std::size_t k = 0; k + F - 1 < list.size(); k += F) {
      Face face{};
      std::copy(list.begin() + static_cast<std::ptrdiff_t>(k),
                list.begin() + static_cast<std::ptrdiff_t>(k + F), face.nodes.begin());
      const std::int64_t e = element_of_face(node_elements, face.nodes.data(), F, elements.connectivity, N);
      if (e < 0)
        throw InputError(bc.where,
                         fmt::format("face {} of set '{}' is not the face of an element", k / F + 1, bc.set));
      face.element = static_cast<std::size_t>(e);
      faces_.push_back(face);
    }
  }
  active_ = !faces_.empty();
}

template <int D>
void TransmittingBoundary<D>::share_nodes(const NodeSharing* sharing, std::size_t node_count) {
  sharing_ = sharing;
  if (!sharing) return;
  // A face set cut to this rank may be empty while another rank's is not (every rank reads the
  // same conditions): any transmitting condition makes every rank take part.
  active_ = true;
  shared_damping_.assign(node_count * D * D, 0.0);
}

template <int D>
void TransmittingBoundary<D>::damp(const double* x, const double* v_old, double* v, const double* node_mass,
                                     const FemElements<D>& elements,
                                     const std::vector<MaterialPoints>& batches, double dt) {
  constexpr int F = D == 2 ? 2 : 4;
  if (!collected_) collect_nodes();
  for (auto& c : damping_) c.fill(0.0);
  for (const Face& face : faces_) {
    const MaterialPoints& pts = batches[static_cast<std::size_t>(elements.material[face.element])];
    const std::size_t p = elements.point[face.element];
    const double rho = pts.density[p];
    const double c_p = pts.wave_speed(p);
    const double c_s = rho > 0.0 ? std::sqrt(std::max(pts.shear_modulus[p], 0.0) / rho) : 0.0;
    // Area vector s (outward normal times area) and the nodal weights w_a (sum 1 in
    // plane / 3-D, sum 2 pi r_mean in axisymmetric mode).
    std::array<double, D> s{};
    std::array<double, F> w{};
    const auto& q = face.nodes;
    if constexpr (D == 2) {
      const double ra = x[q[0] * 2], za = x[q[0] * 2 + 1], rb = x[q[1] * 2], zb = x[q[1] * 2 + 1];
      s = {zb - za, -(rb - ra)};  // counter-clockwise faces: outward normal times length
      w = {0.5, 0.5};
      if (axisymmetric_ && elements.area_weighted_momentum()) {
        // As the element forces at these nodes: the planar share times the ring factor m_a / M_a.
        const std::vector<double>& ring = elements.ring_factors();
        w = {0.5 * ring[static_cast<std::size_t>(q[0])], 0.5 * ring[static_cast<std::size_t>(q[1])]};
      } else if (axisymmetric_) {
        w = {2.0 * std::numbers::pi * (2.0 * ra + rb) / 6.0, 2.0 * std::numbers::pi * (ra + 2.0 * rb) / 6.0};
      }
    } else {
      double d1[3], d2[3];
      for (int i = 0; i < 3; ++i) {
        d1[i] = x[q[2] * 3 + i] - x[q[0] * 3 + i];
        d2[i] = x[q[3] * 3 + i] - x[q[1] * 3 + i];
      }
      s = {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]), 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
           0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
      w = {0.25, 0.25, 0.25, 0.25};
    }
    double area = 0.0;
    for (int i = 0; i < D; ++i) area += s[static_cast<std::size_t>(i)] * s[static_cast<std::size_t>(i)];
    area = std::sqrt(area);
    if (!(area > 0.0)) continue;
    std::array<double, D> n{};
    for (int i = 0; i < D; ++i) n[static_cast<std::size_t>(i)] = s[static_cast<std::size_t>(i)] / area;
    for (int a = 0; a < F; ++a) {
      const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), q[static_cast<std::size_t>(a)]);
      auto& c = damping_[static_cast<std::size_t>(it - nodes_.begin())];
      const double weight =
          w[static_cast<std::size_t>(a)] * area * rho;  // kg/m^3 m^2 (plane strain: per metre)
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          const double nn = n[static_cast<std::size_t>(i)] * n[static_cast<std::size_t>(j)];
          c[static_cast<std::size_t>(i * D + j)] += weight * (c_p * nn + c_s * ((i == j ? 1.0 : 0.0) - nn));
        }
    }
  }
  if (sharing_) {  // a node on a cut: every rank's faces' damping, added up over its holders
    constexpr std::size_t DD = D * D;
    for (std::size_t k = 0; k < nodes_.size(); ++k)
      std::copy(damping_[k].begin(), damping_[k].end(), &shared_damping_[static_cast<std::size_t>(nodes_[k]) * DD]);
    sharing_->sum_shared(shared_damping_, D * D);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      double* c = &shared_damping_[static_cast<std::size_t>(nodes_[k]) * DD];
      std::copy(c, c + DD, damping_[k].begin());
      std::fill(c, c + DD, 0.0);
    }
  }
  // (m I + dt/2 C) v+ = m v_free - dt/2 C v-, node by node.
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const std::int64_t node = nodes_[k];
    const double m = node_mass[node];
    if (!(m > 0.0)) continue;
    const auto& c = damping_[k];
    double a[D][D], rhs[D];
    for (int i = 0; i < D; ++i) {
      rhs[i] = m * v[node * D + i];
      for (int j = 0; j < D; ++j) {
        a[i][j] = (i == j ? m : 0.0) + 0.5 * dt * c[static_cast<std::size_t>(i * D + j)];
        rhs[i] -= 0.5 * dt * c[static_cast<std::size_t>(i * D + j)] * v_old[node * D + j];
      }
    }
    double sol[D];
    if constexpr (D == 2) {
      const double det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
      sol[0] = (rhs[0] * a[1][1] - a[0][1] * rhs[1]) / det;
      sol[1] = (a[0][0] * rhs[1] - rhs[0] * a[1][0]) / det;
    } else {
      const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
      for (int col = 0; col < 3; ++col) {
        double b[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) b[i][j] = j == col ? rhs[i] : a[i][j];
        sol[col] = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                    b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                    b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0])) /
                   det;
      }
    }
    // Dashpot force at t_n, -C v_n; its work over the step once the constraints have acted
    // (work()): on a node a constraint holds too, the velocity the dashpot's impulse leaves is
    // not the one the node moves with.
    double v_mid[D];
    for (int i = 0; i < D; ++i) v_mid[i] = 0.5 * (v_old[node * D + i] + sol[i]);
    for (int i = 0; i < D; ++i) {
      double f = 0.0;
      for (int j = 0; j < D; ++j) f -= c[static_cast<std::size_t>(i * D + j)] * v_mid[j];
      force_[k][i] = f;
      v[node * D + i] = sol[i];
    }
  }
}

template <int D>
double TransmittingBoundary<D>::work(const double* v_old, const double* v, double dt) const {
  const char* owned = sharing_ ? sharing_->owned_nodes().data() : nullptr;
  double work = 0.0;
  for (std::size_t k = 0; k < force_.size(); ++k) {
    const std::int64_t node = nodes_[k];
    if (owned && !owned[node]) continue;
    for (int i = 0; i < D; ++i) work += force_[k][i] * (0.5 * (v_old[node * D + i] + v[node * D + i])) * dt;
  }
  return work;
}

template <int D>
void TransmittingBoundary<D>::collect_nodes() {
  collected_ = true;
  for (const Face& face : faces_) nodes_.insert(nodes_.end(), face.nodes.begin(), face.nodes.end());
  if (sharing_) {  // and the shared nodes another rank's faces hold
    const std::size_t nn = shared_damping_.size() / (D * D);
    std::vector<double> on_face(nn, 0.0);
    for (const std::int64_t n : nodes_) on_face[static_cast<std::size_t>(n)] = 1.0;
    sharing_->sum_shared(on_face, 1);
    for (std::size_t n = 0; n < nn; ++n)
      if (on_face[n] > 0.0) nodes_.push_back(static_cast<std::int64_t>(n));
  }
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  damping_.resize(nodes_.size());
  force_.assign(nodes_.size(), {});
}

template <int D>
void TransmittingBoundary<D>::hold_initial_state(const double* unbalanced) {
  if (!collected_) collect_nodes();
  // The removed soil's traction sigma . n A on the face, lumped to the nodes as the element
  // forces are: taken as the nodal residual, it also carries the boundary half-elements' weight.
  static_force_.assign(nodes_.size(), {});
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    for (int i = 0; i < D; ++i) static_force_[k][i] = -unbalanced[nodes_[k] * D + i];
}

template <int D>
void TransmittingBoundary<D>::visit_state(StateVisitor& v) {
  StateScope scope(v, "transmitting");
  visit(v, "static_force", static_force_);
}

template <int D>
void TransmittingBoundary<D>::hold_still(double* v) {
  if (!collected_) collect_nodes();
  for (const std::int64_t n : nodes_)
    for (int i = 0; i < D; ++i) v[n * D + i] = 0.0;
}

template <int D>
double TransmittingBoundary<D>::add_static_forces(const double* v_old, double dt_old, double* f) const {
  const char* owned = sharing_ ? sharing_->owned_nodes().data() : nullptr;
  double work = 0.0;
  for (std::size_t k = 0; k < static_force_.size(); ++k)
    for (int i = 0; i < D; ++i) {
      const double fi = static_force_[k][i];
      f[nodes_[k] * D + i] += fi;
      if (!owned || owned[nodes_[k]]) work += fi * v_old[nodes_[k] * D + i] * dt_old;
    }
  return work;
}

template class TransmittingBoundary<2>;
template class TransmittingBoundary<3>;

}  // namespace camouflet
