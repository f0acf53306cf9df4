#!/usr/bin/python3
"""Results table and chart of a parameter study (`camouflet sweep`, docs/buried-structure.md).

Reads OUTDIR/cases.csv (written by `camouflet sweep`: case, the varied keys, status, message, wall time)
and each case's run folder OUTDIR/<case>/; writes OUTDIR/sweep.csv (cases.csv plus the headline results
of each run, by the report's definitions in run_metrics.py) and OUTDIR/sweep.png (matplotlib from
Debian's python3-matplotlib). A case that failed keeps its row: its results are what its output holds
(empty when nothing ran).
"""
import argparse
import csv
import math
import os
import sys

from run_metrics import run_metrics

# Results columns of sweep.csv, in order (run_metrics.run_metrics keys).
RESULTS = ("final_time_s", "stop_reason", "front_wall_member_peak_velocity_m_s", "floor_member_peak_velocity_m_s",
           "front_wall_member_filtered_acceleration_g", "floor_member_filtered_acceleration_g",
           "front_wall_peak_velocity_m_s", "floor_peak_velocity_m_s",
           "front_wall_peak_acceleration_g", "floor_peak_acceleration_g", "tm5_velocity_low_m_s",
           "tm5_velocity_high_m_s", "tm5_acceleration_low_g", "tm5_acceleration_high_g",
           "front_wall_peak_deflection_mm", "floor_peak_deflection_mm", "front_wall_final_displacement_mm",
           "floor_final_displacement_mm", "t9_peak_normal_stress_MPa", "t9_filtered_normal_stress_MPa",
           "max_damage", "max_damage_member", "front_wall_mean_damage", "front_wall_lower_mean_damage",
           "front_wall_upper_mean_damage", "other_members_mean_damage", "crater_radius_m", "crater_depth_m",
           "energy_error")


