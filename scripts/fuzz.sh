#!/usr/bin/env bash
# Fuzzes the case reader and the Gmsh import with libFuzzer: a clang
# build in build-fuzz/ with -DCAMOUFLET_FUZZ=ON, then the CTest tests labelled
# "fuzz", each running CAMOUFLET_FUZZ_SECONDS (default 60) seconds.
# -O1 -g1: line numbers in reports and a faster compile. CAMOUFLET_JOBS
# (default: nproc) sets the build parallelism. Extra arguments go to ctest
# (e.g. -R gmsh). A crash leaves its input as crash-* in build-fuzz/fuzz.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=${CAMOUFLET_JOBS:-$(nproc 2>/dev/null || echo 2)}
CXX=clang++ CC=clang cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCAMOUFLET_FUZZ=ON \
  -DCAMOUFLET_TESTS=OFF -DCAMOUFLET_BENCHMARKS=OFF -DCAMOUFLET_FUZZ_SECONDS="${CAMOUFLET_FUZZ_SECONDS:-60}"
cmake --build build-fuzz -j "$jobs" --target fuzz_case_reader fuzz_gmsh_import
ctest --test-dir build-fuzz --output-on-failure -L fuzz "$@"
