#!/usr/bin/env bash
# The quick test suite under AddressSanitizer + UndefinedBehaviorSanitizer
# (issue 9): a Debug build with -DCAMOUFLET_SANITIZE=ON in build-sanitize/.
# Extra arguments go to ctest (e.g. -R Restart). Takes a while: every layer
# is rebuilt instrumented and the tests run several times slower.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAMOUFLET_SANITIZE=ON \
  -DCAMOUFLET_BENCHMARKS=OFF
cmake --build build-sanitize -j "$(nproc 2>/dev/null || echo 2)"
# halt_on_error: the first report fails its test; OpenMP's runtime leaks a few
# thread-pool blocks on purpose, hence no leak detection.
export ASAN_OPTIONS=detect_leaks=0:halt_on_error=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(-LE "long|fuzz")
ctest --test-dir build-sanitize --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "${args[@]}"
