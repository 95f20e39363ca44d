#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Submodels end to end: the JSON says which instance bonds each flat bond
# joins and which instance each element belongs to (and passes the schema
# checker), the report lists instances and bond origins, CSV headers carry
# qualified names, --set reaches an instance's
# parameter, a version 1 file's JSON has none of the new keys, and the
# examples written with lib/ simulate like their flat versions; detectors
# (De, Df) give CSV columns equal to the variables they read.
# Usage: bash tests/components.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: components.sh PATH_TO_BGDRAW}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail=0
D=tests/data/components

"$BGDRAW" $D/two_motors.bg -o "$TMP/m.json" || { echo "FAIL: two_motors.bg"; exit 1; }
python3 tests/json_schema.py "$TMP/m.json" || fail=1
python3 - "$TMP/m.json" <<'PY' || fail=1
import json, sys
d = json.load(open(sys.argv[1]))
bonds = {b["id"]: b for b in d["bonds"]}
ok = True
def want(what, got, exp):
    global ok
    if got != exp:
        print("FAIL %s: %r, expected %r" % (what, got, exp)); ok = False
want("bond numbers", sorted(bonds), [1, 2, 3, 4, 5] + list(range(7, 13)) + list(range(15, 21)))
want("bond 2 origin", bonds[2]["origin"], [{"instance": None, "bond": 2}, {"instance": "M1", "bond": 1}])
want("bond 2 ends", (bonds[2]["from"], bonds[2]["to"]), ("j0", "M1.ji"))
want("bond 4 origin", bonds[4]["origin"], [{"instance": None, "bond": 4}, {"instance": "M1", "bond": 8}])
want("bond 17 origin", bonds[17]["origin"], [{"instance": "M2", "bond": 4}])
elems = {e["name"]: e for e in d["elements"]}
want("M2.G instance", elems["M2.G"]["instance"], "M2")
want("load instance", elems["load"]["instance"], None)
want("instances", d["instances"], [
    {"name": "M1", "submodel": "DCMotor", "parent": None, "bond_offset": 5, "bond_span": 8},
    {"name": "M2", "submodel": "DCMotor", "parent": None, "bond_offset": 13, "bond_span": 8}])
want("states", d["states"], ["M1.La.p", "M1.Jm.p", "M2.La.p", "M2.Jm.p"])
sys.exit(0 if ok else 1)
PY

# The report lists the instances with their bond blocks and each bond's origin.
"$BGDRAW" $D/two_motors.bg --report "$TMP/r.pdf" || { echo "FAIL: report"; fail=1; }
pdftotext -layout "$TMP/r.pdf" - | tr -s ' ' >"$TMP/r.txt"
for want in "Submodel instances" "M1 DCMotor the model 6–13" "M2 DCMotor the model 14–21" \
            "2 j0 M1.ji bond 2 of the model + bond 1 of M1" "17 M2.ji M2.G bond 4 of M2"; do
  grep -qF -- "$want" "$TMP/r.txt" || { echo "FAIL: report lacks '$want'"; fail=1; }
done
if "$BGDRAW" examples/rlc.bg --report "$TMP/v1.pdf" && pdftotext "$TMP/v1.pdf" - | grep -q "Submodel instances"; then
  echo "FAIL: a version 1 report has a submodel section"; fail=1
fi

# CSV: qualified names head the columns; --set M1.R changes only M1's current.
cat >"$TMP/sim.bg" <<EOF
use "$PWD/$D/motor.bg"
Se U = 12
DCMotor M1
DCMotor M2
0 j
bond U -> j
bond j -> M1.a
bond j -> M2.a
R l1 = 0.01
R l2 = 0.01
bond M1.shaft -> l1
bond M2.shaft -> l2
simulate t_end = 0.01, dt = 0.01
plot M1.La.f, M2.La.f, M1.R
EOF
"$BGDRAW" "$TMP/sim.bg" --simulate -o "$TMP/a.csv" --set M1.R=4 || { echo "FAIL: sim.bg"; fail=1; }
head -1 "$TMP/a.csv" | grep -qx 't,M1.La.f,M2.La.f,M1.R' || { echo "FAIL: CSV header $(head -1 "$TMP/a.csv")"; fail=1; }
awk -F, 'NR == 3 { if ($4 != 4 || !($2 < $3)) { print "FAIL: --set M1.R row " $0; exit 1 } }' "$TMP/a.csv" || fail=1

