#!/usr/bin/env bash
# Builds Camouflet (installing what is missing) and runs the default test suite
# (everything but the "long" label), then regenerates docs/verification-report.md.
# Long verification runs: scripts/test.sh -L long   (extra args go to ctest)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scripts/setup.sh
rm -rf build/verification
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(-LE long)
# ctest runs tests side by side on few cores: spinning OpenMP threads would
# steal them from each other.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
status=0
ctest --test-dir build --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "${args[@]}" || status=$?
python3 scripts/verification_report.py build/verification docs/verification-report.md || true
exit $status
