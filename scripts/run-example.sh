#!/usr/bin/env bash
# The main job: builds Camouflet (installing what is missing), runs the
# coarse case of the paper's example (Wang et al. 2005, section 5:
# cases/wang2005/coarse.toml, about 10 minutes on 2 cores), writes its report
# (figures and one HTML page) and says where it is.
# Usage: scripts/run-example.sh [CASE.toml [OUTDIR]]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scripts/setup.sh --target camouflet  # the executable only: no tests, no benchmarks
case_file=${1:-cases/wang2005/coarse.toml}
out=${2:-results/$(basename "$case_file" .toml)}
build/camouflet run "$case_file" -o "$out"
build/camouflet report "$out"
echo "Results are in $root/$out (summary.json, gauge CSVs, fields.pvd for ParaView)"
echo "Report: $root/$out/report.html"