# Detectors: CSV columns named by the detector equal the variables they read,
# and the JSON lists them.
cat >"$TMP/det.bg" <<'EOF'
Se U = step(t)
1 j
R R1 = 2
I L1 = 0.5
0 n
C C1 = 0.1
R R2 = 4
bond U -> j
bond j -> R1
bond j -> L1
bond j -> n
bond n -> C1
bond n -> R2
De vC = n
Df i = j
simulate t_end = 1, dt = 0.1
plot vC, C1.e, i, L1.f
EOF
"$BGDRAW" "$TMP/det.bg" --simulate -o "$TMP/det.csv" -o "$TMP/det.json" || { echo "FAIL: det.bg"; fail=1; }
head -1 "$TMP/det.csv" | grep -qx 't,vC,C1.e,i,L1.f' || { echo "FAIL: detector CSV header"; fail=1; }
awk -F, 'NR > 1 && ($2 != $3 || $4 != $5) { print "FAIL: detector column differs: " $0; bad = 1 } END { exit bad }' "$TMP/det.csv" || fail=1
grep -q '"detectors"' "$TMP/det.json" || { echo "FAIL: JSON has no detectors"; fail=1; }
python3 tests/json_schema.py "$TMP/det.json" || fail=1
grep -A2 '"detectors": \[' "$TMP/det.json" | tr -d ' \n' | grep -qF '"detectors":[{"name":"vC","kind":"De","node":"n"},{"name":"i","kind":"Df","node":"j"}' || { echo "FAIL: JSON detectors"; fail=1; }
# Without a plot statement the CSV has the states, then the detectors (vC = C1.q / 0.1).
grep -v '^plot' "$TMP/det.bg" >"$TMP/det2.bg"
"$BGDRAW" "$TMP/det2.bg" --simulate -o "$TMP/det2.csv" || { echo "FAIL: det2.bg"; fail=1; }
head -1 "$TMP/det2.csv" | grep -qx 't,L1.p,C1.q,vC,i' || { echo "FAIL: detector CSV header without plot: $(head -1 "$TMP/det2.csv")"; fail=1; }
awk -F, 'NR > 1 { d = $4 - 10 * $3; if (d > 1e-12 || d < -1e-12 || $5 != 2 * $2) { print "FAIL: detector value: " $0; bad = 1 } } END { exit bad }' "$TMP/det2.csv" || fail=1
# Equations: the detectors' section names the bond variables; the JSON is self-contained.
"$BGDRAW" "$TMP/det2.bg" --equations text >"$TMP/det2.txt" || fail=1
grep -A2 '^# detectors' "$TMP/det2.txt" | tr '\n' ';' | grep -qx '# detectors (outputs: the bond variables they read);vC = e4;i = f1;' || { echo "FAIL: detector equations"; fail=1; }
"$BGDRAW" "$TMP/det2.bg" --equations json >"$TMP/det2.eq.json" && python3 tests/equations_json.py "$TMP/det2.eq.json" >/dev/null || { echo "FAIL: detector equations JSON"; fail=1; }
# Linear analysis: the detectors are the outputs; DC gains R2/(R1+R2) and 1/(R1+R2).
"$BGDRAW" "$TMP/det2.bg" --linear text >"$TMP/det2.lin" || fail=1
grep -qx 'outputs: vC, i' "$TMP/det2.lin" || { echo "FAIL: linear outputs"; fail=1; }
grep -A1 '^vC/U = (20) / (s^2 + 6.5\*s + 30)$' "$TMP/det2.lin" | grep -q 'DC gain: 0.666667' || { echo "FAIL: vC/U"; fail=1; }
grep -A1 '^i/U = (2\*s + 5) / (s^2 + 6.5\*s + 30)$' "$TMP/det2.lin" | grep -q 'DC gain: 0.166667' || { echo "FAIL: i/U"; fail=1; }

