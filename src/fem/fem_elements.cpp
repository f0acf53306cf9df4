#include "fem/fem_elements.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include "core/error.hpp"
#include "fem/element_pack.hpp"
#include "fem/parallel.hpp"
#include "fem/shape.hpp"
#if defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace camouflet {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

std::atomic<ForceAssembly> default_assembly{ForceAssembly::colour_blocks};

template <int D>
using NodeValues = double[D][Shape<D>::nodes];

template <int D>
inline void gather(const double* field, const std::int64_t* conn, NodeValues<D>& out) {
  for (int a = 0; a < Shape<D>::nodes; ++a)
    for (int i = 0; i < D; ++i) out[i][a] = field[conn[a] * D + i];
}

// Axisymmetric volume weight 2 pi r_bar (r_bar = mean nodal radius, the
// centre of the one-point element); 1 otherwise.
template <int D>
inline double ring_weight(bool axisymmetric, const NodeValues<D>& x, double& r_bar) {
  if constexpr (D == 2) {
    if (axisymmetric) {
      r_bar = 0.25 * (x[0][0] + x[0][1] + x[0][2] + x[0][3]);
      return two_pi * r_bar;
    }
  }
  r_bar = 0.0;
  return 1.0;
}

template <int D>
using PackedNodes = Pack[D][Shape<D>::nodes];

// The elements of one pack: lane l holds element at(l); lanes past `count`
// repeat the last element (computed, never scattered). Consecutive packs
// (the buffer assembly) load element arrays as whole packs; listed packs
// (one colour's elements, element_colouring.hpp) lane by lane.
struct ConsecutiveLanes {
  static constexpr bool consecutive = true;
  std::size_t first;
  int count;
  std::size_t at(int l) const { return first + static_cast<std::size_t>(l < count ? l : count - 1); }
};
struct ListedLanes {
  static constexpr bool consecutive = false;
  const std::uint32_t* element;
  int count;
  std::size_t at(int l) const { return element[l < count ? l : count - 1]; }
};

// Lane l <- element lanes.at(l). Gathers F node fields (positions,
// velocities) at once, so that each node's numbers are fetched once for all.
template <int D, int F, class Lanes>
inline void gather_packs(const double* const (&field)[F], const std::int64_t* connectivity,
                         const Lanes& lanes, PackedNodes<D>* const (&out)[F]) {
  constexpr int N = Shape<D>::nodes;
#if defined(__AVX512F__)
  // One 8-lane gather of node a's numbers (lane l: row of element at(l)), then
  // one 8-lane gather per field and component straight into the pack: no
  // lane-by-lane stores read back as a whole register.
  const std::int64_t* conn = connectivity;
  __m512i row;
  if (Lanes::consecutive && lanes.count == pack_width) {
    conn += lanes.at(0) * N;
    row = _mm512_set_epi64(7 * N, 6 * N, 5 * N, 4 * N, 3 * N, 2 * N, N, 0);
  } else {
    alignas(64) std::int64_t rows[pack_width];
    for (int l = 0; l < pack_width; ++l) rows[l] = static_cast<std::int64_t>(lanes.at(l)) * N;
    row = _mm512_load_si512(rows);
  }
  // The masked forms with an explicit source: the plain ones pass an
  // undefined register that GCC 12 warns about.
  for (int a = 0; a < N; ++a) {
    const __m512i node = _mm512_mask_i64gather_epi64(_mm512_setzero_si512(), 0xFF, row, conn + a, 8);
    const __m512i index = node * D;  // vector extension arithmetic
    for (int f = 0; f < F; ++f)
      for (int i = 0; i < D; ++i)
        (*out[f])[i][a] = _mm512_mask_i64gather_pd(_mm512_setzero_pd(), 0xFF, index, field[f] + i, 8);
  }
#else
  for (int f = 0; f < F; ++f) {
    alignas(sizeof(Pack)) double lanes_of[D][N][pack_width];  // the layout of PackedNodes<D>
    for (int l = 0; l < pack_width; ++l) {
      const std::int64_t* c = connectivity + lanes.at(l) * N;
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < D; ++i) lanes_of[i][a][l] = field[f][c[a] * D + i];
    }
    static_assert(sizeof lanes_of == sizeof *out[f]);
    std::memcpy(out[f], lanes_of, sizeof lanes_of);
  }
