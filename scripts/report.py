#!/usr/bin/python3
"""Figures and one HTML page from the output folder of a buried-structure run
(`camouflet report OUTDIR`, docs/buried-structure.md).

Reads summary.json, the gauge CSVs (group_A, group_B, structure) and the
generator's header line of case.toml; writes PNG figures and report.html into
OUTDIR/report/. Uses the Python standard library, NumPy, SciPy (filters and
shock spectra, structure_shock.py) and matplotlib (Debian's python3-numpy,
python3-scipy, python3-matplotlib). Figure numbers refer to Wang, Lu, Hao, Chong,
Computers and Structures 83 (2005) 339-356.
"""
import argparse
import html
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# The headline quantities have one definition, shared with `camouflet sweep`.
from run_metrics import (F_COUPLING, G, band_ratio, crater, deflections, empirical_averages,  # noqa: E402
                         empirical_range, final_displacements, gauge_names, generator_parameters,
                         ground_shock_peaks, in_structure_peaks, last_snapshots, member_average_motion,
                         radial_stress, read_csv, structure_damage, tm5_functions)
from damage_map import damage_map  # noqa: E402
from structure_shock import (CUTOFF_HZ, can_lowpass, filtered_acceleration, lowpass, shock_response_spectrum,  # noqa: E402
                             uniform)

# The in-structure shock spectra use this damping.
SRS_DAMPING = 0.05
MEMBER_ORDER = ["front wall", "roof", "floor", "back wall"]
# energy.csv's terms (solver/energy_output.hpp) in words; the shares are parts of the term above them.
ENERGY_NAMES = {"join_face": "join, via the centre-face offset", "viscous": "viscous heating (in internal)",
                "sph_kinetic": "kinetic, SPH particles' share", "sph_internal": "internal, SPH particles' share",
                "bar_internal": "internal, rebar's share", "boundary_work": "boundary work",
                "initial_total": "initial total"}


def energy_name(term):
    return ENERGY_NAMES.get(term, term)


def rebar_gauges(case_path):
    """[(name, segment)] from the generator's '# rebar gauges (bars.csv): In-1=front_in.1 ...' line."""
    try:
        with open(case_path) as f:
            for line in f:
                if line.startswith("# rebar gauges (bars.csv):"):
                    return [tuple(item.split("=", 1)) for item in line.split(":", 1)[1].split() if "=" in item]
    except OSError:
        pass
    return []


def speed(cols, g):
    return np.hypot(cols[g + ".velocity_x"], cols[g + ".velocity_y"])


