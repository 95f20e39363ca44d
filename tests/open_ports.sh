#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Open and shorted ports, grounds, unbonded ports (docs/format.md, "Open and
# shorted ports"; issue 29), each against a closed form:
# - tests/data/motor_free.bg: `short M1.shaft` (no load torque): the motor's
#   two states are linear, L i' = U - R i - K w, J w' = K i - b w, so
#   x(t) = A^-1 (expm(A t) - I) b (SciPy); the same without the line (the
#   port's inside is a 1-junction: taken as shorted, with the unbonded-port
#   warning, -Werror an error, -Wno-unbonded-port silent) gives the same CSV;
#   `open M1.shaft` clamps it (w = 0, i = U/R);
# - tests/data/rc_ground.bg: a circuit written node by node, `short gnd`
#   its reference node: C1.e = U (1 - exp(-t/RC));
# - an RC section with ports whose inside nodes are 0-junctions: its
#   unbonded far end is taken as open (zero flow), the chain's last
#   capacitor charges as a single RC.
# Usage: bash tests/open_ports.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
close() { # KIND CSV: rows against the closed form, within 1e-6 of each column's range
  /usr/bin/python3 - "$@" <<'PY'
import csv, math, sys
import numpy as np
from scipy.linalg import expm
kind, rows = sys.argv[1], np.array([[float(x) for x in r] for r in list(csv.reader(open(sys.argv[2])))[1:]])
t = rows[:, 0]
if kind == "motor":
    U, R, L, K, J, b = 12.0, 2.0, 1e-3, 0.05, 1e-4, 1e-5
    A = np.array([[-R / L, -K / L], [K / J, -b / J]])  # x = (i, w)
    bb = np.array([U / L, 0.0])
    x = np.array([np.linalg.solve(A, (expm(A * s) - np.eye(2)) @ bb) for s in t])
    exact = np.column_stack([x[:, 1], x[:, 0]])  # plot M1.Jm.f, M1.La.f
elif kind == "clamped":
    exact = np.column_stack([0 * t, 6.0 * (1 - np.exp(-2.0 / 1e-3 * t))])
elif kind == "rc":
    exact = np.column_stack([2.0 * (1 - np.exp(-t / 1e-3)), 2.0 / 1e3 * np.exp(-t / 1e-3)])
else:  # the ladder's end: one RC of R 1, C 1 charged by 1 V through the section
    exact = np.column_stack([1 - np.exp(-t)])
got = rows[:, 1:1 + exact.shape[1]]
err = [np.max(np.abs(got[:, j] - exact[:, j])) / max(np.ptp(exact[:, j]), np.max(np.abs(exact[:, j])), 1e-300)
       for j in range(exact.shape[1])]
print("%s: largest error over the range %s" % (kind, ", ".join("%.2g" % e for e in err)))
sys.exit(not max(err) < 1e-6)
PY
}
d=$root/tests/data
"$BGDRAW" "$d/motor_free.bg" --simulate -o "$tmp/short.csv" 2>"$tmp/err"; check "short M1.shaft: exit 0, quiet ($(cat "$tmp/err"))" $(($? + $(wc -c <"$tmp/err")))
close motor "$tmp/short.csv"; check "short M1.shaft: the free motor's closed form" $?
sed '/^short M1.shaft$/d' "$d/motor_free.bg" >"$tmp/none.bg"
"$BGDRAW" "$tmp/none.bg" --simulate -o "$tmp/none.csv" 2>"$tmp/err"; check "unbonded shaft: exit 0" $?
grep -q "warning: port 'shaft' of M1 (DCMotor) is not bonded: taken as shorted (zero effort: the 1-junction jw inside" "$tmp/err" &&
  grep -q "\[-Wunbonded-port\]" "$tmp/err"; cs_=$?; check "unbonded shaft: the unbonded-port warning names the default ($(head -c 300 "$tmp/err"))" $cs_