#endif
}

// An element array at the lanes' elements as a pack.
template <class Lanes>
inline Pack load_pack(const double* a, const Lanes& lanes) {
  Pack p;
  if (Lanes::consecutive && lanes.count == pack_width) {
    std::memcpy(&p, a + lanes.at(0), sizeof p);
  } else {
    for (int l = 0; l < pack_width; ++l) p[l] = a[lanes.at(l)];
  }
  return p;
}

// Lanes e0 .. e0 + count - 1 of an element array as a pack; lanes past
// `count` repeat the last element, as in gather_packs.
inline Pack load_pack(const double* a, std::size_t e0, int count) {
  return load_pack(a, ConsecutiveLanes{e0, count});
}

// All pack_width lanes of p into a[e0 ..].
inline void store_pack(double* a, std::size_t e0, const Pack& p) {
  std::memcpy(a + e0, &p, sizeof p);
}

template <int D>
inline Pack ring_weight_pack(bool axisymmetric, const PackedNodes<D>& x, Pack& r_bar) {
  if constexpr (D == 2) {
    if (axisymmetric) {
      r_bar = 0.25 * (x[0][0] + x[0][1] + x[0][2] + x[0][3]);
      return two_pi * r_bar;
    }
  }
  r_bar = Pack{};
  return broadcast(1.0);
}

// gamma_alpha,a = Gamma_alpha,a - (Gamma_alpha . x_i) b_ia: the hourglass shape
// vectors orthogonal to every linear velocity field (FB 1981, eq. 56, without
// their 1/N so that the coefficient has the scale of the LS-DYNA Q_hg).
template <int D>
inline void hourglass_shapes(const PackedNodes<D>& x, const PackedNodes<D>& b,
                             Pack (&g)[Shape<D>::modes][Shape<D>::nodes]) {
  constexpr int N = Shape<D>::nodes;
  for (int m = 0; m < Shape<D>::modes; ++m) {
    Pack gx[D];
    for (int i = 0; i < D; ++i) {
      // Gamma entries are +-1: add or subtract (the same sums as with the
      // products, without the multiplications).
      gx[i] = Pack{};
      for (int a = 0; a < N; ++a) gx[i] = Shape<D>::base[m][a] > 0.0 ? gx[i] + x[i][a] : gx[i] - x[i][a];
    }
    for (int a = 0; a < N; ++a) {
      Pack v = broadcast(Shape<D>::base[m][a]);
      for (int i = 0; i < D; ++i) v -= gx[i] * b[i][a];
      g[m][a] = v;
    }
  }
}

// Number of negative corner Jacobians of a quad (2-D; nodes counter-clockwise): at corner a,
// (x_(a+1) - x_a) x (x_(a-1) - x_a). All four are positive for a convex quad, one is negative
// for a concave one, two or more once its edges cross or it is inverted. 0 in 3-D (not checked).
template <int D, typename Nodes>
int corner_jacobians_negative(const Nodes& x, int lane = -1) {
  int negative = 0;
  if constexpr (D == 2) {
    const auto at = [&](int i, int a) -> double {
      if constexpr (std::is_same_v<Nodes, PackedNodes<D>>)
        return x[i][a][lane];
      else
        return x[i][a];
    };
    for (int a = 0; a < 4; ++a) {
      const int next = (a + 1) % 4, prev = (a + 3) % 4;
      const double j = (at(0, next) - at(0, a)) * (at(1, prev) - at(1, a)) -
                       (at(1, next) - at(1, a)) * (at(0, prev) - at(0, a));
      if (j < 0.0) ++negative;
    }
  }
  return negative;
}

}  // namespace

