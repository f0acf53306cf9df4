#!/usr/bin/env bash
# Installs what Camouflet needs from Debian 12 packages (only those missing),
# then configures and builds it (Release) in build/. Safe to run repeatedly.
# Usage: scripts/setup.sh [--target TARGET] [extra cmake args]
#   --target TARGET  build only TARGET and what it needs (e.g. camouflet, the
#                    executable: the main job needs no tests or benchmarks)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

target=()
if [ "${1:-}" = "--target" ]; then
  [ $# -ge 2 ] || { echo "setup: --target needs a target name" >&2; exit 2; }
  target=(--target "$2")
  shift 2
fi

packages=(g++ cmake ninja-build pkg-config python3 python3-numpy python3-scipy python3-matplotlib
          libgtest-dev libgmock-dev libbenchmark-dev libfmt-dev libtomlplusplus-dev libcli11-dev
          libeigen3-dev libgmsh-dev libhdf5-dev
          libopenmpi-dev openmpi-bin libmetis-dev  # runs across ranks (docs/parallel.md)
          python3-vtk9  # the test that reads a run's .pvtu with VTK's own reader
          chromium)  # the test that opens a run's report.html as a reader would (scripts/report_in_browser.py)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then sudo=sudo; else sudo=; fi
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j "$jobs" "${target[@]}"
