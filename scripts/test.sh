#!/usr/bin/env bash
# Builds Camouflet (installing what is missing) and runs the whole test suite,
# the quick tests and the "long" label (about 10 minutes of tests on 2 cores),
# then regenerates docs/verification-report.md from what ran.
# Quick tests only: scripts/test.sh -LE long   (extra args go to ctest)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scripts/setup.sh
rm -rf build/verification
args=("$@")
# ctest runs tests side by side on few cores: spinning OpenMP threads would
# steal them from each other.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
status=0
ctest --test-dir build --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" ${args[@]+"${args[@]}"} || status=$?
python3 scripts/verification_report.py build/verification docs/verification-report.md || true
exit $status
