#!/usr/bin/env bash
# Grind time of the explicit FEM cycle: builds the benchmark
# tree (build-bench/, Release, benchmarks on) and runs an elastic problem of
# about 100k hex8 elements on 1 and 2 OpenMP threads, printing ns per
# element-cycle. The targets are ~325 ns single core and >= 1.85x on 2 threads.
# Usage: bench/grind_time.sh [elements] [cycles]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
elements=${1:-100000}
cycles=${2:-50}
cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAMOUFLET_BENCHMARKS=ON -DCAMOUFLET_TESTS=OFF >/dev/null
cmake --build build-bench --target grind_time >/dev/null
for threads in 1 2; do
  OMP_NUM_THREADS=$threads OMP_PROC_BIND=close build-bench/bench/grind_time --elements "$elements" --cycles "$cycles"
done