cmp -s "$tmp/none.csv" "$tmp/short.csv"; check "unbonded shaft: the same CSV as short M1.shaft" $?
"$BGDRAW" "$tmp/none.bg" -Werror --check >/dev/null 2>&1; [ $? -eq 1 ]; check "unbonded shaft: -Werror makes it an error" $?
"$BGDRAW" "$tmp/none.bg" -Wno-unbonded-port --check >/dev/null 2>"$tmp/err"; [ ! -s "$tmp/err" ]; check "unbonded shaft: -Wno-unbonded-port silences it" $?
sed 's/^short M1.shaft$/open M1.shaft/' "$d/motor_free.bg" >"$tmp/open.bg"
"$BGDRAW" "$tmp/open.bg" --simulate -o "$tmp/open.csv"; check "open M1.shaft: exit 0" $?
close clamped "$tmp/open.csv"; check "open M1.shaft: clamped, w = 0, i = U/R (1 - exp(-R t/L))" $?
"$BGDRAW" "$d/rc_ground.bg" --simulate -o "$tmp/rc.csv"; check "short gnd: exit 0" $?
close rc "$tmp/rc.csv"; check "short gnd: the RC's closed form" $?
"$BGDRAW" "$d/rc_ground.bg" --check | grep -q "^form: ode"; check "short gnd: an ODE of one state" $?
# the same circuit without its reference node: the node potentials float
# (a class 5 loop through the junctions alone, structurally singular):
# refused, and the message says how to hold the node
grep -v '^short gnd$' "$d/rc_ground.bg" >"$tmp/float.bg"
"$BGDRAW" "$tmp/float.bg" --simulate -o "$tmp/float.csv" 2>"$tmp/err"; [ $? -eq 3 ] && [ ! -e "$tmp/float.csv" ]
check "no ground: refused (exit 3), no CSV" $?
grep -q 'node potentials float.*`short gnd`' "$tmp/err"; cs_=$?; check "no ground: the refusal says \`short gnd\` ($(tail -c 400 "$tmp/err"))" $cs_
"$BGDRAW" "$tmp/float.bg" --causality vandijk --simulate -o "$tmp/float.csv" 2>"$tmp/err"; [ $? -eq 3 ]
check "no ground, van Dijk: refused too" $?
grep -q "van Dijk's causality does not help here" "$tmp/err"; check "no ground, van Dijk: not suggested again" $?
# both branches' bonds out of gnd: jC's effort is e_n2 + e_gnd, a sum, and
# gnd's balance says the two branch currents are opposite while the series
# loop says they are equal: the bond graph as drawn carries no current (its
# own exact answer; docs/format.md says why it is not the RC circuit)
sed -e 's/^bond jC -> gnd$/bond gnd -> jC/' "$tmp/float.bg" >"$tmp/sum.bg"
"$BGDRAW" "$tmp/sum.bg" --simulate -o "$tmp/sum.csv" 2>/dev/null
/usr/bin/python3 -c "
import csv, sys
r = list(csv.reader(open(sys.argv[1])))[1:]
sys.exit(not (len(r) == 501 and all(float(v) == 0 for row in r for v in row[1:])))" "$tmp/sum.csv"
check "both gnd bonds out, no ground: zero current, as the graph says" $?
cat >"$tmp/ladder.bg" <<'BG'
submodel Section(R = 1, C = 1)
  port in, out
  0 a
  1 s
  R r = R
  0 b
  C c = C
  bond in -> a
  bond a -> s
  bond s -> r
  bond s -> b
  bond b -> c
  bond b -> out
end
Se U = 1
Section S1
bond U -> S1.in
simulate t_end = 5, dt = 0.01
plot S1.c.e
BG
"$BGDRAW" "$tmp/ladder.bg" --simulate -o "$tmp/ladder.csv" 2>"$tmp/err"; check "ladder: exit 0" $?
grep -q "port 'out' of S1 (Section) is not bonded: taken as open (zero flow: the 0-junction b inside" "$tmp/err"
cs_=$?; check "ladder: its far end taken as open ($(head -c 200 "$tmp/err"))" $cs_
close ladder "$tmp/ladder.csv"; check "ladder: the last capacitor charges as one RC" $?
finish
