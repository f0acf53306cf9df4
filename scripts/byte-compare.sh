#!/usr/bin/env bash
# Runs one case with two builds of camouflet and compares what they wrote, byte
# for byte: every CSV of the output folder (gauges, energy, structure, members,
# bars) and the final checkpoint. A refactoring that must not change results
# lands only when this prints "identical" for each thread count asked.
# Usage: scripts/byte-compare.sh OLD_EXE NEW_EXE CASE.toml END_TIME_S [THREADS...]
#   e.g. scripts/byte-compare.sh /work/base/build/camouflet build/camouflet \
#          cases/wang2005/coarse.toml 0.07 1 2
# The case is copied beside itself with end_time set to END_TIME_S and a
# [checkpoint] block that writes only the end-of-run checkpoint; outputs go to
# build/byte-compare/<case>-<end time>-t<threads>/{old,new}. A checkpoint
# written by a build that still stamped times into it is compared dataset by
# dataset with h5diff (Debian package hdf5-tools), when that is installed.
# Where a change must alter an order of summation, what differs is listed: per
# CSV column the rows and the largest difference relative to the column's
# largest value; per checkpoint the datasets, and whether all are within 1e-12.
set -euo pipefail
[ $# -ge 4 ] || { sed -n 2,16p "$0" >&2; exit 2; }
old=$1 new=$2 case_file=$3 end_time=$4
shift 4
threads=("$@")
[ ${#threads[@]} -gt 0 ] || threads=(1)
root=$(cd "$(dirname "$0")/.." && pwd)
name=$(basename "$case_file" .toml)
copy="$(dirname "$case_file")/.byte-compare-$name.toml"
trap 'rm -f "$copy"' EXIT
if grep -q '^\[checkpoint\]' "$case_file"; then
  echo "byte-compare: $case_file has its own [checkpoint] block; remove it for the comparison" >&2
  exit 2
fi
sed -E "s/^end_time = [^#]*/end_time = $end_time /" "$case_file" > "$copy"
printf '\n[checkpoint]\ninterval_cycles = 1000000000\nkeep = 1\n' >> "$copy"
# For a CSV that differs: per column, the rows that differ and the largest difference relative
# to the column's largest magnitude (a changed order of summation shows as ~1e-16).
column_differences() {
  python3 - "$1" "$2" <<'PY'
import csv, sys
old = list(csv.reader(open(sys.argv[1])))
new = list(csv.reader(open(sys.argv[2])))
if len(old) != len(new) or old[0] != new[0]:
    print(f"    rows {len(old)} against {len(new)}, or other columns")
    sys.exit()
for c, name in enumerate(old[0]):
    try:
        a = [float(r[c]) for r in old[1:]]
        b = [float(r[c]) for r in new[1:]]
    except ValueError:
        continue
    rows = sum(x != y for x, y in zip(a, b))
    if rows:
        scale = max(max(abs(x) for x in a), 1e-300)
        worst = max(abs(x - y) for x, y in zip(a, b))
        print(f"    {name}: {rows} rows differ, largest by {worst:.3g} = {worst / scale:.3g} of the column's largest value")
PY
}
status=0
for t in "${threads[@]}"; do
  out="$root/build/byte-compare/$name-$end_time-t$t"
  rm -rf "$out"; mkdir -p "$out"
  for side in old new; do
    exe=$old
    [ $side = new ] && exe=$new
    "$exe" run "$copy" -o "$out/$side" --quiet --threads "$t" > "$out.$side.log" 2>&1 || {
      echo "byte-compare: $side run failed (threads $t), see $out.$side.log" >&2; status=1; continue 2; }
  done
  differ=0 files=0
  while IFS= read -r f; do
    files=$((files + 1))
    cmp -s "$out/old/$f" "$out/new/$f" || { echo "  differs: $f"; differ=1; column_differences "$out/old/$f" "$out/new/$f"; }
  done < <(cd "$out/old" && find . -name '*.csv' | sort)
  old_cp=$(ls "$out/old/checkpoints/"*.h5 | tail -1) new_cp=$(ls "$out/new/checkpoints/"*.h5 | tail -1)
  files=$((files + 1))
  if ! cmp -s "$old_cp" "$new_cp"; then
    # Builds before 6 Dec 2026 wrote the HDF5 object headers' times into each
    # checkpoint; against such a build only the datasets can be compared.
    if command -v h5diff >/dev/null && h5diff -q "$old_cp" "$new_cp" >/dev/null 2>&1; then
      echo "  checkpoint $(basename "$old_cp"): every dataset identical (h5diff), file bytes differ (header times)"
    else
      echo "  differs: checkpoint $(basename "$old_cp") / $(basename "$new_cp")"; differ=1
      if command -v h5diff >/dev/null; then
        # The datasets that differ by more than 1e-12 relative (the round-off bound of a changed sum order).
        beyond=$(h5diff -p 1e-12 "$old_cp" "$new_cp" 2>&1 | grep '^dataset' || true)
        if [ -z "$beyond" ]; then
          echo "    every dataset of both within 1e-12 relative (h5diff -p 1e-12)"
        else
          echo "$beyond" | sed 's/^/    beyond 1e-12: /' | head -20
        fi
        { h5diff "$old_cp" "$new_cp" 2>&1 | grep '^dataset' || true; } | sed 's/^/    differs: /' | head -20
        { diff <(h5ls -r "$old_cp" | awk '{print $1}') <(h5ls -r "$new_cp" | awk '{print $1}') || true; } |
          sed -n 's/^< /    only in the old: /p; s/^> /    only in the new: /p' | head -20
      fi
    fi
  fi
  if [ $differ = 0 ]; then echo "$name to $end_time s, $t thread(s): identical ($files files)"; else
    echo "$name to $end_time s, $t thread(s): DIFFERENT"; status=1; fi
done
exit $status
