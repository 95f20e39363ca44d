#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Benchmark (not a test): analysis time of RC ladders of 1000, 10000 and
# 100000 bonds. usage: bench/ladder.sh [BGDRAW]  (default build/bgdraw)
# Prints seconds for `--check` and for `-o x.json` per size, and the ratio
# to the previous size (about 10 when the analysis is linear).
set -e
here=$(cd "$(dirname "$0")" && pwd)
exe=${1:-$here/../build/bgdraw}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }
prev_c=""
prev_j=""
printf '%8s %10s %7s %10s %7s\n' bonds check_s ratio json_s ratio
for bonds in 1000 10000 100000; do
  n=$((bonds / 4))
  python3 "$here/gen_ladder.py" "$n" "$tmp/l$bonds.bg"
  t0=$(now); "$exe" "$tmp/l$bonds.bg" --check >/dev/null; t1=$(now)
  "$exe" "$tmp/l$bonds.bg" -o "$tmp/l$bonds.json" >/dev/null 2>&1 || echo "(json output failed)" >&2
  t2=$(now)
  c=$(echo "$t1 - $t0" | bc -l); j=$(echo "$t2 - $t1" | bc -l)
  rc="-"; rj="-"
  [ -n "$prev_c" ] && rc=$(echo "$c / $prev_c" | bc -l | cut -c1-5)
  [ -n "$prev_j" ] && rj=$(echo "$j / $prev_j" | bc -l | cut -c1-5)
  printf '%8s %10.3f %7s %10.3f %7s\n' "$bonds" "$c" "$rc" "$j" "$rj"
  prev_c=$c; prev_j=$j
done