# --collapse: an unknown instance is an error with a suggestion and writes nothing;
# `all` draws one box per instance (DOT nodes with bg_collapsed=1) and the model's own bonds.
rm -f "$TMP/c.svg"
"$BGDRAW" examples/components/motor_drive_lib.bg --collapse S3 -o "$TMP/c.svg" 2>"$TMP/c.err"
rc=$?
[ "$rc" -eq 2 ] && [ ! -e "$TMP/c.svg" ] && grep -qF -- "--collapse S3: no instance 'S3' (did you mean 'S1'?)" "$TMP/c.err" \
  || { echo "FAIL: --collapse S3 (exit $rc): $(cat "$TMP/c.err")"; fail=1; }
"$BGDRAW" examples/components/motor_drive_lib.bg --collapse all -T dot -o "$TMP/c.dot" || fail=1
[ "$(grep -c 'bg_collapsed=1' "$TMP/c.dot")" -eq 4 ] && [ "$(grep -c 'bg_bond=' "$TMP/c.dot")" -eq 7 ] \
  || { echo "FAIL: --collapse all DOT"; fail=1; }
"$BGDRAW" examples/components/motor_drive_lib.bg --collapse M --collapse G -o "$TMP/c.png" || fail=1

# A version 1 model's JSON has no component keys.
"$BGDRAW" examples/rlc.bg -o "$TMP/v1.json" || fail=1
if grep -q '"origin"\|"instances"\|"instance"' "$TMP/v1.json"; then echo "FAIL: v1 JSON has component keys"; fail=1; fi

# The component examples check clean, draw, and pass the JSON schema checker.
for f in examples/components/*.bg; do
  n=$(basename "$f" .bg)
  "$BGDRAW" "$f" --check >/dev/null 2>"$TMP/err" || { echo "FAIL: $f --check: $(head -3 "$TMP/err")"; fail=1; }
  "$BGDRAW" "$f" -o "$TMP/$n.svg" -o "$TMP/$n.json" || { echo "FAIL: $f outputs"; fail=1; continue; }
  python3 tests/json_schema.py "$TMP/$n.json" || fail=1
done

# Examples written with the component library simulate like their flat twins
# (every CSV value within 1e-6 of the column's largest magnitude).
for pair in rc_ladder motor_drive hydraulic_lift; do
  "$BGDRAW" examples/components/${pair}_lib.bg --simulate -o "$TMP/lib.csv" &&
    "$BGDRAW" examples/components/$pair.bg --simulate -o "$TMP/flat.csv" || { echo "FAIL: simulate $pair"; fail=1; continue; }
  python3 - "$TMP/lib.csv" "$TMP/flat.csv" "$pair" <<'PY' || fail=1
import csv, sys
a = list(csv.reader(open(sys.argv[1])))[1:]
b = list(csv.reader(open(sys.argv[2])))[1:]
if len(a) != len(b) or len(a) < 10:
    print("FAIL %s: %d rows against %d" % (sys.argv[3], len(a), len(b))); sys.exit(1)
for c in range(len(a[0])):
    scale = max(abs(float(r[c])) for r in b) or 1.0
    worst = max(abs(float(x[c]) - float(y[c])) for x, y in zip(a, b))
    if worst > 1e-6 * scale:
        print("FAIL %s: column %d differs by %g (scale %g)" % (sys.argv[3], c, worst, scale)); sys.exit(1)
PY
done

[ $fail -eq 0 ] && echo "components: ok"
exit $fail
