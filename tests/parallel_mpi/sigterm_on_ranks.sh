#!/bin/sh
# SIGTERM to mpirun stops every rank of a run at the same cycle with complete output and a
# checkpoint per rank that a restart on as many ranks reads (docs/parallel.md).
# Usage: sigterm_on_ranks.sh MPIEXEC CAMOUFLET CASE OUTDIR
set -u
mpiexec=$1 camouflet=$2 case=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
# The example run for 0.05 s (some 120,000 cycles: longer than the wait below on any machine).
sed 's/^end_time = .*/end_time = 0.05/' "$case" > "$out/long.toml"
"$mpiexec" -np 2 --oversubscribe "$camouflet" run -q "$out/long.toml" -o "$out/run" > "$out/run.log" 2>&1 &
launcher=$!
sleep 3
kill -TERM $launcher
wait $launcher
status=$?
cat "$out/run.log"
[ $status -ne 0 ] || { echo "mpirun exited 0 after SIGTERM"; exit 1; }
grep -q "interrupted by signal 15 at cycle" "$out/run.log" || { echo "no interruption message"; exit 1; }
c0=$(ls "$out/run/checkpoints/rank_0_of_2" 2>/dev/null)
c1=$(ls "$out/run/checkpoints/rank_1_of_2" 2>/dev/null)
[ -n "$c0" ] && [ "$c0" = "$c1" ] || { echo "checkpoints per rank differ: '$c0' / '$c1'"; exit 1; }
# Complete output: the gauge file's last row has every column.
header=$(head -1 "$out/run/foot.csv" | tr ',' '\n' | wc -l)
last=$(tail -1 "$out/run/foot.csv" | tr ',' '\n' | wc -l)
[ "$header" = "$last" ] || { echo "last gauge row incomplete: $last of $header columns"; exit 1; }
# The checkpoint reads: a restart on 2 ranks goes on for ten more cycles.
cycle=$(echo "$c0" | sed 's/checkpoint_0*\([0-9]*\)\.h5/\1/')
sed "s/^\[run\]/[run]\nmax_cycles = $((cycle + 10))/" "$out/long.toml" > "$out/more.toml"
"$mpiexec" -np 2 --oversubscribe "$camouflet" run -q "$out/more.toml" -o "$out/run" --restart latest > "$out/more.log" 2>&1 ||
  { cat "$out/more.log"; echo "the restart from the SIGTERM checkpoint failed"; exit 1; }
grep -q "\"cycles\": $((cycle + 10))" "$out/run/summary.json" || { echo "the restart did not reach cycle $((cycle + 10))"; exit 1; }
echo "SIGTERM at cycle $cycle: both ranks' checkpoints at that cycle, output complete, restart read"
