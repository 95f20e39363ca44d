#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Flattening cost: N instances of a 10-element submodel against the same model
# written flat, through parse, flatten, compile and the whole causal analysis
# (--check) and with the JSON written, and drawn: the composed model with every
# instance collapsed into one box (--collapse all) against the flat model's
# full drawing (the drawing issue 14 asks for), and expanded (frames) too.
# Best of 3 runs each, in CPU time (user + system: the machine is shared, and
# wall-clock times there vary by several times; Graphviz runs in the process).
# Usage: bench/components.sh [N] [BGDRAW]   (default 1000, build/bgdraw)
set -eu
N=${1:-1000}
BGDRAW=${2:-build/bgdraw}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
python3 "$(dirname "$0")/gen_components.py" "$N" "$TMP/composed.bg" "$TMP/flat.bg"
best() { # best FILE ARGS...: the least CPU time (user + system) of 3 runs, in seconds
  local f=$1 b=999999 t
  shift
  for _ in 1 2 3; do
    t=$( { TIMEFORMAT='%3U %3S'; time "$BGDRAW" "$f" "$@" >/dev/null 2>&1; } 2>&1 | awk '{ print $1 + $2 }')
    b=$(echo "if ($t < $b) $t else $b" | bc -l)
  done
  printf '%.3f' "$b"
}
for args in "--check" "-o $TMP/x.json"; do
  c=$(best "$TMP/composed.bg" $args)
  f=$(best "$TMP/flat.bg" $args)
  printf '%-14s N=%d  composed %ss  flat %ss  ratio %.2f\n' "${args%% *}" "$N" "$c" "$f" \
    "$(echo "$c / $f" | bc -l)"
done
c=$(best "$TMP/composed.bg" --collapse all -o "$TMP/c.svg")
f=$(best "$TMP/flat.bg" -o "$TMP/f.svg")
e=$(best "$TMP/composed.bg" -o "$TMP/e.svg")
printf '%-14s N=%d  composed, collapsed %ss  flat %ss  ratio %.2f  (composed, frames: %ss)\n' \
  "svg" "$N" "$c" "$f" "$(echo "$c / $f" | bc -l)" "$e"
