// The internal forces of the FEM elements at t_n (fem_elements.hpp): stress
// divergence, hoop term and hourglass resistance, element packs on SIMD lanes,
// assembled into the node forces by the chosen ForceAssembly.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"
#include "fem/element_gather.hpp"
#include "fem/fem_elements.hpp"
#include "fem/parallel.hpp"

namespace camouflet {

namespace {

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

}  // namespace

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

template double FemElements<2>::add_internal_forces(const double*, const double*, double*, double*,
                                                    const HourglassControl&, double);
template double FemElements<3>::add_internal_forces(const double*, const double*, double*, double*,
                                                    const HourglassControl&, double);

}  // namespace camouflet
