#!/usr/bin/env bash
# Fuzzes the case reader and the Gmsh import with libFuzzer (issue 9): a clang
# build in build-fuzz/ with -DCAMOUFLET_FUZZ=ON, then the CTest tests labelled
# "fuzz", each running CAMOUFLET_FUZZ_SECONDS (default 60) seconds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
CXX=clang++ CC=clang cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAMOUFLET_FUZZ=ON \
  -DCAMOUFLET_TESTS=OFF -DCAMOUFLET_BENCHMARKS=OFF -DCAMOUFLET_FUZZ_SECONDS="${CAMOUFLET_FUZZ_SECONDS:-60}"
cmake --build build-fuzz -j "$(nproc 2>/dev/null || echo 2)" --target fuzz_case_reader fuzz_gmsh_import
ctest --test-dir build-fuzz --output-on-failure -L fuzz "$@"
