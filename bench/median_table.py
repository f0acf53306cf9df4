#!/usr/bin/env python3
"""Medians of camouflet_bench JSON lines, by problem, thread count and commit.

Usage: bench/median_table.py FILE.jsonl [...]

Prints one row per (problem, threads, commit): the number of runs, the median CPU and wall
grind times (ns per element- or particle-cycle; CPU = all threads), their range, ns per
neighbour for SPH, the median load average, and, where two commits ran the same problem
on the same thread count, the ratio of the second's median CPU grind time to the first's.
The speed-up from 1 to 2 threads is the ratio of wall medians (meaningful on an idle machine only).
"""
import json
import statistics
import sys
from collections import OrderedDict


def read(paths):
    rows = []
    for path in paths:
        with open(path) as f:
            for line in f:
                line = line.strip()
                if not line.startswith("{"):
                    continue
                r = json.loads(line)
                if "grind_cpu_ns" in r:
                    rows.append(r)
    return rows


def main(paths):
    rows = read(paths)
    groups = OrderedDict()
    for r in rows:
        key = (r["problem"], r["threads"], r.get("commit", "unknown"))
        groups.setdefault(key, []).append(r)
    if not groups:
        print("no benchmark lines")
        return
    print(f"{'problem':18} {'thr':>3} {'commit':20} {'runs':>4} {'cpu ns':>9} {'range':>17} "
          f"{'wall ns':>9} {'ns/nbr':>7} {'load':>5} {'cpu vs first commit':>19}")
    first_commit = {}
    wall = {}
    for (problem, threads, commit), rs in groups.items():
        cpu = [r["grind_cpu_ns"] for r in rs]
        med = statistics.median(cpu)
        wall_med = statistics.median(r["grind_wall_ns"] for r in rs)
        wall[(problem, threads, commit)] = wall_med
        pair = [r["ns_per_pair_cpu"] for r in rs if "ns_per_pair_cpu" in r]
        load = statistics.median(r.get("load_average", -1) for r in rs)
        base = first_commit.setdefault((problem, threads), (commit, med))
        ratio = f"{med / base[1]:.3f}" if base[0] != commit else "-"
        nbr = f"{statistics.median(pair):7.2f}" if pair else "      -"
        print(f"{problem:18} {threads:>3} {commit:20} {len(rs):>4} {med:9.1f} "
              f"{min(cpu):8.1f}-{max(cpu):8.1f} {wall_med:9.1f} {nbr} {load:5.2f} {ratio:>19}")
    for (problem, threads, commit), w in wall.items():
        if threads != 1:
            one = wall.get((problem, 1, commit))
            if one:
                print(f"{problem} at {commit}: {threads} threads give {one / w:.2f}x the speed of 1 (wall medians)")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
