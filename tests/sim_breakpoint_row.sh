#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A restart at an input's breakpoint that falls on a row but for rounding
# (docs/simulation.md, "Input discontinuities"): property seed 1731's
# 70-element DAE, a flow source stepping at t = 0.15, rows every 0.025
# s. The sixth row is 6 x 0.025 = 0.15000000000000002; it was IDACalcIC's
# look-ahead at the restart, and IDA refuses one that close ("tout1 too
# close to t0"): exit 3 at t = 0.15 (and at dt 0.05, 3 x 0.05). The run
# now looks ahead a thousandth of the span instead. Reference: the same
# model with rows every 0.02 s, whose rows never meet a breakpoint (it ran
# before too, byte-identical): every shared row (t = 0.1, 0.2, ..., 1)
# agrees to 1e-6 of the largest column range.
# Usage: bash tests/sim_breakpoint_row.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"

model=$root/tests/property/found/seed1731_breakpoint_row.bg
sed 's/dt = 0.025/dt = 0.05/' "$model" >"$tmp/coarse.bg"
sed 's/dt = 0.025/dt = 0.02/' "$model" >"$tmp/ref.bg"
"$BGDRAW" "$model" --simulate -o "$tmp/run.csv" 2>"$tmp/run.err"
check "rows every 0.025: exit 0" $?
"$BGDRAW" "$tmp/coarse.bg" --simulate -o "$tmp/coarse.csv" 2>/dev/null
check "rows every 0.05: exit 0" $?
"$BGDRAW" "$tmp/ref.bg" --simulate -o "$tmp/ref.csv" 2>/dev/null
check "rows every 0.02 (the reference): exit 0" $?

shared() { # RUN.csv REF.csv: the rows at the same times agree
  python3 - "$1" "$2" <<'PY'
import csv, sys
def load(p):
    rows = [r for r in csv.reader(open(p)) if r and not r[0].startswith("#")]
    return rows[0], [[float(x) for x in r] for r in rows[1:]]
ha, a = load(sys.argv[1]); hb, b = load(sys.argv[2])
assert ha == hb
span = max(max(r[j] for r in b) - min(r[j] for r in b) for j in range(1, len(hb)))
pairs = [(x, y) for x in a for y in b if abs(x[0] - y[0]) < 1e-9]
worst = max(abs(x[j] - y[j]) for x, y in pairs for j in range(1, len(ha))) / span
print("%d shared rows, worst %.3g of the largest range" % (len(pairs), worst))
sys.exit(0 if len(pairs) >= 10 and worst < 1e-6 else 1)
PY
}
shared "$tmp/run.csv" "$tmp/ref.csv"
check "rows every 0.025 agree with the reference" $?
shared "$tmp/coarse.csv" "$tmp/ref.csv"
check "rows every 0.05 agree with the reference" $?
finish
