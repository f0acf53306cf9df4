#!/usr/bin/env bash
# The whole-run benchmark on the standard problems (bench/bench_problems.hpp), on 1 and 2
# threads, each run repeated; with --against REV, the build of another commit alternated with
# this one's run for run, so that both see the same machine. Every JSON line (each names its
# commit, flags, compiler, host, threads and load average) is appended to
# bench/results/<date>.jsonl, and a table of medians is printed at the end.
#
# Usage: bench/run_all.sh [--size-scale F] [--repeat N] [--against REV] [--problems "P ..."]
#                         [--threads "T ..."]
#   --size-scale F   every problem F times its full size (F < 1 for a quick look)
#   --repeat N       runs of each problem and thread count per build (default 3)
#   --against REV    also build REV (a git worktree under build-bench-against/) and alternate
#                    its runs with this tree's: A B, then B A, ...
#   --problems       default "taylor_bar hex_impact sedov_hex soil_axisymmetric buried_coarse"
#   --threads        default "1 2"
#   --build DIR      this tree's build folder (default build-bench; `build` of scripts/setup.sh
#                    has the benchmarks too)
# Compare medians of alternated runs on an idle machine, never single runs (docs/performance.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scale=1
repeat=3
against=
problems="taylor_bar hex_impact sedov_hex soil_axisymmetric buried_coarse"
thread_counts="1 2"
build_dir=build-bench
while [[ $# -gt 0 ]]; do
  case $1 in
    --size-scale) scale=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --against) against=$2; shift 2 ;;
    --problems) problems=$2; shift 2 ;;
    --threads) thread_counts=$2; shift 2 ;;
    --build) build_dir=$2; shift 2 ;;
    *) echo "bench/run_all.sh: unknown argument '$1' (see the header of bench/run_all.sh)" >&2; exit 2 ;;
  esac
done

build() {  # build SOURCE_DIR BUILD_DIR: a new folder gets Release without tests; an existing one
  # keeps its options and is only configured again (which refreshes the commit in the lines)
  if [[ -f $2/CMakeCache.txt ]]; then cmake -S "$1" -B "$2" >/dev/null
  else cmake -S "$1" -B "$2" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAMOUFLET_BENCHMARKS=ON -DCAMOUFLET_TESTS=OFF >/dev/null; fi
  cmake --build "$2" --target camouflet_bench >/dev/null
}

# The --against build runs first in each pair, so the table's ratios read "this tree / REV".
binaries=()
commits=()
if [[ -n $against ]]; then
  other="$root/build-bench-against/src"
  if [[ -d $other ]]; then git -C "$other" checkout -q --detach "$against"
  else git worktree add -q --detach "$other" "$against"; fi
  build "$other" "$root/build-bench-against/build"
  binaries+=("$root/build-bench-against/build/bench/camouflet_bench")
  commits+=("$(git -C "$other" describe --always --dirty --abbrev=12)")
fi
build "$root" "$build_dir"
binaries+=("$(cd "$build_dir" && pwd)/bench/camouflet_bench")
commits+=("$(git describe --always --dirty --abbrev=12)")

out=bench/results/$(date -u +%Y-%m-%d).jsonl
mkdir -p bench/results
lines=$(mktemp)
size() { awk -v n="$1" -v s="$scale" 'BEGIN { printf "%d", n * s }'; }
for problem in $problems; do
  case $problem in
    taylor_bar) n=$(size 73746) ;;
    hex_impact | sedov_hex) n=$(size 91125) ;;
    soil_axisymmetric) n=$(size 100000) ;;
    *) n=0 ;;
  esac
  for threads in $thread_counts; do
    args=("$problem" --threads "$threads")
    if [[ $n -gt 0 ]]; then args+=(--size "$n"); fi
    for ((round = 0; round < repeat; ++round)); do
      order=(0)
      if [[ ${#binaries[@]} -eq 2 ]]; then
        if (( round % 2 == 0 )); then order=(0 1); else order=(1 0); fi
      fi
      for k in "${order[@]}"; do
        # A build older than a problem does not know it (usage error, exit 2): skipped.
        if ! line=$(OMP_PROC_BIND=close "${binaries[k]}" "${args[@]}"); then
          echo "skipped: ${binaries[k]} ${args[*]}" >&2
          continue
        fi
        # Lines of builds older than the "commit" key get it here.
        if [[ $line != *'"commit"'* ]]; then line="${line%\}},\"commit\":\"${commits[k]}\"}"; fi
        echo "$line" | tee -a "$out" >>"$lines"
        echo "$line" | cut -c1-160
      done
    done
  done
done
echo "appended to $out"
/usr/bin/env python3 "$root/bench/median_table.py" "$lines"
rm -f "$lines"
