#!/usr/bin/env bash
# Runs the whole-run benchmark on every standard problem on 1 and
# 2 threads and appends the JSON lines to bench/results/<date>.jsonl.
# Usage: bench/run_all.sh [--size-scale F]   (F < 1 scales every problem down, e.g. 0.1)
# Builds build-bench/ (Release, benchmarks on). The machine's load average is
# in every line: on a shared machine compare grind_cpu_ns, not wall time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scale=1
if [[ ${1:-} == --size-scale ]]; then scale=$2; fi
cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAMOUFLET_BENCHMARKS=ON -DCAMOUFLET_TESTS=OFF >/dev/null
cmake --build build-bench --target camouflet_bench >/dev/null
out=bench/results/$(date -u +%Y-%m-%d).jsonl
mkdir -p bench/results
size() { awk -v n="$1" -v s="$scale" 'BEGIN { printf "%d", n * s }'; }
for problem in taylor_bar hex_impact soil_axisymmetric buried_coarse; do
  case $problem in
    taylor_bar) n=$(size 73746) ;;
    hex_impact) n=$(size 91125) ;;
    soil_axisymmetric) n=$(size 100000) ;;
    *) n=0 ;;
  esac
  for threads in 1 2; do
    args=("$problem" --threads "$threads")
    if [[ $n -gt 0 ]]; then args+=(--size "$n"); fi
    OMP_PROC_BIND=close build-bench/bench/camouflet_bench "${args[@]}" | tee -a "$out"
  done
done
echo "appended to $out"
