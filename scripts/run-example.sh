#!/usr/bin/env bash
# The main job: builds Camouflet (installing what is missing) and runs the
# example case, then says where the results are.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scripts/setup.sh
case_file=${1:-cases/examples/elastic_column.toml}
out=${2:-results/$(basename "$case_file" .toml)}
build/camouflet run "$case_file" -o "$out"
echo "Results are in $root/$out (summary.json, gauge CSVs, fields.pvd for ParaView)"