def number(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def text(v):
    if isinstance(v, float):
        return "" if math.isnan(v) else f"{v:.6g}"
    return str(v)


def chart(out, rows, varied):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ok = [r for r in rows if r["status"] == "0"]
    numeric = [k for k in varied if all(not math.isnan(number(r[k])) for r in rows if r[k] != "")
               and any(r[k] != "" for r in rows)]
    # x: the first numeric varied key; one line per combination of the other keys. Otherwise the case names.
    xkey = numeric[0] if numeric else None
    others = [k for k in varied if k != xkey]
    series = {}
    for r in ok:
        label = ", ".join(f"{k} = {r[k]}" for k in others if r[k] != "")
        series.setdefault(label, []).append(r)
    if xkey:
        for s in series.values():
            s.sort(key=lambda r: number(r[xkey]))
        xval = lambda r: number(r[xkey])  # noqa: E731
    else:
        order = {r["case"]: i for i, r in enumerate(rows)}
        xval = lambda r: order[r["case"]]  # noqa: E731
    # The in-structure panels show the member averages, which the TM 5-855-1 averages are compared with
    # (docs/buried-structure.md, "In-structure shock in the report"); the raw single-node peaks stay in sweep.csv.
    panels = (("member-average peak velocity [m/s]",
               (("front_wall_member_peak_velocity_m_s", "front wall (horizontal)"),
                ("floor_member_peak_velocity_m_s", "floor (vertical)")),
               ("tm5_velocity_low_m_s", "tm5_velocity_high_m_s")),
              ("member-average acceleration, 1 kHz low-passed [g]",
               (("front_wall_member_filtered_acceleration_g", "front wall"),
                ("floor_member_filtered_acceleration_g", "floor")),
               ("tm5_acceleration_low_g", "tm5_acceleration_high_g")),
              ("deflection / displacement [mm]", (("front_wall_peak_deflection_mm", "front-wall peak deflection"),
                                                  ("floor_peak_deflection_mm", "floor peak deflection"),
                                                  ("front_wall_final_displacement_mm", "front wall, final"),
                                                  ("floor_final_displacement_mm", "floor, final")), None),
              ("damage [-]", (("max_damage", "largest in the box"), ("front_wall_mean_damage", "front-wall mean"),
                              ("other_members_mean_damage", "other members' mean (largest)")), None),
              ("apparent crater [m]", (("crater_radius_m", "radius"), ("crater_depth_m", "depth")), None),
              ("energy balance error [%]", (("energy_error", "relative error"),), None))
    fig, axes = plt.subplots(2, 3, figsize=(15, 8.5))
    markers = "os^vD<>p"
    for ax, (ylabel, curves, band) in zip(axes.flat, panels):
        scale = 100.0 if ylabel.startswith("energy") else 1.0
        for si, (label, rs) in enumerate(series.items()):
            xs = [xval(r) for r in rs]
            for ci, (col, name) in enumerate(curves):
                ys = [number(r[col]) * scale for r in rs]
                ax.plot(xs, ys, marker=markers[si % len(markers)], ls="-" if xkey else "none", color=f"C{ci}",
                        label=name + (f" ({label})" if label else ""))
            if band:
                lo = [number(r[band[0]]) for r in rs]
                hi = [number(r[band[1]]) for r in rs]
                if len(xs) == 1 and not math.isnan(lo[0]):  # one point: bars instead of a band
                    ax.vlines(xs, [0.5 * lo[0]], [2.0 * hi[0]], color="0.8", lw=8, zorder=0,
                              label="0.5 × lower … 2 × upper TM 5-855-1 average" if si == 0 else None)
                    ax.vlines(xs, lo, hi, color="0.5", lw=8, zorder=0,
                              label="TM 5-855-1 average, n = 2.5 … 2 (f = 0.6)" if si == 0 else None)
                elif not all(math.isnan(v) for v in lo):
                    ax.fill_between(xs, lo, hi, color="0.6", alpha=0.35, zorder=0, step=None if xkey else "mid",
                                    label="TM 5-855-1 average, n = 2.5 … 2 (f = 0.6)" if si == 0 else None)
                    ax.fill_between(xs, [0.5 * v for v in lo], [2.0 * v for v in hi], color="0.85", alpha=0.35, zorder=0,
                                    step=None if xkey else "mid",
                                    label="0.5 × lower … 2 × upper average" if si == 0 else None)
        ax.set_ylabel(ylabel)
        ax.set_xlabel(xkey if xkey else "case")
        if not xkey:
            ax.set_xticks(range(len(rows)), [r["case"] for r in rows], rotation=45, ha="right", fontsize=8)
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    failed = len(rows) - len(ok)
    fig.suptitle(f"Parameter study: {len(ok)} of {len(rows)} cases ran to their end"
                 + (f" ({failed} failed: see sweep.csv)" if failed else ""))
    fig.tight_layout()
    path = os.path.join(out, "sweep.png")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("outdir")
    ap.add_argument("--camouflet", default="", help="camouflet executable (for `empirical --csv`)")
    args = ap.parse_args()
    with open(os.path.join(args.outdir, "cases.csv"), newline="") as f:
        reader = csv.DictReader(f)
        fields = list(reader.fieldnames)
        rows = list(reader)
    varied = fields[1:fields.index("status")]
    for r in rows:
        folder = os.path.join(args.outdir, r["case"])
        m = run_metrics(folder, args.camouflet) if os.path.exists(os.path.join(folder, "summary.json")) else {}
        for k in RESULTS:
            r[k] = text(m.get(k, ""))
    with open(os.path.join(args.outdir, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields + list(RESULTS), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    print(f"sweep: {os.path.join(args.outdir, 'sweep.csv')} ({len(rows)} cases)")
    try:
        print(f"sweep: {chart(args.outdir, rows, varied)}")
    except ImportError as e:
        print(f"sweep: no chart: {e} (install python3-matplotlib, scripts/setup.sh)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
