#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A short deterministic fuzz run (tests/fuzz/README.md): each fuzz target of
# the build (parse, import, equations, simulate, render, linear; the fixed-seed driver) runs
# every seed (examples/, tests/bad/, the regression inputs tests/fuzz/corpus/)
# and a fixed number of mutants of them, and must finish without a crash, a
# sanitizer report or a hang (10 s per input). A failing input is printed.
# Usage: bash tests/fuzz_short.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: fuzz_short.sh PATH_TO_BGDRAW}
bin=$(dirname "$BGDRAW")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0}
for spec in parse:20000 import:4000 equations:4000 simulate:2000 render:400 linear:2000; do
  t=${spec%%:*} runs=${spec#*:}
  exe=$bin/fuzz_$t
  if [ ! -x "$exe" ]; then echo "FAIL fuzz_$t not built next to $BGDRAW"; fail=$((fail + 1)); continue; fi
  BG_FUZZ_SAVE=$tmp/input "$exe" -runs "$runs" -seed 20 -dict tests/fuzz/bg.dict \
    examples tests/bad tests/fuzz/corpus tests/data >"$tmp/out" 2>&1
  st=$?
  if [ $st -eq 0 ]; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL fuzz_$t (status $st); the input:"
    od -c "$tmp/input" | head -40
    tail -20 "$tmp/out"
  fi
done
echo "fuzz_short: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