ForceAssembly default_force_assembly() {
  return default_assembly.load();
}

void set_default_force_assembly(ForceAssembly assembly) {
  default_assembly.store(assembly);
}

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
  set_assembly(default_force_assembly());
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
void FemElements<D>::set_assembly(ForceAssembly assembly) {
  assembly_ = assembly;
  const std::size_t block = assembly == ForceAssembly::colour_blocks ? colour_block_size(size()) : 1;
  if (assembly != ForceAssembly::buffers &&
      (colouring_.block != block || colouring_.begin.back() * block < size()))
    colouring_ = colour_elements(connectivity, nodes, node_count_, block);
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
double FemElements<D>::add_internal_forces(const double* x, const double* v, double* f, double* f_hourglass,
                                           const HourglassControl& hg, double dt_previous) {
  constexpr int N = nodes;
  constexpr int W = pack_width;
  const bool axi = axisymmetric_;
  // Without per-element control, `hg` for every element: kappa 0 for "none".
  const bool own_hg = !hourglass_coefficient.empty();
  const double hg_kappa = hg.form == HourglassForm::none ? 0.0 : hg.coefficient;
  const bool hg_stiff = hg.form == HourglassForm::stiffness;
  // Whether any pack holds stiffness-form energy (the colour paths keep one sum per slot then).
  const bool any_stiff_hg = own_hg ? stiffness_anywhere : hg_stiff && hg_kappa > 0.0;
  const std::size_t ne = size();
  const bool area = axi && area_weighted_;
  if (area && ring_factor_.size() != node_count_) update_ring_factors(x);

  // One pack of elements lanes.at(0 .. count - 1) (element_pack.hpp): forces
  // computed lane-parallel, scattered into f_out (and the hourglass part into
  // fh_out) lane by lane; returns the stiffness-form hourglass energy held.
  const auto pack = [&](const auto& lanes, double* f_out, double* fh_out) {
    const int count = lanes.count;
    bool any = false;
    for (int l = 0; l < count; ++l) any = any || !eroded[lanes.at(l)];
    if (!any) return 0.0;  // an eroded element carries no force
    // The lanes' hourglass control: kappa and form per lane (the same
    // arithmetic per lane whichever forms share the pack).
    Pack kappa = broadcast(hg_kappa);
    bool stiff[W];
    bool viscous_hg = false, stiff_hg = false;
    for (int l = 0; l < W; ++l) {
      const std::size_t e = lanes.at(l);
      if (own_hg) kappa[l] = hourglass_coefficient[e];
      stiff[l] = own_hg ? hourglass_stiffness[e] != 0 : hg_stiff;
      if (l < count && kappa[l] > 0.0) (stiff[l] ? stiff_hg : viscous_hg) = true;
    }
    PackedNodes<D> xe, ve, b, fe;
    if (viscous_hg || stiff_hg)
      gather_packs<D, 2>({x, v}, connectivity.data(), lanes, {&xe, &ve});
    else
      gather_packs<D, 1>({x}, connectivity.data(), lanes, {&xe});
    const Pack measure = Shape<D>::gradients(xe, b);
    Pack r_bar{};
    const Pack w = ring_weight_pack<D>(axi, xe, r_bar);
    const Pack vol = measure * w;

    // Stress divergence: f_ia = -V sigma_ij b_ja (FB 1981, eq. 17), with q as a pressure.
    Pack sig[D][D] = {}, hoop{};
    for (int l = 0; l < W; ++l) {
      const std::size_t e = lanes.at(l);
      const SymTensor& s = stress[e];
      const double q = viscosity[e];
      sig[0][0][l] = s.xx - q;
      sig[1][1][l] = s.yy - q;
      sig[0][1][l] = sig[1][0][l] = s.xy;
      hoop[l] = s.zz - q;
      if constexpr (D == 3) {
        sig[2][2][l] = s.zz - q;
        sig[1][2][l] = sig[2][1][l] = s.yz;
        sig[0][2][l] = sig[2][0][l] = s.zx;
      }
    }
    if (!area) {
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < D; ++i) {
          Pack t{};
          for (int j = 0; j < D; ++j) t += sig[i][j] * b[j][a];
          fe[i][a] = -vol * t;
        }
    }
    if constexpr (D == 2) {
      if (axi && !area) {
        // Hoop stress: virtual power of sigma_tt against the hoop rate v_r / r_bar,
        // v_r at the centre = mean of the nodal v_r.
        const Pack hoop_force = vol * hoop / (N * r_bar);
        for (int a = 0; a < N; ++a) fe[0][a] -= hoop_force;
      } else if (area) {
        // Area-weighted momentum (Wilkins 1964): the planar divergence of
        // sigma over the area, the sources (sigma_rr - sigma_tt) / r and
        // sigma_rz / r shared equally, and each node's sum scaled by its ring
        // factor m_a / M_a, so that the acceleration is the area force over
        // the area mass M_a (q cancels from the r source: it is planar only).
        const Pack source_r = measure * (sig[0][0] - hoop) / (N * r_bar);
        const Pack source_z = measure * sig[1][0] / (N * r_bar);
        for (int a = 0; a < N; ++a) {
          Pack ring;
          for (int l = 0; l < W; ++l)
            ring[l] = ring_factor_[static_cast<std::size_t>(
                connectivity[lanes.at(l) * N + static_cast<std::size_t>(a)])];
          for (int i = 0; i < D; ++i) {
            Pack t{};
            for (int j = 0; j < D; ++j) t += sig[i][j] * b[j][a];
            fe[i][a] = ring * (-measure * t + (i == 0 ? source_r : source_z));
          }
        }
      }
    }

    double stored = 0.0;
    PackedNodes<D> fh;
    if (viscous_hg || stiff_hg) {
      Pack g[Shape<D>::modes][N];
      hourglass_shapes<D>(xe, b, g);
      // Viscous: a_h = kappa rho c l^(D-1) / 4 (FB 1981, eq. 60; the LS-DYNA
      // form Q_hg rho V^(2/3) c / 4 in 3-D); stiffness: k = kappa rho c^2 l^(D-2) / 4.
      // l = V / largest face, from the last kinematics (same geometry).
      const Pack rho = load_pack(density.data(), lanes), c = load_pack(wave_speed.data(), lanes),
                 le = load_pack(length.data(), lanes);
      Pack coef;
      if (!stiff_hg) {
        coef = 0.25 * kappa * rho * c * (D == 2 ? le : le * le);
      } else if (!viscous_hg) {
        coef = 0.25 * kappa * rho * c * c * (D == 2 ? broadcast(1.0) : le);
      } else {  // both forms in this pack (parts meet in it)
        Pack stiff_lanes{};
        for (int l = 0; l < W; ++l) stiff_lanes[l] = stiff[l] ? 1.0 : 0.0;
        const Pack viscous_coef = 0.25 * kappa * rho * c * (D == 2 ? le : le * le);
        const Pack stiff_coef = 0.25 * kappa * rho * c * c * (D == 2 ? broadcast(1.0) : le);
        coef = stiff_lanes > 0.0 ? stiff_coef : viscous_coef;
      }
      coef *= w;
      // All mode amplitudes first, then each force component as one sum over
      // the modes (in mode order, as before), held in registers rather than
      // accumulated in memory mode by mode.
      Pack scaled[Shape<D>::modes][D];
      for (int m = 0; m < Shape<D>::modes; ++m)
        for (int i = 0; i < D; ++i) {
          Pack rate{};
          for (int a = 0; a < N; ++a) rate += g[m][a] * ve[i][a];
          Pack amplitude = rate;
          if (stiff_hg) {
            for (int l = 0; l < count; ++l) {
              if (!stiff[l]) continue;
              const std::size_t e = lanes.at(l);
              double& hd = hourglass_displacement[e * modes * D + static_cast<std::size_t>(m * D + i)];
              if (!eroded[e]) hd += rate[l] * dt_previous;
              amplitude[l] = hd;
              if (!eroded[e]) stored += 0.5 * coef[l] * hd * hd;
            }
          }
          scaled[m][i] = coef * amplitude;
        }
      for (int i = 0; i < D; ++i)
        for (int a = 0; a < N; ++a) {
          Pack h{};
          for (int m = 0; m < Shape<D>::modes; ++m) h -= scaled[m][i] * g[m][a];
          fh[i][a] = h;
          fe[i][a] += h;
        }
    }

    // Lane by lane, node by node: the node's D force values and, when asked
    // for, its D hourglass values at one computed address (each array sees its
    // additions in the same order as before).
    // Only the viscous form's forces go to fh_out: the stiffness form's
    // energy is held as a state (the return value), not integrated as work.
    const bool scatter_hourglass = fh_out && viscous_hg;
    for (int l = 0; l < count; ++l) {
      const std::size_t e = lanes.at(l);
      if (eroded[e]) continue;
      const std::int64_t* c = connectivity.data() + e * N;
      const bool scatter_lane = scatter_hourglass && !stiff[l];
      for (int a = 0; a < N; ++a) {
        const std::int64_t k = c[a] * D;
        double* fk = f_out + k;
        for (int i = 0; i < D; ++i) fk[i] += fe[i][a][l];
        if (scatter_lane) {
          double* hk = fh_out + k;
          for (int i = 0; i < D; ++i) hk[i] += fh[i][a][l];
        }
      }
    }
    return stored;
  };
  const auto consecutive = [&](std::int64_t k) {
    const std::size_t e0 = static_cast<std::size_t>(k) * W;
    return ConsecutiveLanes{e0, static_cast<int>(std::min<std::size_t>(W, ne - e0))};
  };

  const int team = static_cast<std::int64_t>(ne) > parallel_threshold ? omp_get_max_threads() : 1;
  if (assembly_ != ForceAssembly::buffers) {
    // One colour after the other, the packs (colours) or blocks (colour_blocks) of a colour
    // shared out among the threads and scattered straight into f: no two of a colour share a
    // node, so each node gets its contributions in colour order whatever the thread count (the
    // barrier at the end of each colour's loop keeps the colours apart).
    set_assembly(assembly_);  // the colouring, if not made yet
    const std::size_t colours = colouring_.colours(), block = colouring_.block;
    const bool single = block == 1;
    // Slots of a colour: its packs of single elements, or its blocks.
    const auto slots = [&](std::size_t c) {
      const std::size_t count = colouring_.begin[c + 1] - colouring_.begin[c];
      return single ? (count + W - 1) / W : count;
    };
    if (any_stiff_hg) {
      std::size_t all = 0;
      for (std::size_t c = 0; c < colours; ++c) all += slots(c);
      pack_stored_.assign(all, 0.0);
    }
    const std::uint32_t* const listed = colouring_.blocks.data();
#pragma omp parallel num_threads(team) if (team > 1)
    {
      std::size_t slot_base = 0;  // first slot of colour c among all colours' slots
      for (std::size_t c = 0; c < colours; ++c) {
        const std::size_t first = colouring_.begin[c], count = colouring_.begin[c + 1] - first;
        const std::int64_t n_slots = static_cast<std::int64_t>(slots(c));
#pragma omp for schedule(static)
        for (std::int64_t k = 0; k < n_slots; ++k) {
          double held = 0.0;
          if (single) {
            const std::size_t offset = static_cast<std::size_t>(k) * W;
            held = pack(ListedLanes{listed + first + offset,
                                    static_cast<int>(std::min<std::size_t>(W, count - offset))},
                        f, f_hourglass);
          } else {
            const std::size_t e_begin = listed[first + static_cast<std::size_t>(k)] * block;
            const std::size_t e_end = std::min(ne, e_begin + block);
            for (std::size_t e0 = e_begin; e0 < e_end; e0 += W)
              held += pack(ConsecutiveLanes{e0, static_cast<int>(std::min<std::size_t>(W, e_end - e0))}, f,
                           f_hourglass);
          }
          if (any_stiff_hg) pack_stored_[slot_base + static_cast<std::size_t>(k)] = held;
        }
        slot_base += static_cast<std::size_t>(n_slots);
      }
    }
    double stored = 0.0;
    for (const double held : pack_stored_) stored += held;  // slot order: any thread count, the same sum
    if (!any_stiff_hg) pack_stored_.clear();
    return stored;
  }

  const std::int64_t packs = static_cast<std::int64_t>((ne + W - 1) / W);
  double stored = 0.0;
  if (team == 1) {
    for (std::int64_t k = 0; k < packs; ++k) stored += pack(consecutive(k), f, f_hourglass);
    return stored;
  }
  // Race-free assembly: thread 0 scatters into f, thread t > 0 into its own
  // zeroed buffer; the buffers are then added in thread order (deterministic
  // for a given thread count) and zeroed again for the next call.
  const std::size_t values = node_count_ * D;
  if (thread_force_.size() < static_cast<std::size_t>(team - 1)) {
    thread_force_.resize(static_cast<std::size_t>(team - 1));
    thread_hourglass_force_.resize(static_cast<std::size_t>(team - 1));
  }
  for (int t = 0; t < team - 1; ++t) {
    thread_force_[static_cast<std::size_t>(t)].resize(values, 0.0);
    if (f_hourglass) thread_hourglass_force_[static_cast<std::size_t>(t)].resize(values, 0.0);
  }
  const std::int64_t nv = static_cast<std::int64_t>(values);
#pragma omp parallel num_threads(team) reduction(+ : stored)
  {
    const int t = omp_get_thread_num();
    double* f_out = t == 0 ? f : thread_force_[static_cast<std::size_t>(t - 1)].data();
    double* fh_out = f_hourglass == nullptr ? nullptr
                     : t == 0               ? f_hourglass
                                            : thread_hourglass_force_[static_cast<std::size_t>(t - 1)].data();
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < packs; ++k) stored += pack(consecutive(k), f_out, fh_out);
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < nv; ++k) {
      for (int s = 0; s < team - 1; ++s) {
        double& buffer = thread_force_[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)];
        f[k] += buffer;
        buffer = 0.0;
        if (f_hourglass) {
          double& hb = thread_hourglass_force_[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)];
          f_hourglass[k] += hb;
          hb = 0.0;
        }
      }
    }
  }
  return stored;
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

