// The element force kernel (element_forces.hpp): one pack of elements on SIMD lanes.
#include "fem/element_forces.hpp"

#include <cmath>
#include <cstring>

#include "fem/edge_viscosity.hpp"
#include "fem/element_gather.hpp"
#include "fem/subzonal_pressure.hpp"

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

#if defined(__AVX512F__) && defined(__AVX512VL__)
// The pack's node values as one record per lane and node: rows[l][a][i] = f[i][a][l] (the 3-D
// records padded to 4), by 8 x 8 transposes of whole registers.
template <int D, int S>
inline void node_records(const PackedNodes<D>& f, double (&rows)[pack_width][Shape<D>::nodes][S]) {
  constexpr int N = Shape<D>::nodes;
  __m512d columns[8], out[8];
  if constexpr (D == 3) {
    static_assert(S == 4);
    for (int a = 0; a < N; a += 2) {  // nodes a and a + 1: rows[l][a .. a + 1] is one 64-byte line
      for (int b = 0; b < 2; ++b) {
        for (int i = 0; i < 3; ++i) columns[4 * b + i] = reinterpret_cast<__m512d>(f[i][a + b]);
        columns[4 * b + 3] = _mm512_setzero_pd();
      }
      simd::transpose_8x8(columns, out);
      for (int l = 0; l < 8; ++l) _mm512_store_pd(rows[l][a], out[l]);
    }
  } else {
    static_assert(S == 2 && N == 4);
    for (int a = 0; a < N; ++a)
      for (int i = 0; i < 2; ++i) columns[2 * a + i] = reinterpret_cast<__m512d>(f[i][a]);
    simd::transpose_8x8(columns, out);
    for (int l = 0; l < 8; ++l) _mm512_store_pd(rows[l][0], out[l]);
  }
}
#endif

}  // namespace

template <int D>
ElementForceKernel<D>::ElementForceKernel(FemElements<D>& elements, const double* x, const double* v,
                                          const HourglassControl& hg, double dt_previous)
    : elements_(elements), x_(x), v_(v), dt_previous_(dt_previous) {
  axi_ = elements.axisymmetric_;
  // Without per-element control, `hg` for every element: kappa 0 for "none".
  own_hg_ = !elements.hourglass_coefficient.empty();
  hg_kappa_ = hg.form == HourglassForm::none ? 0.0 : hg.coefficient;
  hg_stiff_ = hg.form == HourglassForm::stiffness;
  // Whether any pack holds stiffness-form energy.
  any_stiff_hg_ = own_hg_ ? elements.stiffness_anywhere : hg_stiff_ && hg_kappa_ > 0.0;
  area_ = axi_ && elements.area_weighted_;
  if (area_ && elements.ring_factor_.size() != elements.node_count_) elements.update_ring_factors(x);
}

template <int D>
int ElementForceKernel<D>::width() {
  return pack_width;
}

template <int D>
double ElementForceKernel<D>::consecutive(std::size_t first, int count, double* f_out, double* fh_out) const {
  return pack(ConsecutiveLanes{first, count}, f_out, fh_out);
}

template <int D>
double ElementForceKernel<D>::consecutive_into_slots(std::size_t first, int count, double* f_slots,
                                                     double* fh_slots) const {
  return pack<ConsecutiveLanes, true>(ConsecutiveLanes{first, count}, f_slots, fh_slots);
}

template <int D>
double ElementForceKernel<D>::listed(const std::uint32_t* element, int count, double* f_out,
                                     double* fh_out) const {
  return pack(ListedLanes{element, count}, f_out, fh_out);
}

