#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A predicted index above 1 that the equations contradict (docs/simulation.md,
# "Refusal"; docs/property.md, finding 23): the structure of the equations has
# index 0 or 1 (Pantelides differentiates nothing) and the numeric index at
# the initial point is 1, so the model is simulated as it stands, with the
# disagreement stated, instead of refused. Exact solutions: an LC pair, and a
# loop of junctions through an MTF whose flows are 0 and whose common effort
# is U / (1/n(t) + 0.35).
# Usage: bash tests/sim_index_contradicted.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"

# Property seed 4692's merged model, reduced by hand: the 1-junctions j1 and
# j6 and the 0-junction j5 close two causal loops through T1 and T2 that share
# bonds 14, 24 (Rosenberg-Andry not satisfied: predicted index 2); their
# equations, (1/n + 0.35) e17 = U and (1 - n - 1/1.35) f = 0, are regular for
# n(t) = 1.87 + 0.432 sin t >= 1.438.
cat >"$tmp/loop.bg" <<'M'
model loopmtf
1   j1
0   j5
1   j6
MTF T1 = 1.87 + 0.432*sin(t)
TF  T2 = 1.35
Se  U = sin(2*t)
0   j12
I   L8 = 0.854 [p0 = 0.3]
C   C7 = 2.54 [q0 = 0.5]
bond 14 j1 -> T1
bond 16 T2 -> j1
bond 17 j5 -> j1
bond 24 T1 -> j5
bond 29 j6 -> j5
bond 41 j6 -> T2
bond 42 U -> j1
bond 18 L8 -> j12
bond 36 j12 -> C7
simulate t_end = 3, dt = 0.075, rtol = 1e-9, atol = 1e-11
plot C7.q, L8.p, f14, f24, f29, e17
M
"$BGDRAW" "$tmp/loop.bg" -o "$tmp/loop.csv" -o "$tmp/loop.json" 2>"$tmp/err"; st=$?
check "loops through an MTF: exit 0 (got $st)" $st
grep -q "the numeric index is computed from the equations themselves and is the one to use" "$tmp/err"
check "loops through an MTF: the disagreement is stated on stderr" $?
python3 - "$tmp/loop.json" <<'PY'
import json, sys
i = json.load(open(sys.argv[1]))["index"]
sys.exit(not (i["predicted"] == 2 and i["numeric"] == 1 and i["disagreement"]
              and i["reduction"]["status"] == "failed" and not i["reduction"]["differentiated"]))
PY
check "loops through an MTF: predicted 2, numeric 1, Pantelides differentiates nothing" $?
python3 - "$tmp/loop.csv" <<'PY'
import csv, math, sys
rows = [[float(v) for v in r] for r in list(csv.reader(open(sys.argv[1])))[1:]]
L, C, q0, p0 = 0.854, 2.54, 0.5, 0.3
w = 1 / math.sqrt(L * C)
err = 0
for t, q, p, f14, f24, f29, e17 in rows:
    qx = q0 * math.cos(w * t) + p0 / (L * w) * math.sin(w * t)
    px = L * (-q0 * w * math.sin(w * t) + p0 / L * math.cos(w * t))
    n = 1.87 + 0.432 * math.sin(t)
    ex = math.sin(2 * t) / (1 / n + 0.35)
    err = max(err, abs(q - qx), abs(p - px), abs(f14), abs(f24), abs(f29), abs(e17 - ex))
print("  largest error %.2g" % err)
sys.exit(not (len(rows) == 41 and err < 1e-7))
PY
check "loops through an MTF: q, p exact (LC), flows 0, e17 = U/(1/n + 0.35), to 1e-7" $?
finish
