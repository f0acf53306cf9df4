// The kinematics of the FEM elements at mid-step (fem_elements.hpp): volume,
// density, strain rate and spin, artificial viscosity and the step limit,
// element packs on SIMD lanes, with the tangled-element check.
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "core/error.hpp"
#include "fem/edge_viscosity.hpp"
#include "fem/element_gather.hpp"
#include "fem/fem_elements.hpp"
#include "fem/parallel.hpp"
#include "fem/subzonal_pressure.hpp"

namespace camouflet {

namespace {

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
  // Each element's viscosity form: its part's where the parts differ, else the run's.
  const bool own_forms = !viscosity_form.empty();
  const bool edges = own_forms ? edge_form_anywhere : visc.form == ViscosityForm::edge;
  const bool subzones = !subzone_pressure.empty();
  // r-z area form: planar subzone areas and median lengths, the nodes' ring factors apply them
  // (element_forces.cpp).
  constexpr std::size_t edge_values = static_cast<std::size_t>(ElementEdges<D>::count * D);
#pragma omp parallel for schedule(static) reduction(min : bad, tangled) reduction(+ : viscous_work) if (static_cast<std::int64_t>(ne) > parallel_threshold)
  for (std::int64_t k = 0; k < packs; ++k) {
    const std::size_t e0 = static_cast<std::size_t>(k) * W;
    const int count = static_cast<int>(std::min<std::size_t>(W, ne - e0));
    bool any = false;
    for (int l = 0; l < count; ++l) any = any || !eroded[e0 + static_cast<std::size_t>(l)];
    if (!any) continue;
    // Each lane's viscosity form (q below): its part's where the parts differ, else the run's.
    ViscosityForm form[W];
    bool along_acceleration = false, volumetric = false;
    for (int l = 0; l < W; ++l) {
      form[l] = own_forms && l < count ? viscosity_form[e0 + static_cast<std::size_t>(l)] : visc.form;
      along_acceleration = along_acceleration || form[l] == ViscosityForm::acceleration;
      volumetric = volumetric || form[l] == ViscosityForm::volumetric;
    }
    PackedNodes<D> xe, ve, ae, xh, b;
    // The previous velocities orient only the acceleration form's q: gathered for it alone (their
    // gather cost every hex8 3 % more instructions a cycle under the other forms).
    if (along_acceleration)
      gather_packs<D, 3>({x, v, v_previous}, connectivity.data(), ConsecutiveLanes{e0, count},
                         {&xe, &ve, &ae});
    else
      gather_packs<D, 2>({x, v}, connectivity.data(), ConsecutiveLanes{e0, count}, {&xe, &ve});
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
    Pack div{};  // the edge form: no q
    if (along_acceleration) {
      Pack abar[D] = {}, a2{};
      for (int i = 0; i < D; ++i) {
        for (int n = 0; n < N; ++n) abar[i] += ve[i][n] - ae[i][n];
        a2 += abar[i] * abar[i];
      }
      Pack ala{};
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) ala += abar[i] * L[i][j] * abar[j];
      for (int l = 0; l < W; ++l)
        if (form[l] == ViscosityForm::acceleration) div[l] = a2[l] > 0.0 ? ala[l] / a2[l] : 0.0;
    }
    if (volumetric) {
      const Pack trace = L[0][0] + L[1][1] + L[2][2];
      for (int l = 0; l < W; ++l)
        if (form[l] == ViscosityForm::volumetric) div[l] = trace[l];
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
#if defined(__AVX512F__) && defined(__AVX512VL__)
    // A whole pack of one material whose points are consecutive, without subzones or edge forces
    // (the usual case): the points' arrays written as whole packs, the strain rates and spins
    // turned into per-point records by transposes. The same values and the same viscous-work sum
    // (element order) as the lane loop below.
    if (whole && !subzones && !edges) {
      const int m = material[e0];
      const std::size_t p0 = point[e0];
      bool together = true;
      for (int l = 1; l < W && together; ++l)
        together = material[e0 + static_cast<std::size_t>(l)] == m &&
                   point[e0 + static_cast<std::size_t>(l)] == p0 + static_cast<std::size_t>(l);
      if (together) {
        for (int l = 0; l < W; ++l) {
          if constexpr (D == 2)
            if (corner_jacobians_negative<D>(xe, l) >= 2)
              tangled = std::min(tangled, static_cast<std::int64_t>(e0 + static_cast<std::size_t>(l)));
          viscous_work -= work[l];
        }
        MaterialPoints& pts = batches[static_cast<std::size_t>(m)];
        store_pack(pts.density_previous.data(), p0, load_pack(pts.density.data(), p0, W));
        store_pack(pts.density.data(), p0, rho);
        store_pack(pts.artificial_viscosity.data(), p0, q_mean);
        store_pack(pts.characteristic_length.data(), p0, le);
        static_assert(sizeof(SymTensor) == 6 * sizeof(double) && sizeof(Spin) == 3 * sizeof(double));
        const __m512d zero = _mm512_setzero_pd();
        __m512d columns[8] = {reinterpret_cast<__m512d>(L[0][0]),
                              reinterpret_cast<__m512d>(L[1][1]),
                              reinterpret_cast<__m512d>(L[2][2]),
                              reinterpret_cast<__m512d>(d_xy),
                              reinterpret_cast<__m512d>(d_yz),
                              reinterpret_cast<__m512d>(d_zx),
                              zero,
                              zero};
        __m512d rows[8];
        simd::transpose_8x8(columns, rows);
        for (int l = 0; l < W; ++l)
          _mm512_mask_storeu_pd(&pts.strain_rate[p0 + static_cast<std::size_t>(l)].xx, 0x3F, rows[l]);
        columns[0] = reinterpret_cast<__m512d>(w_xy);
        columns[1] = reinterpret_cast<__m512d>(w_yz);
        columns[2] = reinterpret_cast<__m512d>(w_zx);
        for (int c = 3; c < 6; ++c) columns[c] = zero;
        simd::transpose_8x8(columns, rows);
        for (int l = 0; l < W; ++l)
          _mm512_mask_storeu_pd(&pts.spin[p0 + static_cast<std::size_t>(l)].xy, 0x7, rows[l]);
        store_pack(volume.data(), e0, vol);
        store_pack(density.data(), e0, rho);
        store_pack(viscosity.data(), e0, q);
        store_pack(length.data(), e0, le);
        store_pack(speed.data(), e0, speed_pack);
        continue;
      }
    }
#endif
    // The subzone volumes at t_(n+1) of the whole pack at once where every lane takes the same
    // measure (subzone_volumes on packs: each lane has the bits of the element alone).
    bool subzone_pack = false;
    for (int l = 0; l < count && subzones; ++l)
      subzone_pack = subzone_pack || subzonal_coefficient[e0 + static_cast<std::size_t>(l)] > 0.0;
    for (int l = 1; l < count && subzone_pack; ++l)
      subzone_pack = area_form(e0 + static_cast<std::size_t>(l)) == area_form(e0);
    Pack subzone_volume_pack[N];
    if (subzone_pack) subzone_volumes<D>(xe, axi && !area_form(e0), subzone_volume_pack);
    // The limiter psi of each edge of lane l's element e, from the velocity differences along the
    // edges' continuations (global nodes at the same x(n+1), v(n+1/2)).
    const auto edge_limiters = [&](int l, std::size_t e, double(&psi)[ElementEdges<D>::count]) {
      using Edges = ElementEdges<D>;
      for (int kk = 0; kk < Edges::count; ++kk) {
        const int first = Edges::node[kk][0], second = Edges::node[kk][1];
        double du[D], dx[D], du_l[D], dx_l[D], du_r[D], dx_r[D];
        for (int i = 0; i < D; ++i)
          du[i] = ve[i][second][l] - ve[i][first][l], dx[i] = xe[i][second][l] - xe[i][first][l];
        const std::int64_t* beyond =
            &edge_continuation[(e * Edges::count + static_cast<std::size_t>(kk)) * 2];
        if (beyond[0] >= 0)
          for (int i = 0; i < D; ++i) {
            const std::size_t n = static_cast<std::size_t>(beyond[0]) * D + static_cast<std::size_t>(i);
            du_l[i] = ve[i][first][l] - v[n], dx_l[i] = xe[i][first][l] - x[n];
          }
        if (beyond[1] >= 0)
          for (int i = 0; i < D; ++i) {
            const std::size_t n = static_cast<std::size_t>(beyond[1]) * D + static_cast<std::size_t>(i);
            du_r[i] = v[n] - ve[i][second][l], dx_r[i] = x[n] - xe[i][second][l];
          }
        psi[kk] = edge_limiter<D>(du, dx, beyond[0] >= 0 ? du_l : nullptr, beyond[0] >= 0 ? dx_l : nullptr,
                                  beyond[1] >= 0 ? du_r : nullptr, beyond[1] >= 0 ? dx_r : nullptr);
      }
    };
    // The new edge forces of the whole pack where every lane takes the same measure (edge_viscous_forces
    // on packs: each lane has the bits of the element alone); the limiters stay lane by lane.
    bool edge_pack = false;
    for (int l = 0; l < count && edges; ++l) edge_pack = edge_pack || form[l] == ViscosityForm::edge;
    for (int l = 1; l < count && edge_pack; ++l)
      edge_pack = area_form(e0 + static_cast<std::size_t>(l)) == area_form(e0);
    Pack edge_force_pack[edge_values];
    if (edge_pack) {
      const bool limited = !edge_continuation.empty();
      Pack psi[ElementEdges<D>::count];
      if (limited)
        for (int l = 0; l < W; ++l) {
          double psi_l[ElementEdges<D>::count];
          edge_limiters(l, e0 + static_cast<std::size_t>(std::min(l, count - 1)), psi_l);
          for (int k = 0; k < ElementEdges<D>::count; ++k) psi[k][l] = psi_l[k];
        }
      edge_viscous_forces<D>(xe, ve, axi && !area_form(e0), rho, load_pack(wave_speed.data(), e0, count),
                             visc.quadratic, visc.linear, edge_force_pack, limited ? psi : nullptr);
    }
    int batch_index = -1;
    double *pts_density = nullptr, *pts_density_previous = nullptr, *pts_viscosity = nullptr,
           *pts_length = nullptr, *pts_energy = nullptr;
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
        pts_energy = pts.specific_energy.data();
      }
      const std::size_t p = point[e];
      pts_density_previous[p] = pts_density[p];
      pts_density[p] = rho[l];
      pts_strain_rate[p] = SymTensor{L[0][0][l], L[1][1][l], L[2][2][l], d_xy[l], d_yz[l], d_zx[l]};
      pts_spin[p] = Spin{w_xy[l], w_yz[l], w_zx[l]};
      pts_viscosity[p] = q_mean[l];
      pts_length[p] = le[l];
      // This lane's nodes at t_(n+1), for the subzonal pressures and the edge viscosity.
      const bool area_l = axi && area_form(e);  // the r-z area form (a part's own or the run's)
      const bool ring_volumes = axi && !area_l;
      const bool subzones_l = subzones && subzonal_coefficient[e] > 0.0;
      const bool edges_l = edges && form[l] == ViscosityForm::edge;
      double xl[D][N];
      if (subzones_l || edges_l)
        for (int i = 0; i < D; ++i)
          for (int a = 0; a < N; ++a) xl[i][a] = xe[i][a][l];
      if (subzones_l) {
        // The subzones' pressure differences at t_(n+1); their forces' work over this step, the
        // old and the new dp_s each over half of dV_s (as q's), goes into the element. The r-z
        // area form measures the subzones by their areas and books the work on the ring 2 pi r_bar.
        double v_new[N];
        if (subzone_pack)
          for (int a = 0; a < N; ++a) v_new[a] = subzone_volume_pack[a][l];
        else
          subzone_volumes<D>(xl, ring_volumes, v_new);
        double total = 0.0;
        for (int a = 0; a < N; ++a) total += v_new[a];
        const double stiffness = subzonal_coefficient[e] * wave_speed[e] * wave_speed[e] * rho[l];
        double work = 0.0;
        for (int a = 0; a < N; ++a) {
          const std::size_t k = e * N + static_cast<std::size_t>(a);
          const double dp = stiffness * (subzone_fraction[k] * total / v_new[a] - 1.0);
          work -= 0.5 * (subzone_pressure[k] + dp) * (v_new[a] - subzone_volume[k]);
          subzone_pressure[k] = dp;
          subzone_volume[k] = v_new[a];
        }
        pts_energy[p] += work * (area_l ? w[l] : 1.0) / mass[e];
      }
      if (edges_l) {
        // The edge forces at t_(n+1) from x(n+1), v(n+1/2); the work of the old and the new
        // forces over this step, each for its half (the trapezoid of q's work above), heats the
        // element before its material update.
        double vl[D][N];
        for (int i = 0; i < D; ++i)
          for (int a = 0; a < N; ++a) vl[i][a] = ve[i][a][l];
        double* force = &edge_force[e * edge_values];
        // The heat is the work the forces take from the nodes: in the r-z area form each node
        // feels its planar share times its ring factor (element_forces.cpp), so its velocity
        // enters times that factor.
        double vw[D][N];
        for (int a = 0; a < N; ++a) {
          const double ring =
              area_l
                  ? ring_factor_[static_cast<std::size_t>(connectivity[e * N + static_cast<std::size_t>(a)])]
                  : 1.0;
          for (int i = 0; i < D; ++i) vw[i][a] = ring * vl[i][a];
        }
        const double old_power = edge_viscous_power<D>(force, vw);
        if (edge_pack) {
          for (std::size_t k = 0; k < edge_values; ++k) force[k] = edge_force_pack[k][l];
        } else {
          double psi[ElementEdges<D>::count];
          const bool limited = !edge_continuation.empty();
          if (limited) edge_limiters(l, e, psi);
          edge_viscous_forces<D>(xl, vl, ring_volumes, rho[l], wave_speed[e], visc.quadratic, visc.linear,
                                 force, limited ? psi : nullptr);
        }
        const double heat = 0.5 * dt * (old_power + edge_viscous_power<D>(force, vw));
        pts_energy[p] += heat / mass[e];
        viscous_work += heat;
      }
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

template KinematicsResult FemElements<2>::kinematics(const double*, const double*, const double*, double,
                                                     const ViscosityControl&, std::vector<MaterialPoints>&);
template KinematicsResult FemElements<3>::kinematics(const double*, const double*, const double*, double,
                                                     const ViscosityControl&, std::vector<MaterialPoints>&);

}  // namespace camouflet