def save(fig, outdir, name):
    if fig.get_layout_engine() is None:  # a figure that chose its layout keeps it
        fig.tight_layout()
    path = os.path.join(outdir, name)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return name


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("outdir")
    ap.add_argument("--camouflet", default="", help="camouflet executable (for `empirical --csv`)")
    args = ap.parse_args()
    out = args.outdir
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    gen = generator_parameters(os.path.join(out, "case.toml"))
    W = gen.get("charge_mass_kg", 100.0)
    d = gen.get("burst_depth_m", 0.5)
    standoff = gen.get("standoff_m", 6.0)
    length = gen.get("box_length_m", 4.0)
    height = gen.get("box_height_m", 1.0)
    # The soil-structure interface (structure.interface of the generator; fused unless the line says).
    if gen.get("structure_kind") == "free_field" or not gen:
        interface = ""
    elif gen.get("interface") == "slide":
        interface = f", soil–structure interface sliding (Coulomb friction {gen.get('friction', 0.0):g})"
    else:
        interface = ", soil–structure interface fused (shared nodes)"
    w3 = W ** (1.0 / 3.0)
    figdir = os.path.join(out, "report")
    os.makedirs(figdir, exist_ok=True)
    # The page in reading order: a figure ((file, caption)) sits under the heading and beside the table
    # (html text) of its subject, not in a gallery after all tables.
    blocks = []
    plt.rcParams.update({"figure.figsize": (7.5, 4.6), "axes.grid": True, "grid.alpha": 0.3, "font.size": 10})

    groups = {}
    for name in ("group_A", "group_B"):
        path = os.path.join(out, name + ".csv")
        if os.path.exists(path):
            groups[name] = read_csv(path)

    # Fig. 8b: peak stress against scaled distance with TM-5 Functions 1 and 2.
    peaks = {}
    if groups:
        blocks.append("<h2>Ground shock</h2>")
        fig, ax = plt.subplots()
        Zs = np.geomspace(0.2, 3.0, 100)
        f1, f2 = tm5_functions(Zs)
        ax.fill_between(Zs, f1 / 1.5, f2 * 1.5, color="0.85", label="TM-5 band widened by 1.5")
        ax.loglog(Zs, f1, "k--", label="Function 1: f·15·Z$^{-2.5}$")
        ax.loglog(Zs, f2, "k-.", label="Function 2: f·22·Z$^{-2}$")
        for (name, rows), style in zip(ground_shock_peaks(out, d, W).items(), ("o-", "s-")):
            Z, P = np.array([r[1] for r in rows]), np.array([r[3] for r in rows])
            peaks[name] = (Z, P)
            ax.loglog(Z, P, style, label=f"group {name[-1]} (computed)")
        ax.set_ylim(bottom=f1.min() / 30.0)  # gauges the wave has not reached fall off the bottom
        ax.set_xlabel("scaled distance Z = R / W$^{1/3}$  [m/kg$^{1/3}$]")
        ax.set_ylabel("peak radial stress [MPa]")
        ax.set_title(f"Attenuation of peak stress, {W:g} kg TNT at {d:g} m (cf. Fig. 8b), f = {F_COUPLING}")
        ax.legend(fontsize=8)
        blocks.append((save(fig, figdir, "fig08b_peak_stress.png"),
                       "Peak radial stress against scaled distance: group A (parallel to the ground at the charge "
                       "depth) and group B (45° line down), with the TM 5-855-1 Functions 1 and 2 (f = 0.6)."))
        rows = []
        for name, (Z, P) in peaks.items():
            lo, hi = tm5_functions(Z)
            for z, p, a, b in zip(Z, P, lo, hi):
                inside = band_ratio(z, p) == 1.0
                rows.append(f"<tr><td>{name[-1]}</td><td>{z:.3f}</td><td>{z * w3:.2f}</td><td>{p:.3g}</td>"
                            f"<td>{a:.3g} / {b:.3g}</td><td>{'yes' if inside else 'no'}</td></tr>")
        blocks.append("<h3>Peak stresses against TM-5</h3><table><tr><th>group</th><th>Z [m/kg<sup>1/3</sup>]</th>"
                      "<th>R [m]</th><th>peak [MPa]</th><th>TM-5 Function 1 / Function 2 [MPa]</th>"
                      "<th>within the band widened by ×1.5</th></tr>" +
                      "".join(rows) + "</table>")

    # Fig. 9: stress and velocity histories at equal distance (the A/B pair nearest 4 m).
    if "group_A" in groups and "group_B" in groups:
        tA, cA = groups["group_A"]
        tB, cB = groups["group_B"]
        best = None
        for g in gauge_names(cA, "A"):
            other = "B" + g[1:]
            if other + ".stress_xx" not in cB:
                continue
            _, R = radial_stress(cA, g, -d)
            if best is None or abs(R - 4.0) < abs(best[2] - 4.0):
                best = (g, other, R)
        if best:
            fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
            sA, _ = radial_stress(cA, best[0], -d)
            sB, _ = radial_stress(cB, best[1], -d)
            axes[0].plot(tA * 1e3, sA, label=f"group A ({best[0]})")
            axes[0].plot(tB * 1e3, sB, label=f"group B ({best[1]})")
            axes[0].set_ylabel("radial stress [MPa, compression +]")
            axes[1].plot(tA * 1e3, speed(cA, best[0]), label=f"group A ({best[0]})")
            axes[1].plot(tB * 1e3, speed(cB, best[1]), label=f"group B ({best[1]})")
            axes[1].set_ylabel("particle speed [m/s]")
            for ax in axes:
                ax.set_xlabel("time [ms]")
                ax.legend()
            fig.suptitle(f"Histories at {best[2]:.2f} m from the charge (cf. Fig. 9)")
            blocks.append((save(fig, figdir, "fig09_histories.png"),
                           f"Stress and velocity histories at the same range ({best[2]:.2f} m) in group A and group B."))

    spath = os.path.join(out, "structure.csv")
    if os.path.exists(spath):
        if gen.get("structure_kind") == "free_field":
            # structure.kind = "free_field": no box; the targets and members are the soil in its place.
            blocks.append("<h2>Free field at the box's place</h2><p>This run has no box "
                          "(<code>structure.kind = \"free_field\"</code>): the soil fills its place and "
                          "interior, and the targets and members below, named after the box's parts, "
                          "measure that soil: the free-field motion the box is weighed against "
                          "(docs/buried-structure.md, \"The box against the free field\").</p>")
        else:
            blocks.append("<h2>Structure response</h2>")
        t, c = read_csv(spath)
        ms = t * 1e3
        has = lambda g: g + ".velocity_x" in c  # noqa: E731
        # Fig. 11: interface stress at target 9 (normal stress on the wall face).
        if has("t9"):
            fig, ax = plt.subplots()
            # One soil element's stress sampled every gauge interval carries the cycle-to-cycle noise
            # of the contact: the raw normal stress stays as a light trace, the normal stress and the
            # pressure low-passed at CUTOFF_HZ (as the accelerations) are drawn over it. The two
            # differ by the deviator -s_xx, often small there: the pressure is dashed so both show.
            normal = -c["t9.stress_xx"] / 1e6
            ax.plot(ms, normal, lw=0.6, color="0.75", label="normal to the wall, raw")
            tu, nu = uniform(t, normal)
            if can_lowpass(tu):
                _, pu = uniform(t, c["t9.pressure"] / 1e6)
                ax.plot(tu * 1e3, lowpass(tu, nu, CUTOFF_HZ), lw=2.0, label=f"normal, {CUTOFF_HZ:g} Hz")
                ax.plot(tu * 1e3, lowpass(tu, pu, CUTOFF_HZ), "--", lw=1.2, color="black",
                        label=f"pressure, {CUTOFF_HZ:g} Hz")
            ax.set_xlabel("time [ms]")
            ax.set_ylabel("stress [MPa, compression +]")
            ax.set_title("Interface stress at target 9, front wall mid-height (cf. Fig. 11)")
            ax.legend()
            blocks.append((save(fig, figdir, "fig11_interface_stress.png"),
                           "Soil stress at the soil–structure interface at the front wall's mid-height (target 9): "
                           f"the normal stress raw (grey) and low-passed at {CUTOFF_HZ:g} Hz (solid), the pressure "
                           f"low-passed (dashed); they differ by the deviator."))
        # Fig. 12: displacements of the front wall and deflections.
        if all(has(g) for g in ("t1", "t2", "t3", "t5", "t6")):
            fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
            for g in ("t1", "t2", "t3"):
                axes[0].plot(ms, c[g + ".displacement_x"] * 1e3, label=f"{g} horizontal")
                axes[0].plot(ms, c[g + ".displacement_y"] * 1e3, "--", label=f"{g} vertical")
            axes[0].set_ylabel("displacement [mm]")
            axes[0].set_title("front wall (targets 1–3)")
            wall, floor = deflections(c)
            axes[1].plot(ms, wall * 1e3, label="front wall (horizontal, t2 vs t1/t3)")
            axes[1].plot(ms, floor * 1e3, label="floor (vertical, t5 vs t3/t6)")
            axes[1].set_ylabel("deflection [mm]")
            axes[1].set_title("deflections")
            for ax in axes:
                ax.set_xlabel("time [ms]")
                ax.legend(fontsize=8)
            fig.suptitle("Displacements and deflections (cf. Fig. 12)")
            blocks.append((save(fig, figdir, "fig12_displacements.png"),
                           f"Front-wall displacements and deflections. Peak front-wall deflection "
                           f"{np.nanmax(np.abs(wall)) * 1e3:.2f} mm ({np.nanmax(np.abs(wall)) / height * 100:.3f} % of "
                           f"the height); floor {np.nanmax(np.abs(floor)) * 1e3:.2f} mm "
                           f"({np.nanmax(np.abs(floor)) / length * 100:.3f} % of the length)."))
        # Figs. 15-16: velocity and acceleration of the front wall and the floor.
        sets = (("front wall", ("t1", "t2", "t3"), "x", "horizontal", "fig15_front_wall.png", "Fig. 15"),
                ("floor", ("t3", "t4", "t5"), "y", "vertical", "fig16_floor.png", "Fig. 16"))
        measured = in_structure_peaks(c)
        filtered_peaks, srs_inputs = {}, {}
        for title, gs, axis, word, fname, ref in sets:
            if title not in measured:
                continue
            fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
            for k, g in enumerate(gs):
                axes[0].plot(ms, c[f"{g}.velocity_{axis}"], label=g)
                a = c[f"{g}.acceleration_{axis}"]
                # Raw in grey behind: one colour per target made a solid band that hid the low-passed lines.
                axes[1].plot(ms, a / G, color="0.55", lw=0.4, alpha=0.3, zorder=1,
                             label="raw gauges" if k == 0 else None)
                lp = filtered_acceleration(t, c[f"{g}.velocity_{axis}"])
                if lp:
                    axes[1].plot(lp[0] * 1e3, lp[1] / G, color=f"C{k}", lw=1.2, zorder=2,
                                 label=f"{g}, {CUTOFF_HZ:g} Hz")
                    filtered_peaks.setdefault(title, []).append(np.max(np.abs(lp[1])) / G)
                    if g == gs[1]:
                        srs_inputs[title] = (g, axis, lp)
            axes[0].set_ylabel(f"{word} velocity [m/s]")
            axes[1].set_ylabel(f"{word} acceleration [g]")
            clipped = ""
            if title in filtered_peaks:
                # The raw trace is aliased noise about ten times the low-passed peak; on its scale the
                # low-passed trace, the one to read, is a flat line.
                top = 1.5 * max(filtered_peaks[title])
                axes[1].set_ylim(-top, top)
                clipped = " (clipped to the axis; its peaks are in the table)"
            for ax in axes:
                ax.set_xlabel("time [ms]")
                ax.legend()
            fig.suptitle(f"{title.capitalize()}: {word} velocity and acceleration (cf. {ref})")
            blocks.append((save(fig, figdir, fname),
                           f"{title.capitalize()} {word} velocity and acceleration. Grey: the raw acceleration "
                           f"gauges (one cycle's nodal value per sample, aliased){clipped}. Bold: the velocity's "
                           f"difference quotient low-passed at {CUTOFF_HZ:g} Hz (zero-phase Butterworth, -3 dB at "
                           f"the cut-off; scripts/structure_shock.py)."))
        # Member averages (members.csv): the span's rigid-body motion, raw and low-passed.
        member_rows = {}
        mpath = os.path.join(out, "members.csv")
        if os.path.exists(mpath):
            for title, (member, axis, word, vmax, lp) in member_average_motion(*read_csv(mpath)).items():
                member_rows[title] = (vmax, np.nanmax(np.abs(lp[1])) / G if lp else float("nan"), word)
                if lp:
                    srs_inputs[f"{title}, member average"] = (member, axis, lp)
        # Shock response spectra of the low-passed motion at mid-wall and mid-floor.
        if srs_inputs:
            fig, ax = plt.subplots(figsize=(7.5, 5.2))
            freqs = np.geomspace(2.0, 2000.0, 60)
            for k, (title, (g, axis, (tu, au))) in enumerate(sorted(srs_inputs.items())):
                srs = shock_response_spectrum(tu, au, freqs, damping=SRS_DAMPING)
                ax.loglog(freqs, srs["pseudo_velocity"], "-" if "member" in title else "--",
                          color=f"C{k // 2}", label=f"{title} ({g}, {axis})")
            ax.set_xlim(freqs[0], freqs[-1])
            lo, hi = ax.get_ylim()
            for acc_g in (1, 10, 100, 1000):  # lines of constant acceleration: PV = a / w
                ax.loglog(freqs, acc_g * G / (2 * np.pi * freqs), color="0.7", lw=0.6, ls=":")
            for disp in (1e-4, 1e-3, 1e-2, 1e-1):  # lines of constant displacement: PV = d w
                ax.loglog(freqs, disp * 2 * np.pi * freqs, color="0.7", lw=0.6, ls="--")
            ax.set_ylim(lo, hi)
            ax.set_xlabel("natural frequency [Hz]")
            ax.set_ylabel("pseudo-velocity [m/s]")
            ax.set_title(f"Shock response spectra, {SRS_DAMPING * 100:g} % damping (low-passed at {CUTOFF_HZ:g} Hz)")
            ax.legend(fontsize=8)
            blocks.append((save(fig, figdir, "srs_structure.png"),
                           "Pseudo-velocity shock response spectra (maximax) of the low-passed base motion: "
                           "the front wall's and the floor's member averages (solid) and their mid-span targets "
                           "(dashed). Dotted grey: constant acceleration "
                           "1, 10, 100, 1000 g; dashed grey: constant displacement 0.1, 1, 10, 100 mm."))
        avg = empirical_averages(args.camouflet, W, standoff, standoff + length)
        if measured:
            rows = []
            v_lo, v_hi, a_lo, a_hi = empirical_range(avg)
            for title, (vmax, amax, word) in measured.items():
                ok = 0.5 * v_lo <= vmax <= 2.0 * v_hi
                af = max(filtered_peaks[title]) if title in filtered_peaks else float("nan")
                rows.append(f"<tr><td>{title} ({word}), largest of 3 targets</td><td>{vmax:.3g}</td>"
                            f"<td>{v_lo:.3g} – {v_hi:.3g}</td>"
                            f"<td>{'yes' if ok else 'no'}</td><td>{amax:.4g}</td><td>{af:.4g}</td>"
                            f"<td>{a_lo:.4g} – {a_hi:.4g}</td></tr>")
            for title, (vmax, af, word) in member_rows.items():
                ok = 0.5 * v_lo <= vmax <= 2.0 * v_hi
                rows.append(f"<tr><td>{title} ({word}), member average</td><td>{vmax:.3g}</td>"
                            f"<td>{v_lo:.3g} – {v_hi:.3g}</td><td>{'yes' if ok else 'no'}</td><td></td>"
                            f"<td>{af:.4g}</td><td>{a_lo:.4g} – {a_hi:.4g}</td></tr>")
            blocks.append(
                "<h3>In-structure shock against TM-5 averages</h3>"
                f"<p>TM-5 averages over R = {standoff:g} … {standoff + length:g} m from "
                "<code>camouflet empirical --csv</code> (n = 2.5 and 2, f = 0.6). The criterion is "
                "0.5 × the lower to 2 × the upper average. Peaks of the largest of the member's three "
                "single-node targets, and of the member average (members.csv: mass-weighted over the member's "
                f"nodes); accelerations raw, and from the velocity low-passed at {CUTOFF_HZ:g} Hz.</p>"
                "<table><tr><th>where</th><th>peak velocity [m/s]</th><th>TM-5 V<sub>avg</sub> [m/s]</th>"
                "<th>within criterion</th><th>peak acceleration, raw [g]</th>"
                f"<th>peak acceleration, {CUTOFF_HZ:g} Hz [g]</th><th>TM-5 a<sub>avg</sub> [g]</th></tr>" +
                "".join(rows) + "</table>")

    # Permanent displacements, damage of the box (Fig. 14's numbers) and the apparent crater (run_metrics.py).
    rows = []
    if os.path.exists(spath):
        for title, u in final_displacements(read_csv(spath)[1]).items():
            rows.append(f"<tr><td>{title}: largest displacement at the end of the run</td><td>{u * 1e3:.3g} mm</td></tr>")
    dmg = structure_damage(out, gen)
    if dmg:
        rows.append(f"<tr><td>largest damage in the box</td><td>{dmg['max']:.3g} ({dmg['member']})</td></tr>")
        lower, upper = dmg["front_wall_halves"]
        # The members in the order the load meets them, the front wall's halves under it (Fig. 14's finding).
        for m in sorted(dmg["mean"], key=lambda m: (MEMBER_ORDER + [m]).index(m)):
            rows.append(f"<tr><td>mean damage, {m}</td><td>{dmg['mean'][m]:.3g}</td></tr>")
            if m == "front wall":
                rows.append(f"<tr><td>&emsp;lower half (facing the charge) / upper half</td>"
                            f"<td>{lower:.3g} / {upper:.3g}</td></tr>")
    cr = crater(out, gen)
    if cr:
        rows.append(f"<tr><td>apparent crater radius / depth</td><td>{cr[0]:.3g} m / {cr[1]:.3g} m</td></tr>")
    if rows:
        files, t_last = last_snapshots(out)
        when = f" (t = {t_last * 1e3:.1f} ms)" if t_last is not None else ""
        blocks.append("<h2>Permanent displacement, damage and crater</h2><p>At the last snapshot" + when +
                      "; damage D is 0 intact to 1 fully damaged. Definitions in <code>scripts/run_metrics.py</code> "
                      "(docs/buried-structure.md).</p><table>" + "".join(rows) + "</table>")
    if dmg:
        fig, caption = damage_map(dmg["section"], (lower, upper))
        blocks.append((save(fig, figdir, "fig14_damage.png"), caption))

    # Fig. 13: rebar strain at the rebar gauges In-1..3 / Out-1..3 (bars.csv; the case header names the segments).
    bpath = os.path.join(out, "bars.csv")
    rebar = rebar_gauges(os.path.join(out, "case.toml"))
    if os.path.exists(bpath) and rebar:
        blocks.append("<h2>Reinforcement</h2>")
        t, c = read_csv(bpath)
        fig, ax = plt.subplots()
        rows = []
        for name, segment in rebar:
            col = segment + ".axial_strain"
            if col not in c:
                continue
            ax.plot(t * 1e3, c[col] * 1e6, "-" if name.startswith("In") else "--", label=f"{name} ({segment})")
            rows.append(f"<tr><td>{name}</td><td>{segment}</td><td>{np.nanmax(np.abs(c[col])) * 1e6:.0f}</td>"
                        f"<td>{np.nanmax(c[segment + '.plastic_strain']) * 1e6:.0f}</td></tr>")
        ax.set_xlabel("time [ms]")
        ax.set_ylabel("axial strain [µε, tension +]")
        ax.set_title("Rebar strain in the front wall (cf. Fig. 13)")
        ax.legend(fontsize=8)
        blocks.append((save(fig, figdir, "fig13_rebar_strain.png"),
                       "Axial strain of the front wall's inner (In) and outer, soil-side (Out) bars at the top, "
                       "mid-height and bottom (embedded bars, docs/buried-structure.md)."))
        blocks.append("<h3>Rebar gauges</h3><table><tr><th>gauge</th><th>bar segment</th><th>peak |strain| [µε]</th>"
                      "<th>plastic strain [µε]</th></tr>" + "".join(rows) + "</table>")

    # Energy history and where the boundary work goes (energy.csv, solver/energy_output.hpp).
    epath = os.path.join(out, "energy.csv")
    if os.path.exists(epath) or summary.get("energy_J"):
        blocks.append("<h2>Energy balance</h2>")
    if os.path.exists(epath):
        t, c = read_csv(epath)
        terms = ["kinetic", "internal", "hourglass", "eroded", "transmitting", "constraints", "join", "join_face",
                 "contact"]
        fig, (ax, ax2) = plt.subplots(2, 1, figsize=(7.5, 6.4), sharex=True)
        for k in terms:
            col = "energy." + k
            if col in c and np.nanmax(np.abs(c[col])) > 0:
                ax.plot(t * 1e3, c[col] / 1e6, label=energy_name(k))
        ax.set_ylabel("energy [MJ, full revolution]")
        ax.set_title("Energy history (work terms: done on the model)")
        ax.legend(fontsize=8, ncol=2)
        e0 = c["energy.kinetic"][0] + c["energy.internal"][0]
        ax2.plot(t * 1e3, c["energy.residual"] / e0 * 100, label="residual / E0")
        ax2.plot(t * 1e3, -c["energy.join"] / e0 * 100, "--", label="− join work / E0 (booked as boundary work)")
        ax2.plot(t * 1e3, c["energy.relative_error"] * 100, ":", label="relative error (run)")
        ax2.set_xlabel("time [ms]")
        ax2.set_ylabel("% of initial energy")
        ax2.legend(fontsize=8)
        blocks.append((save(fig, figdir, "energy_history.png"),
                       "Energy history from energy.csv: the terms of the balance and the boundary work split into "
                       "transmitting dashpots, constraints and loads, SPH-FEM join work and contact work; below, "
                       "the signed residual (kinetic + internal + hourglass + eroded − initial − boundary work) "
                       "and the join work, as percentages of the initial energy."))
        rows = "".join(f"<tr><td>{energy_name(k)}</td><td>{c['energy.' + k][-1] / 1e6:.4g}</td>"
                       f"<td>{c['energy.' + k][-1] / e0 * 100:.3g}</td></tr>"
                       for k in terms + ["viscous", "sph_kinetic", "sph_internal", "bar_internal", "residual"]
                       if "energy." + k in c)
        blocks.append(f"<h3>Energy at t = {t[-1] * 1e3:.2f} ms</h3><table><tr><th>term</th><th>[MJ]</th>"
                      f"<th>% of the initial energy E0</th></tr>{rows}</table>")

    # Energy balance (summary.json holds the final state only).
    e = summary.get("energy_J", {})
    if e:
        fig, ax = plt.subplots(figsize=(7.5, 3.6))
        keys = ["kinetic", "internal", "hourglass", "viscous", "boundary_work", "initial_total"]
        vals = [e.get(k) or 0.0 for k in keys]
        ax.barh([energy_name(k) for k in keys], [v / 1e6 for v in vals], color=["C0", "C1", "C2", "C3", "C4", "0.5"])
        ax.set_xlabel("energy at the end of the run [MJ, full revolution]")
        ax.set_title(f"Energy balance at t = {summary.get('final_time_s', 0) * 1e3:.2f} ms: relative error "
                     f"{(e.get('relative_error') or 0) * 100:.2f} %")
        blocks.append((save(fig, figdir, "energy_balance.png"),
                       "Energy balance at the end of the run (summary.json)."))

    status = (f"{html.escape(str(summary.get('stop_reason')))} at t = {summary.get('final_time_s', 0) * 1e3:.3f} ms "
              f"(end time {summary.get('end_time_s', 0) * 1e3:.1f} ms) after {summary.get('cycles')} cycles, "
              f"{summary.get('wall_seconds', 0):.0f} s wall time")
    body = [f"<h1>{html.escape(summary.get('title') or 'Camouflet run')}</h1>",
            f"<p>{W:g} kg TNT at {d:g} m depth; structure {standoff:g} – {standoff + length:g} m from the axis"
            f"{interface}. Run: {status}.</p>"]
    if summary.get("failed"):
        body.append("<p><b>The run stopped early (numerical failure): the figures show the time simulated.</b></p>")
    for b in blocks:
        body.append(b if isinstance(b, str) else
                    f"<figure><img src='report/{b[0]}'><figcaption>{html.escape(b[1])}</figcaption></figure>")
    page = ("<!doctype html><html><head><meta charset='utf-8'><title>Camouflet report</title><style>"
            "body{font-family:sans-serif;max-width:70em;margin:auto}img{max-width:100%}"
            "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:2px 8px}"
            "td+td{white-space:nowrap}h2{margin-top:1.6em;border-bottom:1px solid #ccc}figure{margin:1em 0}"
            "figcaption{color:#444;margin-bottom:2em}</style></head><body>" + "\n".join(body) + "</body></html>\n")
    path = os.path.join(out, "report.html")
    with open(path, "w") as f:
        f.write(page)
    print(f"report: {os.path.abspath(path)} ({sum(not isinstance(b, str) for b in blocks)} figures)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
