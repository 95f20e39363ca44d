#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The analysis JSON of every example, with every causality method and the
# variants of docs/examples.md, against the schema of docs/json.md
# (tests/json_schema.py: required keys, vocabularies, references); each run
# twice, byte for byte the same.
# Usage: bash tests/json_schema.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: json_schema.sh PATH_TO_BGDRAW}
command -v python3 >/dev/null || { echo "python3 not found"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
n=0

# run NAME.json ARGS...: writes $tmp/NAME.json twice and compares
run() {
  local out=$1
  shift
  if ! "$BGDRAW" "$@" -o "$tmp/$out" >/dev/null 2>"$tmp/err" ||
     ! "$BGDRAW" "$@" -o "$tmp/again.json" >/dev/null 2>>"$tmp/err"; then
    echo "FAIL bgdraw $* -o $out"
    sed 's/^/    /' "$tmp/err"
    fail=$((fail + 1))
    return
  fi
  if ! cmp -s "$tmp/$out" "$tmp/again.json"; then
    echo "FAIL $out: two runs differ"
    fail=$((fail + 1))
  fi
  n=$((n + 1))
}

for f in examples/*.bg; do
  b=$(basename "$f" .bg)
  for m in scap relaxed vandijk lagrange; do run "$b.$m.json" "$f" --causality "$m"; done
done
run bond_loop.n1.json examples/bond_loop.bg --set n=1
run modulated_source.k2.json examples/modulated_source.bg --set k=2
sed 's/^bond 2 jB -> jC/bond 2 jC -> jB/' examples/bond_loop.bg >"$tmp/bond_loop_rev.bg"
run bond_loop_rev.json "$tmp/bond_loop_rev.bg"
sed 's/^bond 5  jB |-> R1/bond 5  jB -> R1/' examples/class12_paths.bg >"$tmp/class12_free.bg"
run class12_free.json "$tmp/class12_free.bg"
sed 's/^R   R1 = R10/R   R1 = R10 [causality = conductance]/' examples/delta.bg >"$tmp/delta_r1.bg"
run delta_r1.json "$tmp/delta_r1.bg"

# multiport fields (docs/format.md): the reference models of tests/data/fields
for f in tests/data/fields/*.bg; do
  b=$(basename "$f" .bg)
  for m in scap relaxed vandijk lagrange; do run "field_$b.$m.json" "$f" --causality "$m"; done
done

if ! python3 tests/json_schema.py "$tmp"/*.json; then fail=$((fail + 1)); fi
echo "$n documents checked, $fail failures"
[ "$fail" -eq 0 ] && [ "$n" -gt 0 ]
