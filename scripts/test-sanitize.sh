#!/usr/bin/env bash
# The quick test suite under AddressSanitizer + UndefinedBehaviorSanitizer
# (docs/reliability.md): a build with -DCAMOUFLET_SANITIZE=ON in build-sanitize/
# (-O1 -g1: line numbers in reports, a faster compile than full debug info).
# UBSan is compiled with -fno-sanitize-recover=all, so every report (ASan or
# UBSan) ends its test process and fails the test.
# Extra arguments go to ctest (default: -LE "long|fuzz", the quick suite),
# e.g. scripts/test-sanitize.sh -R Restart.
# CAMOUFLET_JOBS (default: nproc) sets the build and ctest parallelism.
# Takes a while: every layer is rebuilt instrumented and the tests run
# several times slower (docs/reliability.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=${CAMOUFLET_JOBS:-$(nproc 2>/dev/null || echo 2)}
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCAMOUFLET_SANITIZE=ON -DCAMOUFLET_BENCHMARKS=OFF
cmake --build build-sanitize -j "$jobs"
# halt_on_error: the first report fails its test; OpenMP's runtime leaks a few
# thread-pool blocks on purpose, hence no leak detection.
export ASAN_OPTIONS=detect_leaks=0:halt_on_error=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(-LE "long|fuzz")
ctest --test-dir build-sanitize --output-on-failure -j "$jobs" "${args[@]}"
