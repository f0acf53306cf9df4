#!/usr/bin/env python3
"""Compares a run across MPI ranks with the serial run of the same case (docs/parallel.md).

Usage: compare_rank_runs.py SERIAL_DIR RANKS_DIR TOLERANCE

Every CSV of the serial output folder (the gauges' and energy.csv) must exist in the other with
the same columns and rows. Each quantity is compared over every gauge and component at once,
relative to its largest serial value (a column that is round-off in both runs, a transverse
velocity of 1e-16 m/s, is not a difference). The energies are compared relative to the largest
energy term. Prints the worst difference of each quantity; exits 1 when one exceeds TOLERANCE.
"""
import re
import sys
from pathlib import Path

import numpy as np


def quantity(column):
    """'p2.velocity_x' -> 'velocity'; 'energy.kinetic' -> 'energy'; 'time_s' -> 'time_s';
    'bottom.3.axial_stress' (bars.csv: bar, segment, quantity) -> 'axial_stress'."""
    name = column.split(".", 1)[-1] if column.startswith("p") or column.startswith("m") else column
    if column.startswith("energy."):
        return "energy" if column != "energy.relative_error" else "relative_error"
    if column.count(".") == 2:
        return column.rsplit(".", 1)[-1]
    return re.sub(r"_(x|y|z|xx|yy|zz|xy|yz|zx|r|theta)$", "", name)


def read(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def main():
    serial_dir, ranks_dir, tolerance = Path(sys.argv[1]), Path(sys.argv[2]), float(sys.argv[3])
    failed = False
    files = sorted(serial_dir.glob("*.csv"))
    if not files:
        print(f"no CSV files in {serial_dir}")
        return 1
    for serial_path in files:
        ranks_path = ranks_dir / serial_path.name
        if not ranks_path.exists():
            print(f"{serial_path.name}: missing from {ranks_dir}")
            failed = True
            continue
        header_s, s = read(serial_path)
        header_r, r = read(ranks_path)
        if header_s != header_r or s.shape != r.shape:
            print(f"{serial_path.name}: columns or rows differ ({s.shape} against {r.shape})")
            failed = True
            continue
        groups = {}
        for k, column in enumerate(header_s):
            groups.setdefault(quantity(column), []).append(k)
        worst = []
        for name, columns in groups.items():
            if name == "relative_error":
                continue  # a ratio of round-off sized residuals early in the run
            scale = np.max(np.abs(s[:, columns]))
            if scale == 0.0:
                diff = np.max(np.abs(r[:, columns]))
            else:
                diff = np.max(np.abs(r[:, columns] - s[:, columns])) / scale
            worst.append((name, diff))
            failed = failed or not diff <= tolerance
        print(f"{serial_path.name}: " + ", ".join(f"{n} {d:.2g}" for n, d in worst))
    print("differences within" if not failed else "differences beyond", f"{tolerance:g}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
