#!/usr/bin/python3
"""Side-by-side table of the headline results of several buried-structure runs
(`camouflet compare OUTDIR...`, docs/buried-structure.md "Comparing runs").

Its first use is the buried-structure case's convergence table (coarse -> default -> paper
resolution of the same case), but any runs of cases made by `camouflet
generate` can be compared. Every quantity has the report's definition
(scripts/run_metrics.py). Writes a Markdown table to standard output (one row
per quantity, one column per run) and, with --csv, the same numbers as CSV.
Standard library and NumPy only.
"""
import argparse
import csv
import json
import math
import os
import sys

from run_metrics import band_ratio, generator_parameters, ground_shock_peaks, read_csv, run_metrics

nan = float("nan")


def summary(outdir):
    try:
        with open(os.path.join(outdir, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def interface_stress_peak(outdir):
    """Peak compressive normal stress on the front wall's soil face at target 9 (Fig. 11), MPa."""
    path = os.path.join(outdir, "structure.csv")
    if not os.path.exists(path):
        return nan
    _, cols = read_csv(path)
    s = cols.get("t9.stress_xx")
    return float(max(-s)) / 1e6 if s is not None and len(s) else nan


def fmt(v, digits=3):
    if isinstance(v, str):
        return v
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "—"
    if isinstance(v, int):
        return str(v)
    return f"{v:.{digits}g}"


def collect(outdir, camouflet):
    """[(quantity, value, shown)] of one run, in table order."""
    s = summary(outdir)
    gen = generator_parameters(os.path.join(outdir, "case.toml"))
    m = run_metrics(outdir, camouflet)
    rows = [("simulated time [ms]", m["final_time_s"] * 1e3, None),
            ("stop reason", m["stop_reason"], None),
            ("cycles", s.get("cycles", nan), None),
            ("wall time [s]", s.get("wall_seconds", nan), None),
            ("energy balance error [%]", m["energy_error"] * 100.0, None)]
    shock = ground_shock_peaks(outdir, gen.get("burst_depth_m", 0.5), gen.get("charge_mass_kg", 100.0))
    inside = {}
    for group, gauges in shock.items():
        letter = group[-1]
        inside[letter] = [0, 0]
        for g, Z, R, peak in gauges:
            ratio = band_ratio(Z, peak)
            shown = fmt(peak) + ("" if ratio == 1.0 else f" ({ratio:.2f}×)")
            rows.append((f"{g} peak radial stress [MPa], Z = {Z:.2f}", peak, shown))
            # The generator places the groups at Z = 0.3 ... 2.5 (must-show 2's range), snapped to the mesh.
            inside[letter][0] += ratio == 1.0
            inside[letter][1] += 1
    for letter, (n, total) in inside.items():
        rows.append((f"group {letter} within ×1.5 of the TM-5 band", f"{n} of {total}", None))
    if "group_A" in shock and "group_B" in shock:
        # Gauge k of both groups lies at the same range (A along the charge depth, B down at 45°).
        a = {g[1:]: p for g, _, _, p in shock["group_A"]}
        pairs = [(a[g[1:]], p) for g, _, _, p in shock["group_B"] if g[1:] in a]
        below = sum(pa < pb for pa, pb in pairs)
        rows.append(("group A below group B at equal range", f"{below} of {len(pairs)}", None))
    rows += [("front-wall peak horizontal velocity [m/s]", m["front_wall_peak_velocity_m_s"], None),
             ("floor peak vertical velocity [m/s]", m["floor_peak_velocity_m_s"], None),
             ("TM-5 average velocity [m/s]", f"{fmt(m['tm5_velocity_low_m_s'])}–{fmt(m['tm5_velocity_high_m_s'])}",
              None),
             ("front-wall peak acceleration [g]", m["front_wall_peak_acceleration_g"], None),
             ("floor peak acceleration [g]", m["floor_peak_acceleration_g"], None),
             ("front-wall peak deflection [mm]", m["front_wall_peak_deflection_mm"], None),
             ("floor peak deflection [mm]", m["floor_peak_deflection_mm"], None),
             ("front-wall final displacement [mm]", m["front_wall_final_displacement_mm"], None),
             ("floor final displacement [mm]", m["floor_final_displacement_mm"], None),
             ("interface stress at t9, peak [MPa]", interface_stress_peak(outdir), None),
             ("largest damage (member)", m["max_damage"], f"{fmt(m['max_damage'], 2)} ({m['max_damage_member']})"
              if m["max_damage_member"] else None),
             ("front-wall mean damage", m["front_wall_mean_damage"], None),
             ("largest mean damage of the other members", m["other_members_mean_damage"], None),
             ("apparent crater radius [m]", m["crater_radius_m"], None),
             ("apparent crater depth [m]", m["crater_depth_m"], None)]
    return rows


def richardson(values, ratio):
    """(order p, Richardson estimate, None) of f_coarse, f_medium, f_fine on meshes each finer by
    `ratio`, or (nan, nan, reason) where three values do not allow one: the differences
    e1 = f_medium - f_coarse and e2 = f_fine - f_medium must have the same sign and shrink
    (monotone convergence); then p = ln(e1 / e2) / ln(ratio) and f = f_fine + e2 / (ratio^p - 1)."""
    try:
        f1, f2, f3 = (float(v) for v in values)
    except (TypeError, ValueError):
        return nan, nan, "—"
    if not all(math.isfinite(f) for f in (f1, f2, f3)):
        return nan, nan, "—"
    e1, e2 = f2 - f1, f3 - f2
    if e2 == 0.0:
        return nan, nan, "unchanged" if e1 == 0.0 else "fine = medium"
    if e1 * e2 < 0.0:
        return nan, nan, "oscillates"
    if abs(e2) >= abs(e1):
        return nan, nan, "diverges"
    p = math.log(e1 / e2) / math.log(ratio)
    return p, f3 + e2 / (ratio ** p - 1.0), None


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("outdirs", nargs="+", metavar="OUTDIR")
    ap.add_argument("--label", action="append", default=[], help="column heading, one per OUTDIR, in order")
    ap.add_argument("--csv", help="also write the numbers as CSV to this file")
    ap.add_argument("--camouflet", default="", help="camouflet executable (for `empirical --csv`)")
    ap.add_argument("--refinement", type=float, default=0.0,
                    help="three runs, coarse to fine, each finer by this ratio: add the observed order of "
                         "convergence and the Richardson estimate of each quantity")
    args = ap.parse_args()
    if args.label and len(args.label) != len(args.outdirs):
        sys.exit(f"error: {len(args.label)} --label for {len(args.outdirs)} output folders")
    if args.refinement and (len(args.outdirs) != 3 or not args.refinement > 1.0):
        sys.exit(f"error: --refinement needs three output folders (coarse to fine) and a ratio above 1, "
                 f"got {len(args.outdirs)} folders and {args.refinement:g}")
    labels = args.label or [os.path.basename(os.path.normpath(d)) for d in args.outdirs]
    runs = [collect(d, args.camouflet) for d in args.outdirs]
    order = []
    for rows in runs:
        for q, _, _ in rows:
            if q not in order:
                order.append(q)
    # Gauge rows are named with the first run's Z; finer meshes put the same gauge within a cell of it.
    keyed = []
    for rows in runs:
        keyed.append({q.split(" peak radial")[0] if " peak radial" in q else q: (v, shown) for q, v, shown in rows})
    names = []
    for q in order:
        key = q.split(" peak radial")[0] if " peak radial" in q else q
        if key not in [k for k, _ in names]:
            names.append((key, q))
    extra = ["observed order", "Richardson estimate"] if args.refinement else []
    print("| quantity | " + " | ".join(labels + extra) + " |")
    print("|---|" + "---|" * (len(labels) + len(extra)))
    orders = {}
    for key, q in names:
        cells = []
        for k in keyed:
            v, shown = k.get(key, (nan, None))
            cells.append(shown if shown is not None else fmt(v))
        if args.refinement:
            orders[key] = richardson([k.get(key, (nan, None))[0] for k in keyed], args.refinement)
            p, estimate, why = orders[key]
            cells += [fmt(p, 2) if why is None else why, fmt(estimate) if why is None else "—"]
        print(f"| {q} | " + " | ".join(cells) + " |")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(["quantity"] + labels + extra)
            for key, q in names:
                row = [q] + [k.get(key, (nan, None))[0] for k in keyed]
                if args.refinement:
                    p, estimate, why = orders[key]
                    row += [p if why is None else why, estimate if why is None else ""]
                w.writerow(row)


if __name__ == "__main__":
    main()
