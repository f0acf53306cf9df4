#!/bin/sh
# A checkpoint written on 2 MPI ranks restarts on 2 ranks to the same result bit for bit, and is
# refused on 3 ranks and on one with a message naming the count (docs/parallel.md).
# Usage: restart_on_ranks.sh MPIEXEC CAMOUFLET CASE OUTDIR
set -eu
mpiexec=$1 camouflet=$2 case=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
# The case with checkpoints every 50 cycles; the same stopped at cycle 120 (max_cycles may change on
# a restart, docs/reliability.md).
cp "$case" "$out/whole.toml"
printf '\n[checkpoint]\ninterval_cycles = 50\nkeep = 3\n' >> "$out/whole.toml"
sed 's/^\[run\]/[run]\nmax_cycles = 120/' "$out/whole.toml" > "$out/stopped.toml"
run2() { "$mpiexec" -np 2 --oversubscribe "$camouflet" run -q "$@"; }
run2 "$out/whole.toml" -o "$out/whole" > /dev/null
run2 "$out/stopped.toml" -o "$out/restarted" > /dev/null
grep -q '"cycles": 120' "$out/restarted/summary.json" || { echo "the stopped run did not stop at cycle 120"; exit 1; }
run2 "$out/whole.toml" -o "$out/restarted" --restart latest > /dev/null
files=$(cd "$out/whole" && find . -name '*.csv' -o -name '*.pvtu' -o -name '*.vtu' -o -name '*.pvd' | sort)
[ -n "$files" ] || { echo "no output files"; exit 1; }
for name in $files; do
  cmp -s "$out/whole/$name" "$out/restarted/$name" || { echo "$name differs after the restart on 2 ranks"; exit 1; }
done
echo "restart on 2 ranks: $(echo $files | wc -w) gauge, energy and field files (pieces too) the same bits as the run without a stop"
if "$mpiexec" -np 3 --oversubscribe "$camouflet" run -q "$out/whole.toml" -o "$out/restarted" --restart latest \
    > "$out/three.log" 2>&1; then
  echo "a restart on 3 ranks was not refused"; exit 1
fi
grep -q "written on 2 ranks; restart on as many" "$out/three.log" || { cat "$out/three.log"; exit 1; }
if "$camouflet" run -q "$out/whole.toml" -o "$out/restarted" --restart latest > "$out/one.log" 2>&1; then
  echo "a restart on one rank was not refused"; exit 1
fi
grep -q "written on 2 ranks; restart on as many" "$out/one.log" || { cat "$out/one.log"; exit 1; }
echo "refused on 3 ranks and on one: $(grep -h 'written on' "$out/three.log" | head -1)"