template <int D>
KinematicsResult FemElements<D>::kinematics(const double* x, const double* v, const double* v_previous, double dt,
                                            const ViscosityControl& visc,
                                            std::vector<MaterialPoints>& batches) {
  constexpr int N = nodes;
  constexpr int W = pack_width;
  const bool axi = axisymmetric_;
  const std::size_t ne = size();
  const std::int64_t packs = static_cast<std::int64_t>((ne + W - 1) / W);
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
  std::int64_t tangled = std::numeric_limits<std::int64_t>::max();
  double viscous_work = 0.0;
#pragma omp parallel for schedule(static) reduction(min : bad, tangled) reduction(+ : viscous_work) if (static_cast<std::int64_t>(ne) > parallel_threshold)
  for (std::int64_t k = 0; k < packs; ++k) {
    const std::size_t e0 = static_cast<std::size_t>(k) * W;
    const int count = static_cast<int>(std::min<std::size_t>(W, ne - e0));
    bool any = false;
    for (int l = 0; l < count; ++l) any = any || !eroded[e0 + static_cast<std::size_t>(l)];
    if (!any) continue;
    PackedNodes<D> xe, ve, ae, xh, b;
    gather_packs<D, 3>({x, v, v_previous}, connectivity.data(), ConsecutiveLanes{e0, count}, {&xe, &ve, &ae});
    Pack speed2{};
    for (int a = 0; a < N; ++a) {
      Pack s2{};
      for (int i = 0; i < D; ++i) {
        xh[i][a] = xe[i][a] - 0.5 * dt * ve[i][a];
        s2 += ve[i][a] * ve[i][a];
      }
      speed2 = max_of(speed2, s2);
    }

    // Velocity gradient L_ij = sum_a v_ia b_ja on the mid-step geometry (FB 1981, eq. 14).
    Shape<D>::gradients(xh, b);
    Pack L[3][3] = {};
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) {
        Pack t{};
        for (int a = 0; a < N; ++a) t += ve[i][a] * b[j][a];
        L[i][j] = t;
      }
    if constexpr (D == 2) {
      if (axi) {
        // Hoop strain rate v_r / r at the element centre.
        Pack vr{}, r{};
        for (int a = 0; a < N; ++a) {
          vr += ve[0][a];
          r += xh[0][a];
        }
        L[2][2] = vr / r;
      }
    }

    // New volume and density at t_{n+1}.
    const Pack measure = Shape<D>::measure(xe);
    Pack r_bar{};
    const Pack w = ring_weight_pack<D>(axi, xe, r_bar);
    const Pack vol = measure * w;
    const Pack le = Shape<D>::length(xe, measure);

    // Strain rate, spin, density and q of the whole pack, lane-parallel (the
    // same operations per lane as the scalar forms they replace, so the same
    // roundings); lanes whose volume is bad are computed but never written.
    const Pack d_xy = 0.5 * (L[0][1] + L[1][0]), d_yz = 0.5 * (L[1][2] + L[2][1]),
               d_zx = 0.5 * (L[2][0] + L[0][2]);
    const Pack w_xy = 0.5 * (L[0][1] - L[1][0]), w_yz = 0.5 * (L[1][2] - L[2][1]),
               w_zx = 0.5 * (L[2][0] - L[0][2]);
    const Pack rho = load_pack(mass.data(), e0, count) / vol;
    // Artificial bulk viscosity, compression only (von Neumann-Richtmyer
    // quadratic + Landshoff linear): q = rho l (C_q^2 l |d| + C_l c) |d| with
    // d the strain rate along the element's acceleration a (Wilkins 1980,
    // J. Comput. Phys. 36, 281): d = a.L.a / |a|^2, with a the nodes' mean
    // velocity change over the step (constraints included: a driven boundary
    // orients q from its first step); 0 where no node has changed velocity
    // (the first step from an initial velocity jump takes no q). A shock
    // decelerates the material along its normal, so d is the compression
    // across it; a smooth convergent flow (a cylinder or sphere of gas
    // coasting inwards) compresses across the flow, not along a, and takes
    // no q, where tr D would heat it (docs/theory-fem.md, "Artificial
    // viscosity"). The in-plane part only in r-z: a has no hoop component.
    Pack div{};
    if (visc.along_acceleration) {
      Pack abar[D] = {}, a2{};
      for (int i = 0; i < D; ++i) {
        for (int n = 0; n < N; ++n) abar[i] += ve[i][n] - ae[i][n];
        a2 += abar[i] * abar[i];
      }
      Pack ala{};
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) ala += abar[i] * L[i][j] * abar[j];
      for (int l = 0; l < W; ++l) div[l] = a2[l] > 0.0 ? ala[l] / a2[l] : 0.0;
    } else {
      div = L[0][0] + L[1][1] + L[2][2];
    }
    const Pack q_all = rho * le *
                       (visc.quadratic * visc.quadratic * le * -div +
                        visc.linear * load_pack(wave_speed.data(), e0, count)) *
                       -div;
    const Pack q = div < 0.0 ? q_all : Pack{};
    // The force at t_n carried the previous q, the force at t_(n+1) carries
    // this one; each acts over half of this step's volume change, so the
    // energy equation is charged with their mean (time-centred q dV).
    const Pack q_mean = 0.5 * (load_pack(viscosity.data(), e0, count) + q);
    const Pack work = q_mean * (vol - load_pack(volume.data(), e0, count));
    const Pack speed_pack = sqrt_of(speed2);

    // Every lane present, valid and not eroded (the usual case): the element
    // arrays are stored as whole packs after the lane loop.
    bool whole = count == W;
    for (int l = 0; l < count && whole; ++l)
      whole = !eroded[e0 + static_cast<std::size_t>(l)] && vol[l] > 0.0 && std::isfinite(vol[l]);
    int batch_index = -1;
    double *pts_density = nullptr, *pts_density_previous = nullptr, *pts_viscosity = nullptr,
           *pts_length = nullptr;
    SymTensor* pts_strain_rate = nullptr;
    Spin* pts_spin = nullptr;
    for (int l = 0; l < count; ++l) {
      const std::size_t e = e0 + static_cast<std::size_t>(l);
      if (eroded[e]) continue;
      const double vol_l = vol[l];
      if (!(vol_l > 0.0) || !std::isfinite(vol_l)) {
        bad = std::min(bad, static_cast<std::int64_t>(e));
        continue;
      }
      if constexpr (D == 2) {
        // The one-point area is the mean of the corner Jacobians: a quad whose edges cross (top
        // nodes driven past the bottom ones on one side only) keeps a positive area while two
        // corners have turned inside out, and its forces and density are then meaningless
        // (such an element in the buried-structure case set the time step for milliseconds unnoticed).
        if (corner_jacobians_negative<D>(xe, l) >= 2)
          tangled = std::min(tangled, static_cast<std::int64_t>(e));
      }
      viscous_work -= work[l];  // element order, as the scalar sum

      // The material batch of this lane: its arrays looked up only when the
      // material changes from the previous lane (usually once per pack).
      const int m = material[e];
      if (m != batch_index) {
        batch_index = m;
        MaterialPoints& pts = batches[static_cast<std::size_t>(m)];
        pts_density = pts.density.data();
        pts_density_previous = pts.density_previous.data();
        pts_strain_rate = pts.strain_rate.data();
        pts_spin = pts.spin.data();
        pts_viscosity = pts.artificial_viscosity.data();
        pts_length = pts.characteristic_length.data();
      }
      const std::size_t p = point[e];
      pts_density_previous[p] = pts_density[p];
      pts_density[p] = rho[l];
      pts_strain_rate[p] = SymTensor{L[0][0][l], L[1][1][l], L[2][2][l], d_xy[l], d_yz[l], d_zx[l]};
      pts_spin[p] = Spin{w_xy[l], w_yz[l], w_zx[l]};
      pts_viscosity[p] = q_mean[l];
      pts_length[p] = le[l];
      if (!whole) {
        volume[e] = vol_l;
        density[e] = rho[l];
        viscosity[e] = q[l];
        length[e] = le[l];
        speed[e] = speed_pack[l];
      }
    }
    if (whole) {
      store_pack(volume.data(), e0, vol);
      store_pack(density.data(), e0, rho);
      store_pack(viscosity.data(), e0, q);
      store_pack(length.data(), e0, le);
      store_pack(speed.data(), e0, speed_pack);
    }
  }
  KinematicsResult result;
  result.viscous_work = viscous_work;
  if (bad != std::numeric_limits<std::int64_t>::max()) {
    result.bad_element = bad;
    result.bad_volume = volume_of(x, static_cast<std::size_t>(bad));
  }
  if (tangled != std::numeric_limits<std::int64_t>::max()) {
    result.tangled_element = tangled;
    NodeValues<D> xe;
    gather<D>(x, &connectivity[static_cast<std::size_t>(tangled) * nodes], xe);
    result.tangled_corners = corner_jacobians_negative<D>(xe);
  }
  return result;
}

template class FemElements<2>;
template class FemElements<3>;

}  // namespace camouflet
