#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Benchmark (not a test): every seed example (examples/*.bg) end to end:
# parse, causality, analysis, equations, numeric index, diagram (SVG),
# analysis JSON and simulation (CSV) in one run, as
#   bgdraw X.bg -o X.svg -o X.json -o X.csv -v
# Prints per example the wall time (best of RUNS, default 3), the
# simulation's own time (from -v), the exit status, and from the JSON's
# "simulation" object the outcome, solver, unknowns and steps.
# Usage: bash bench/examples_bench.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: examples_bench.sh PATH_TO_BGDRAW}
RUNS=${RUNS:-3}
case $BGDRAW in */*) BGDRAW=$(cd "$(dirname "$BGDRAW")" && pwd)/$(basename "$BGDRAW") ;; esac
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

now() { date +%s.%N; }
field() { # field KEY FILE: the value of "KEY": in the simulation object
  sed -n '/^  "simulation": {/,/^  }/p' "$2" | sed -n "s/^ *\"$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" | head -n 1
}
printf '%-22s %6s %8s %8s  %-8s %-12s %8s %7s\n' example exit total_s sim_s status solver unknowns steps
total=0
for f in examples/*.bg; do
  name=$(basename "$f" .bg)
  best=''
  for ((i = 0; i < RUNS; i++)); do
    s=$(now)
    "$BGDRAW" "$f" -o "$tmp/$name.svg" -o "$tmp/$name.json" -o "$tmp/$name.csv" -v 2>"$tmp/$name.err"
    st=$?
    e=$(now)
    best=$(awk -v a="$best" -v b="$(echo "$e - $s" | bc -l)" 'BEGIN { print (a == "" || b < a) ? b : a }')
  done
  sim=$(sed -n 's/.*simulate: \(done\|failed\) in \([0-9.]*\) s.*/\2/p' "$tmp/$name.err")
  steps=$(sed -n 's/.*"statistics": {"steps": \([0-9]*\),.*/\1/p' "$tmp/$name.json" 2>/dev/null)
  if [ -s "$tmp/$name.json" ] && grep -q '"simulation"' "$tmp/$name.json"; then
    status=$(field status "$tmp/$name.json"); solver=$(field solver "$tmp/$name.json")
    unknowns=$(field unknowns "$tmp/$name.json")
  else
    status='-' solver='-' unknowns='-'
  fi
  printf '%-22s %6s %8.3f %8s  %-8s %-12s %8s %7s\n' "$name" "$st" "$best" "${sim:--}" \
    "${status:--}" "${solver:--}" "${unknowns:--}" "${steps:--}"
  total=$(echo "$total + $best" | bc -l)
  if [ "$st" -ne 0 ]; then
    grep -E 'refused|failed|error' "$tmp/$name.err" | head -n 2 | cut -c1-150 | sed 's/^/    /'
  fi
done
printf 'total %.3f s for %d examples (best of %d runs each)\n' "$total" "$(ls examples/*.bg | wc -l)" "$RUNS"
