#!/usr/bin/env python3
"""The motion of the SPH particle columns next to the axis of an r-z run.

Reads a particle snapshot (particles_NNNN.vtu) and reports, for the first few
columns of soil particles (grouped by their initial distance from the axis),
the mean axial and radial displacement of the particles that started in a
depth band below the charge centre. A spherical cavity expansion moves the
first two columns down alike (within about 1 %) and outwards in proportion to
their radius (the hoop strain u_r / r the same in both); docs/theory/sph.md,
"The first columns next to the axis", says why the ratio of the first
column's axial travel to the second's is the axis treatment's measure.

    scripts/axis_columns.py RUN_DIR [--frame N] [--charge-z -0.5]
                            [--band 0.7 1.4] [--columns 3] [--json]
"""
import argparse
import glob
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_metrics import read_vtu  # noqa: E402


def read_particles(path):
    """(time, {name: array}) of a particle snapshot (run_metrics.read_vtu reads the arrays)."""
    points, _, arrays = read_vtu(path)
    arrays.setdefault("position", points)
    time = None
    for node in ET.parse(path).getroot().iter("DataArray"):
        if node.get("Name") == "TimeValue":
            time = float(node.text)
    for key in ("position", "displacement", "material"):
        if key not in arrays:
            sys.exit(f"{path}: no '{key}' array in the particle snapshot")
    return time, arrays


def column_motion(arrays, charge_z, band, columns):
    """Mean (u_z, u_r) of each of the first `columns` soil columns in the depth band."""
    x = arrays["position"]
    u = arrays["displacement"]
    x0 = x - u
    material = arrays["material"].astype(int)
    # The soil is the material of the particles farthest from the charge.
    far = np.argmax(np.hypot(x0[:, 0], x0[:, 1] - charge_z))
    soil = material == material[far]
    below = charge_z - x0[:, 1]
    in_band = soil & (below >= band[0]) & (below <= band[1])
    radii = np.unique(np.round(x0[in_band, 0], 6))
    if len(radii) < columns:
        sys.exit(f"only {len(radii)} soil columns in the band {band} m below the charge")
    out = []
    for k in range(columns):
        pick = in_band & (np.abs(x0[:, 0] - radii[k]) < 1e-6)
        out.append({"r0": float(radii[k]), "particles": int(pick.sum()),
                    "u_z": float(u[pick, 1].mean()), "u_r": float(u[pick, 0].mean()),
                    "u_z_min": float(u[pick, 1].min()),
                    **{name: float(arrays[name][pick].mean()) for name in ("pressure", "plastic_strain", "damage", "density")
                       if name in arrays}})
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run_dir")
    parser.add_argument("--frame", type=int, default=-1, help="snapshot number (default: the last)")
    parser.add_argument("--charge-z", type=float, default=-0.5, help="charge centre z, m")
    parser.add_argument("--band", type=float, nargs=2, default=[0.7, 1.4],
                        help="depth band below the charge centre, m (initial positions)")
    parser.add_argument("--columns", type=int, default=3)
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--verbose", action="store_true", help="also the columns' mean pressure, plastic strain, damage, density")
    args = parser.parse_args()
    frames = sorted(glob.glob(os.path.join(args.run_dir, "particles_*.vtu")),
                    key=lambda p: int(re.search(r"_(\d+)\.vtu$", p).group(1)))
    if not frames:
        sys.exit(f"{args.run_dir}: no particles_*.vtu")
    path = frames[args.frame] if args.frame < 0 else os.path.join(args.run_dir, f"particles_{args.frame:04d}.vtu")
    time, arrays = read_particles(path)
    cols = column_motion(arrays, args.charge_z, args.band, args.columns)
    ratio = cols[0]["u_z"] / cols[1]["u_z"] if cols[1]["u_z"] != 0 else float("nan")
    if args.json:
        print(json.dumps({"snapshot": path, "time_s": time, "columns": cols,
                          "axial_ratio_first_to_second": ratio}, indent=1))
        return
    print(f"{path}: t = {time} s, soil {args.band[0]}-{args.band[1]} m below the charge centre")
    for k, c in enumerate(cols):
        print(f"  column {k + 1} (r0 = {c['r0']:.4f} m, {c['particles']} particles): "
              f"u_z {c['u_z']:+.4f} m (deepest {c['u_z_min']:+.4f}), u_r {c['u_r']:+.4f} m, "
              f"u_r / r0 {c['u_r'] / c['r0']:+.3f}")
        if args.verbose:
            print("      " + ", ".join(f"{k} {c[k]:.4g}" for k in ("pressure", "plastic_strain", "damage", "density") if k in c))
    print(f"  axial travel, first column / second: {ratio:.3f}")


if __name__ == "__main__":
    main()