// One pack of elements lanes.at(0 .. count - 1) (element_gather.hpp): forces
// computed lane-parallel, scattered into f_out (and the hourglass part into
// fh_out) lane by lane; returns the stiffness-form hourglass energy held.
template <int D>
template <class Lanes, bool into_slots>
double ElementForceKernel<D>::pack(const Lanes& lanes, double* f_out, double* fh_out) const {
  constexpr int N = FemElements<D>::nodes;
  constexpr int W = pack_width;
  constexpr int modes = FemElements<D>::modes;
  FemElements<D>& el = elements_;
  const double* const x = x_;
  const double* const v = v_;
  const double dt_previous = dt_previous_;
  const bool axi = axi_, area = area_, own_hg = own_hg_, hg_stiff = hg_stiff_;
  const double hg_kappa = hg_kappa_;
  const std::vector<char>& eroded = el.eroded;
  const std::vector<std::int64_t>& connectivity = el.connectivity;
  const std::vector<double>& hourglass_coefficient = el.hourglass_coefficient;
  const std::vector<char>& hourglass_stiffness = el.hourglass_stiffness;
  const std::vector<SymTensor>& stress = el.stress;
  const std::vector<double>& viscosity = el.viscosity;
  const std::vector<double>& density = el.density;
  const std::vector<double>& wave_speed = el.wave_speed;
  const std::vector<double>& length = el.length;
  const std::vector<double>& ring_factor_ = el.ring_factor_;
  std::vector<double>& hourglass_displacement = el.hourglass_displacement;

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
#if defined(__AVX512F__) && defined(__AVX512VL__)
  {
    // Each lane's six stress values as one row, turned into six packs by a transpose: the same
    // values and the same subtractions as the lane loop below.
    static_assert(sizeof(SymTensor) == 6 * sizeof(double));
    __m512d rows[8], columns[8];
    for (int l = 0; l < 8; ++l) rows[l] = _mm512_maskz_loadu_pd(0x3F, &stress[lanes.at(l)].xx);
    simd::transpose_8x8(rows, columns);
    Pack s[6];
    for (int c = 0; c < 6; ++c) s[c] = reinterpret_cast<Pack>(columns[c]);
    const Pack q = load_pack(viscosity.data(), lanes);
    sig[0][0] = s[0] - q;
    sig[1][1] = s[1] - q;
    sig[0][1] = sig[1][0] = s[3];
    hoop = s[2] - q;
    if constexpr (D == 3) {
      sig[2][2] = s[2] - q;
      sig[1][2] = sig[2][1] = s[4];
      sig[0][2] = sig[2][0] = s[5];
    }
  }
#else
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
#endif
  // The lanes in the r-z area form: all, none, or (parts of both forms meet in this pack) some.
  bool all_area = area, no_area = !area;
  bool area_lane[W];
  for (int l = 0; l < W; ++l) area_lane[l] = area;
  if (area && !el.area_form_.empty()) {
    all_area = true, no_area = true;
    for (int l = 0; l < W; ++l) {
      area_lane[l] = el.area_form_[lanes.at(l)] != 0;
      all_area = all_area && area_lane[l];
      no_area = no_area && !area_lane[l];
    }
  }
  if (!all_area) {
    for (int a = 0; a < N; ++a)
      for (int i = 0; i < D; ++i) {
        Pack t{};
        for (int j = 0; j < D; ++j) t += sig[i][j] * b[j][a];
        fe[i][a] = -vol * t;
      }
    if constexpr (D == 2) {
      if (axi) {
        // Hoop stress: virtual power of sigma_tt against the hoop rate v_r / r_bar,
        // v_r at the centre = mean of the nodal v_r.
        const Pack hoop_force = vol * hoop / (N * r_bar);
        for (int a = 0; a < N; ++a) fe[0][a] -= hoop_force;
      }
    }
  }
  if constexpr (D == 2) {
    if (!no_area) {
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
          const Pack f = ring * (-measure * t + (i == 0 ? source_r : source_z));
          if (all_area) {
            fe[i][a] = f;
          } else {
            for (int l = 0; l < W; ++l)
              if (area_lane[l]) fe[i][a][l] = f[l];
          }
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

  // The edge viscosity's forces and the subzonal pressures' from the last kinematics
  // (edge_viscosity.hpp, subzonal_pressure.hpp: f_a = sum_s dp_s dV_s/dx_a); in the r-z area
  // form planar, times each node's ring factor.
  // Lanes that all take the same subzone measure (every lane in the area form or none) run on the
  // pack: the same operations per lane as the lane loop after it (subzone_volumes on packs, a
  // lane select where that loop skips a zero dp), so the same bits.
  bool same_measure = true;
  for (int l = 1; l < count; ++l) same_measure = same_measure && area_lane[l] == area_lane[0];
  if ((!el.edge_force.empty() || !el.subzone_pressure.empty()) && same_measure) {
    using E = ElementEdges<D>;
    Pack fl[D][N] = {};
    if (!el.edge_force.empty()) {
      for (int k = 0; k < E::count; ++k)
        for (int i = 0; i < D; ++i) {
          Pack force;
          for (int l = 0; l < W; ++l)
            force[l] = el.edge_force[lanes.at(l) * static_cast<std::size_t>(E::count * D) +
                                     static_cast<std::size_t>(k * D + i)];
          fl[i][E::node[k][0]] += force;
          fl[i][E::node[k][1]] -= force;
        }
    }
    if (!el.subzone_pressure.empty()) {
      Pack v_s[N], grad[N][D][N];
      subzone_volumes<D>(xe, axi && !area_lane[0], v_s, grad);
      for (int s = 0; s < N; ++s) {
        Pack dp;
        for (int l = 0; l < W; ++l)
          dp[l] = el.subzone_pressure[lanes.at(l) * N + static_cast<std::size_t>(s)];
        for (int i = 0; i < D; ++i)
          for (int a = 0; a < N; ++a) fl[i][a] = dp != 0.0 ? fl[i][a] + dp * grad[s][i][a] : fl[i][a];
      }
    }
    for (int a = 0; a < N; ++a) {
      Pack ring = broadcast(1.0);
      if (area_lane[0])
        for (int l = 0; l < W; ++l)
          ring[l] = ring_factor_[static_cast<std::size_t>(
              connectivity[lanes.at(l) * N + static_cast<std::size_t>(a)])];
      for (int i = 0; i < D; ++i) fe[i][a] += ring * fl[i][a];
    }
  } else if (!el.edge_force.empty() || !el.subzone_pressure.empty()) {
    using E = ElementEdges<D>;
    for (int l = 0; l < count; ++l) {
      const std::size_t e = lanes.at(l);
      const bool ring_volumes = axi && !area_lane[l];
      double fl[D][N] = {};
      if (!el.edge_force.empty()) {
        const double* force = &el.edge_force[e * static_cast<std::size_t>(E::count * D)];
        for (int k = 0; k < E::count; ++k)
          for (int i = 0; i < D; ++i) {
            fl[i][E::node[k][0]] += force[k * D + i];
            fl[i][E::node[k][1]] -= force[k * D + i];
          }
      }
      if (!el.subzone_pressure.empty()) {
        double xl[D][N], v_s[N], grad[N][D][N];
        for (int i = 0; i < D; ++i)
          for (int a = 0; a < N; ++a) xl[i][a] = xe[i][a][l];
        subzone_volumes<D>(xl, ring_volumes, v_s, grad);
        for (int s = 0; s < N; ++s) {
          const double dp = el.subzone_pressure[e * N + static_cast<std::size_t>(s)];
          if (dp == 0.0) continue;
          for (int i = 0; i < D; ++i)
            for (int a = 0; a < N; ++a) fl[i][a] += dp * grad[s][i][a];
        }
      }
      for (int a = 0; a < N; ++a) {
        const double ring =
            area_lane[l]
                ? ring_factor_[static_cast<std::size_t>(connectivity[e * N + static_cast<std::size_t>(a)])]
                : 1.0;
        for (int i = 0; i < D; ++i) fe[i][a][l] += ring * fl[i][a];
      }
    }
  }

  // Lane by lane, node by node: the node's D force values and, when asked
  // for, its D hourglass values at one computed address (each array sees its
  // additions in the same order as before).
  // Only the viscous form's forces go to fh_out: the stiffness form's
  // energy is held as a state (the return value), not integrated as work.
  const bool scatter_hourglass = fh_out && viscous_hg;
#if defined(__AVX512F__) && defined(__AVX512VL__)
  // The lanes' values turned into per-lane node records by transposes (element_gather.hpp does
  // the reverse), each node's D values then added (or, into slots, stored) per record: the same
  // additions in the same order as the lane loop below, which serves targets without AVX-512VL,
  // so the same bits.
  {
    constexpr int S = D == 3 ? 4 : 2;  // doubles per node record (3-D: x y z and a pad)
    alignas(64) double f_rows[W][N][S], h_rows[W][N][S];
    node_records<D>(fe, f_rows);
    if (scatter_hourglass) node_records<D>(fh, h_rows);
    constexpr __mmask8 mask = D == 3 ? 0x7 : 0x3;
    for (int l = 0; l < count; ++l) {
      const std::size_t e = lanes.at(l);
      if constexpr (into_slots) {  // every slot written, eroded elements' with noughts
        const bool gone = eroded[e] != 0, lane_hourglass = scatter_hourglass && !stiff[l] && !gone;
        for (int a = 0; a < N; ++a) {
          const std::size_t k = (e * N + static_cast<std::size_t>(a)) * D;
          const __m256d zero = _mm256_setzero_pd();
          _mm256_mask_storeu_pd(f_out + k, mask, gone ? zero : _mm256_maskz_loadu_pd(mask, f_rows[l][a]));
          if (fh_out)
            _mm256_mask_storeu_pd(fh_out + k, mask,
                                  lane_hourglass ? _mm256_maskz_loadu_pd(mask, h_rows[l][a]) : zero);
        }
        continue;
      }
      if (eroded[e]) continue;
      const std::int64_t* c = connectivity.data() + e * N;
      const bool scatter_lane = scatter_hourglass && !stiff[l];
      // x and y as one 128-bit add, z (3-D) alone: a masked store does not forward to the next
      // load of the same node (the next lane's element shares it), which stalled the loop.
      const auto add_to = [](double* sums, const double* values) {
        _mm_storeu_pd(sums, _mm_add_pd(_mm_loadu_pd(sums), _mm_load_pd(values)));
        if constexpr (D == 3) sums[2] += values[2];
      };
      for (int a = 0; a < N; ++a) {
        const std::int64_t k = c[a] * D;
        add_to(f_out + k, f_rows[l][a]);
        if (scatter_lane) add_to(fh_out + k, h_rows[l][a]);
      }
    }
    return stored;
  }
#endif
  for (int l = 0; l < count; ++l) {
    const std::size_t e = lanes.at(l);
    if constexpr (into_slots) {  // every slot written, eroded elements' with noughts
      const bool gone = eroded[e] != 0, lane_hourglass = scatter_hourglass && !stiff[l] && !gone;
      for (int a = 0; a < N; ++a) {
        const std::size_t k = (e * N + static_cast<std::size_t>(a)) * D;
        for (int i = 0; i < D; ++i) f_out[k + static_cast<std::size_t>(i)] = gone ? 0.0 : fe[i][a][l];
        if (fh_out)
          for (int i = 0; i < D; ++i) fh_out[k + static_cast<std::size_t>(i)] = lane_hourglass ? fh[i][a][l] : 0.0;
      }
      continue;
    }
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
}

template class ElementForceKernel<2>;
template class ElementForceKernel<3>;

}  // namespace camouflet
