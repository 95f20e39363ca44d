#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Steps that cannot grow (docs/simulation.md; docs/property.md, finding 30):
# property seed 5044's 100-element model, index-reduced (12 dummy
# derivatives, 52 unknowns), driven from rest. After the state event at
# t = 0.64 (a piecewise-linear resistor's flow crosses 0) every attempt to
# double the step failed IDA's error test on the dummy derivatives, whose
# BDF-rate error shows only when the step changes: 306 180 steps with
# 305 509 failures, 37 s, and 2.9e-5 of the range off. The run now finds
# the trapped interval and runs it again with the unknowns computed from
# the states' rates out of the error test.
# References: the same model at rtol 1e-12, and the model merged by
# `--transform merge-stores` (another DAE: 38 unknowns) at rtol 1e-12.
# Usage: bash tests/sim_step_trap.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"

model=$root/tests/property/found/seed5044_robust.bg
tight() { sed -E 's/rtol = 1e-9, atol = 1e-11/rtol = 1e-12, atol = 1e-14/' "$1"; }

"$BGDRAW" "$model" --simulate -v -o "$tmp/run.csv" 2>"$tmp/run.err"
check "the model runs (exit 0)" $?
grep -q 'the error test failed at .* (the step could not grow); again with the unknowns computed from the states' "$tmp/run.err"
check "-v says the interval was trapped and run again" $?
steps=$(sed -n 's/.*simulate: done in .*rows, \([0-9]*\) steps.*/\1/p' "$tmp/run.err")
[ -n "$steps" ] && [ "$steps" -lt 20000 ]
check "under 20 000 steps (306 180 before; $steps)" $?

tight "$model" >"$tmp/tight.bg"
"$BGDRAW" "$tmp/tight.bg" --simulate -o "$tmp/tight.csv" 2>/dev/null
check "the model at rtol 1e-12 runs" $?
"$BGDRAW" "$model" --transform merge-stores -o "$tmp/merged.bg" 2>/dev/null
check "merge-stores applies" $?
tight "$tmp/merged.bg" >"$tmp/merged_tight.bg"
"$BGDRAW" "$tmp/merged_tight.bg" --simulate -o "$tmp/merged.csv" 2>/dev/null
check "the merged model at rtol 1e-12 runs" $?

# every column (the resistors' and the source's efforts and flows) within
# 1e-6 of the largest column range (measured 5e-8 against either reference)
close() { # A.csv B.csv
  python3 - "$1" "$2" <<'PY'
import csv, sys
def load(p):
    rows = [r for r in csv.reader(open(p)) if r and not r[0].startswith("#")]
    return rows[0], [[float(x) for x in r] for r in rows[1:]]
ha, a = load(sys.argv[1]); hb, b = load(sys.argv[2])
assert ha == hb and len(a) == len(b) == 41, (len(a), len(b))
span = max(max(r[j] for r in b) - min(r[j] for r in b) for j in range(1, len(hb)))
worst = max(abs(x[j] - y[j]) for x, y in zip(a, b) for j in range(1, len(ha))) / span
print("worst %.3g of the largest range" % worst)
sys.exit(0 if worst < 1e-6 else 1)
PY
}
close "$tmp/run.csv" "$tmp/tight.csv"
check "the run agrees with the model at rtol 1e-12" $?
close "$tmp/run.csv" "$tmp/merged.csv"
check "the run agrees with the merged model at rtol 1e-12" $?
finish
