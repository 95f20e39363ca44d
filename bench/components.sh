#!/usr/bin/env bash
# Flattening cost: N instances of a 10-element submodel against the same model
# written flat, through parse, flatten, compile and the whole causal analysis
# (--check) and with the JSON written. Best of 3 wall-clock runs each.
# Usage: bench/components.sh [N] [BGDRAW]   (default 1000, build/bgdraw)
set -eu
N=${1:-1000}
BGDRAW=${2:-build/bgdraw}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
python3 "$(dirname "$0")/gen_components.py" "$N" "$TMP/composed.bg" "$TMP/flat.bg"
best() { # best FILE ARGS...: the fastest of 3 runs, in seconds
  local f=$1 b=999999 t s e
  shift
  for _ in 1 2 3; do
    s=$(date +%s.%N)
    "$BGDRAW" "$f" "$@" >/dev/null 2>&1
    e=$(date +%s.%N)
    t=$(echo "$e - $s" | bc -l)
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
