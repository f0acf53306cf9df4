#!/usr/bin/env bash
# SPH grind time: ns per particle-cycle of the whole SPH
# cycle (neighbour update, forces, kick/drift, kinematics, material update) for
# ~100k particles in 2-D and 3-D, on 1 and 2 threads, with the mean neighbour
# count (from the force-loop benchmark). Needs a build with benchmarks:
#   cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAMOUFLET_BENCHMARKS=ON
#   cmake --build build-bench --target bench_sph
set -euo pipefail
bench=${1:-build-bench/bench/bench_sph}
for threads in 1 2; do
  echo "== ${threads} thread(s)"
  OMP_NUM_THREADS=${threads} "${bench}" --benchmark_filter='(full_cycle|force_loop)<[23]>/100000' \
    --benchmark_min_time=0.5 --benchmark_counters_tabular=true 2>/dev/null |
    awk '/full_cycle|force_loop|Benchmark/ {print}'
done
