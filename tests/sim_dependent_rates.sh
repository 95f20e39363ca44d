#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A dependent store's rate in the output rows of an IDA run (docs/simulation.md,
# "Dependent stores' rates in the rows"; docs/property.md, finding 19): taken
# from the constraints' time derivatives at the row's states, not IDA's BDF
# estimate, and differenced from the left just before an input's jump.
# Usage: bash tests/sim_dependent_rates.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
# worst CASE CSV LIMIT: 41 rows, and the largest error of CASE's rows below
# LIMIT: cap, f2 against cos(2t); par, f3 against 2 f2 over f2's range
worst() {
  python3 - "$1" "$2" "$3" <<'PY'
import csv, math, sys
case, path, limit = sys.argv[1], sys.argv[2], float(sys.argv[3])
rows = [[float(v) for v in r] for r in list(csv.reader(open(path)))[1:]]
if case == "cap":
    err = max(abs(r[1] - math.cos(2 * r[0])) for r in rows)
else:
    err = max(abs(r[2] - 2 * r[1]) for r in rows) / (max(r[1] for r in rows) - min(r[1] for r in rows))
print("  %s: largest error %.2g" % (case, err))
sys.exit(not (len(rows) == 41 and err < limit))
PY
}

# A capacitor across an effort source (dependent: q = 0.5 U): its flow is
# 0.5 U' = cos(2t) exactly; the step comes 1e-5 after the row at t = 1.5,
# closer than the difference's two steps of 3e-5 (a difference from the
# right there read the jump: 25 000 instead of cos 3)
cat >"$tmp/cap.bg" <<'M'
model cap
Se  U = sin(2*t) + step(t - 1.50001)
0   j
C   C1 = 0.5 [q0 = 0]
R   R1 = 2
bond 1 U -> j
bond 2 j -> C1
bond 3 j -> R1
simulate t_end = 3, dt = 0.075, rtol = 1e-9, atol = 1e-11
plot f2, C1.q
M
"$BGDRAW" "$tmp/cap.bg" -o "$tmp/cap.csv" -o "$tmp/cap.json" 2>/dev/null; st=$?
check "capacitor across a source: exit 0 (got $st)" $st
python3 -c "import json,sys; a=json.load(open(sys.argv[1])); sys.exit(not (a['dependent_stores'] == ['C1'] and a['simulation']['solver'] == 'ida'))" "$tmp/cap.json"
check "capacitor across a source: C1 dependent, IDA" $?
worst cap "$tmp/cap.csv" 5e-9
check "capacitor across a source: f2 = cos(2t) to 5e-9 in every row, t = 1.5 too" $?

# Two capacitors in parallel (C2 = 2 C1: dependent, q2 = 2 q1) driven by a
# flow source, with an R and an I: C2's flow is twice C1's at every row to
# the rounding (IDA's estimate was 2e-7 of the range off)
cat >"$tmp/par.bg" <<'M'
model par
Sf  S = cos(t)
0   j
C   C1 = 1 [q0 = 0.1]
C   C2 = 2 [q0 = 0.2]
R   R1 = 5
1   k
I   L1 = 0.5 [p0 = 0.3]
bond 1 S -> j
bond 2 j -> C1
bond 3 j -> C2
bond 4 j -> k
bond 5 k -> R1
bond 6 k -> L1
simulate t_end = 3, dt = 0.075, rtol = 1e-9, atol = 1e-11
plot f2, f3
M
"$BGDRAW" "$tmp/par.bg" -o "$tmp/par.csv" -o "$tmp/par.json" 2>/dev/null; st=$?
check "parallel capacitors: exit 0 (got $st)" $st
python3 -c "import json,sys; a=json.load(open(sys.argv[1])); sys.exit(not (a['dependent_stores'] == ['C2']))" "$tmp/par.json"
check "parallel capacitors: C2 dependent" $?
worst par "$tmp/par.csv" 1e-12
check "parallel capacitors: f3 = 2 f2 in every row, to 1e-12 of the range" $?
finish
