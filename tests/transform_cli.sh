#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Model transformations (docs/transform.md): --transform NAME -o NEW.bg.
# Each transformed model re-parses, keeps the rest of the model (params,
# simulate, plot, options, comments), has the equations the chapter derives,
# and simulates like the original (and like a closed-form or hand-derived
# reference); misuse is a clear usage error (exit 2), a transformation that
# does not apply is refused with the reason (exit 3) and writes nothing.
# Usage: bash tests/transform_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
BG=${1:?usage: transform_cli.sh PATH_TO_BGDRAW}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail=0
check() { if eval "$2"; then :; else echo "FAIL $1"; fail=$((fail + 1)); fi; }
D=tests/data/transform

# --- merge-stores: Figure 3.14, two inertias through a gear of ratio n --------
"$BG" $D/gear.bg --transform merge-stores -o "$TMP/gear.bg" 2>"$TMP/err"; rc=$?
check "merge exit 0" '[ $rc -eq 0 ]'
check "merge header says why" 'head -1 "$TMP/gear.bg" | grep -qF "# Transformed by bgdraw --transform merge-stores from gear.bg."'
check "merge header cites the chapter" 'grep -q "^# .*Section 4.4" "$TMP/gear.bg"'
check "merged inertia J1 + J2/n^2 (bgdraw TF: load speed = w/n)" 'grep -qxF "I   Jm = J1 + J2/n^2  [p0 = 0.5*(J1 + J2/n^2)/J1]" "$TMP/gear.bg"'
check "dependent store and its bond removed" '! grep -q "Jl" <(grep -v "^#" "$TMP/gear.bg")'
for keep in 'param M0 = 2, J1 = 0.5, J2 = 4, n = 3, b1 = 0.2, b2 = 1.5' \
            'simulate t_end = 10, dt = 0.01' 'plot w.f, v.f  [title = "speeds"]' \
            'TF  G  = n             # gear: load speed = motor speed / n' 'bond 7 v -> bl'; do
  check "merge keeps '$keep'" 'grep -qxF "$keep" "$TMP/gear.bg"'
done
"$BG" "$TMP/gear.bg" --check >"$TMP/check" 2>&1; rc=$?
check "merged model re-parses" '[ $rc -eq 0 ]'
check "merged model: one state, no dependent store, an ODE" 'grep -qxF "dependent stores: none" "$TMP/check" && grep -qF "form: ode" "$TMP/check" && grep -qxF "states (1): Jm.p" "$TMP/check"'
"$BG" "$TMP/gear.bg" --equations text >"$TMP/eq" 2>&1
check "merged equations: f2 = Jm.p/(J1 + J2/n^2)" 'grep -qxF "f2 = Jm.p/(J1 + J2/n^2)" "$TMP/eq"'
"$BG" $D/gear.bg --transform merge-stores -o "$TMP/gear2.bg"
check "merge rerun identical" 'cmp -s "$TMP/gear.bg" "$TMP/gear2.bg"'
"$BG" $D/gear.bg --simulate -o "$TMP/a.csv" 2>/dev/null
"$BG" "$TMP/gear.bg" --simulate -o "$TMP/b.csv" 2>/dev/null
# closed form: Jeq w' = M0 - (b1 + b2/n^2) w, w(0) = p0/J1; v = w/n
python3 - "$TMP/a.csv" "$TMP/b.csv" <<'PY' || fail=$((fail + 1))
import csv, math, sys
M0, J1, J2, n, b1, b2 = 2, 0.5, 4, 3, 0.2, 1.5
J, b = J1 + J2 / n**2, b1 + b2 / n**2
def w(t): return M0 / b + (1 - M0 / b) * math.exp(-b * t / J)
worst = 0
for path in sys.argv[1:]:
    rows = list(csv.reader(open(path)))
    assert rows[0] == ["t", "w.f", "v.f"], rows[0]
    for r in rows[1:]:
        t, wf, vf = map(float, r)
        worst = max(worst, abs(wf - w(t)), abs(vf - w(t) / n))
assert len(rows) == 1002, len(rows)
assert worst < 1e-4, "merge: worst deviation from the closed form %g" % worst
PY

# --- merge-stores through an MTF: Figure 4.30, virtual inertia and gyristor ------
SC=examples/slider_crank.bg
"$BG" $SC --transform merge-stores -o "$TMP/sc.bg" 2>"$TMP/err"; rc=$?
check "virtual inertia: exit 0" '[ $rc -eq 0 ]'
check "virtual inertia: J's law f = p/(J0 + m0*T^2)" 'grep -qF "I   J : f = p/((J0) + (m0)*(rc*(rc*cos(phi) + sqrt(L^2 - rc^2*sin(phi)^2))*sin(phi)/sqrt(L^2 - rc^2*sin(phi)^2))^2)" "$TMP/sc.bg"'
check "virtual inertia: the companion gyristor on w" 'grep -q "^R   GR_J = m0\*rc\*f1\*sin(phi)" "$TMP/sc.bg" && grep -qxF "bond 8 w -> GR_J" "$TMP/sc.bg" && grep -q "^# .*Figure 4.30" "$TMP/sc.bg"'
check "virtual inertia: m and bond 5 removed, the rest kept" '! grep -q "^I   m\|^bond 5" "$TMP/sc.bg" && grep -qxF "state phi'"'"' = w.f  [init = 0]" "$TMP/sc.bg" && grep -qxF "plot phi, w.f, v.f" "$TMP/sc.bg"'
"$BG" "$TMP/sc.bg" --check >"$TMP/check" 2>&1
check "virtual inertia: an explicit ODE in J.p and phi" 'grep -qF "states (2): J.p, phi" "$TMP/check" && grep -qF "form: ode; predicted index: 0" "$TMP/check"'
sed 's/^R   GR_J = .*/R   GR_J = 0/' "$TMP/sc.bg" >"$TMP/sc_nogr.bg"
"$BG" $SC --simulate -o "$TMP/sc0.csv" 2>/dev/null
"$BG" "$TMP/sc.bg" --simulate -o "$TMP/sc1.csv" 2>/dev/null
"$BG" "$TMP/sc_nogr.bg" --simulate -o "$TMP/sc2.csv" 2>/dev/null
# the reference: Equation 4.53 integrated by RK4, (J + m T^2) w' + m T T' w^2 + b T^2 w = M
python3 - "$TMP" <<'PY' || fail=$((fail + 1))
import csv, math, sys
T_ = sys.argv[1]
J0, m0, rc, L, b0, M0 = 0.05, 2, 0.05, 0.2, 5, 1
def T(p):
    s = math.sqrt(L**2 - rc**2 * math.sin(p)**2)
    return rc * (rc * math.cos(p) + s) * math.sin(p) / s
def dT(p, h=1e-6): return (T(p + h) - T(p - h)) / (2 * h)
def rhs(p, w):
    t = T(p)
    return w, (M0 - m0 * t * dT(p) * w * w - b0 * t * t * w) / (J0 + m0 * t * t)
ref, p, w, h = {0: (0.0, 0.0)}, 0.0, 0.0, 1e-4
for k in range(1, 20001):
    k1 = rhs(p, w); k2 = rhs(p + h / 2 * k1[0], w + h / 2 * k1[1])
    k3 = rhs(p + h / 2 * k2[0], w + h / 2 * k2[1]); k4 = rhs(p + h * k3[0], w + h * k3[1])
    p += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]); w += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    if k % 40 == 0: ref[k // 40] = (p, w)
def dev(path):
    rows = list(csv.reader(open(path)))
    assert rows[0] == ["t", "phi", "w.f", "v.f"] and len(rows) == 502, (rows[0], len(rows))
    worst = 0
    for i, r in enumerate(rows[1:]):
        if i not in ref: continue
        pr, wr = ref[i]
        worst = max(worst, abs(float(r[1]) - pr) / 36, abs(float(r[2]) - wr) / 35,
                    abs(float(r[3]) - T(pr) * wr) / 2)
    return worst
d0, d1, d2 = dev(T_ + "/sc0.csv"), dev(T_ + "/sc1.csv"), dev(T_ + "/sc2.csv")
assert d0 < 1e-4, "the original DAE against Equation 4.53: %g" % d0
assert d1 < 1e-4, "the virtual inertia against Equation 4.53: %g" % d1
assert d2 > 1e-2, "without its gyristor the virtual inertia should be wrong: %g" % d2
PY

# --- parasitic: Figure 4.5, C stores at the bridge's lower 0-junctions ----------
HB=examples/hydraulic_bridge.bg
"$BG" $HB --transform parasitic -o "$TMP/hb.bg" 2>"$TMP/err"; rc=$?
check "parasitic exit 0" '[ $rc -eq 0 ]'
check "parasitic: C stores at n1 and n4 (the junctions of Figure 4.5)" 'grep -qxF "C   Cp_n1 = Cp_n1_0  [q0 = Cp_n1_0*3077824.6413558265]" "$TMP/hb.bg" && grep -qxF "bond 16 n1 -> Cp_n1" "$TMP/hb.bg" && grep -qxF "bond 17 n4 -> Cp_n4" "$TMP/hb.bg"'
check "parasitic: the values as params with the stated factor" 'grep -q "^param Cp_n1_0 = .* \"parasitic capacitance at n1 (bgdraw --transform parasitic)\"" "$TMP/hb.bg" && grep -q "^# .*100 times faster" "$TMP/hb.bg"'
check "parasitic: the plot is kept" 'grep -qxF "plot v.f, n1.e, n4.e" "$TMP/hb.bg"'
"$BG" "$TMP/hb.bg" --check >"$TMP/check" 2>&1
check "parasitic: an explicit ODE of order 3, no class 2 path" 'grep -qF "states (3): Cp_n1.q, Cp_n4.q, mp.p" "$TMP/check" && grep -qF "class 2: 0" "$TMP/check" && grep -qF "form: ode; predicted index: 0" "$TMP/check"'
"$BG" "$TMP/hb.bg" --equations text >"$TMP/eq"
# Equation 4.13a: C1 p' = (flow in through R2) - (flow out through R1) - A v
check "parasitic: the chapter's Equation 4.13a" 'grep -qxF "f16 = f2 - f1 - f10" "$TMP/eq" && grep -qxF "Cp_n1.q'"'"' = f16" "$TMP/eq" && grep -qxF "f10 = A*f11" "$TMP/eq"'
"$BG" $HB -o "$TMP/hb0.json"
"$BG" "$TMP/hb.bg" -o "$TMP/hb1.json"
"$BG" $HB --simulate -o "$TMP/hb0.csv" 2>/dev/null
"$BG" "$TMP/hb.bg" --simulate -o "$TMP/hb1.csv" 2>/dev/null
"$BG" "$TMP/hb.bg" --set Cp_n1_0=1.02e-19 --set Cp_n4_0=1.02e-19 --simulate -o "$TMP/hb2.csv" 2>/dev/null
python3 - "$TMP" <<'PY' || fail=$((fail + 1))
import csv, json, sys
T = sys.argv[1]
# the stated factor: every estimate of a new store is at least 100 times faster
# than the original's fastest, and the binding one is within the 3-digit rounding
d0, d1 = json.load(open(T + "/hb0.json")), json.load(open(T + "/hb1.json"))
scale = lambda e: e["value"] if e["kind"] == "time_constant" else 1 / e["value"]
fastest = min(scale(e) for e in d0["estimates"])
paths = d1["causal_paths"]
new = [scale(e) for e in d1["estimates"]
       if any(x.startswith("Cp_") for x in paths[e["path"] - 1]["ends"])]
assert len(new) == 6 and max(new) <= fastest / 100, (new, fastest)
assert max(new) >= 0.98 * fastest / 100, (new, fastest)
def dev(a, b):
    a, b = list(csv.reader(open(a))), list(csv.reader(open(b)))
    assert a[0] == b[0] == ["t", "v.f", "n1.e", "n4.e"] and len(a) == len(b) == 502
    worst = 0
    for j in range(1, 4):
        col = [float(r[j]) for r in a[1:]]
        rng = max(col) - min(col)
        worst = max(worst, max(abs(float(x[j]) - float(y[j])) for x, y in zip(a[1:], b[1:])) / rng)
    return worst
d = dev(T + "/hb0.csv", T + "/hb1.csv")
d2 = dev(T + "/hb0.csv", T + "/hb2.csv")
# the deviation is of the order of 1/factor, and vanishes with C (4.13 -> 4.1b, 4.1e)
assert d < 1e-2, "parasitic: deviation %g of the range" % d
assert d2 < d / 50, "parasitic: C 100 times smaller, deviation %g vs %g" % (d2, d)
PY
PC=examples/parallel_conductance.bg
"$BG" $PC --transform parasitic -o "$TMP/pc.bg" 2>"$TMP/err"; rc=$?
check "parasitic on a type 1 conflict: exit 0" '[ $rc -eq 0 ]'
check "parasitic on a type 1 conflict: C at k, a stiff solver asked" 'grep -qxF "bond 4 k -> Cp_k" "$TMP/pc.bg" && grep -qxF "simulate  [t_end = 1.4, solver = cvode_bdf]" "$TMP/pc.bg" && grep -qF "causality relaxed" "$TMP/pc.bg"'
"$BG" "$TMP/pc.bg" --check >"$TMP/check" 2>&1
check "parasitic on a type 1 conflict: no conflict left, an ODE" 'grep -qxF "conflicts: 0" "$TMP/check" && grep -qF "form: ode" "$TMP/check"'
"$BG" $PC --simulate -o "$TMP/pc0.csv" 2>/dev/null
"$BG" "$TMP/pc.bg" --simulate -o "$TMP/pc1.csv" 2>/dev/null
python3 - "$TMP/pc0.csv" "$TMP/pc1.csv" <<'PY' || fail=$((fail + 1))
import csv, sys
a, b = (list(csv.reader(open(p))) for p in sys.argv[1:])
assert len(a) == len(b) == 502, (len(a), len(b))
col = [float(r[1]) for r in a[1:]]
d = max(abs(float(x[1]) - float(y[1])) for x, y in zip(a[1:], b[1:])) / (max(col) - min(col))
assert d < 1e-5, "parasitic on parallel_conductance: deviation %g" % d
PY
# an index-2 original: delta's causal loop of gain +1 (Figure 4.16), against the
# hand-derived solution: iL1 + iL2 = I0 and (L1 + L2) iL1' = R3 (I0 - iR2 - iL1)
# with iR2 = ((R1 + R3) I0 - R3 iL1)/(R1 + R2 + R3): iL1 = (1 - exp(-t/3))/2
"$BG" examples/delta.bg --transform parasitic -o "$TMP/dp.bg" 2>"$TMP/err"; rc=$?
check "parasitic on a causal loop: exit 0, C at nB" '[ $rc -eq 0 ] && grep -qxF "bond 13 nB -> Cp_nB" "$TMP/dp.bg" && grep -q "^# .*causal loop 1" "$TMP/dp.bg"'
"$BG" "$TMP/dp.bg" --check >"$TMP/check" 2>&1
check "parasitic on a causal loop: no causal loop left, index 1" 'grep -qxF "causal loops: 0" "$TMP/check" && grep -qF "numeric index: 1" "$TMP/check"'
"$BG" "$TMP/dp.bg" --simulate -o "$TMP/dp1.csv" 2>/dev/null
"$BG" "$TMP/dp.bg" --set Cp_nB_0=1e-6 --simulate -o "$TMP/dp2.csv" 2>/dev/null
python3 - "$TMP/dp1.csv" "$TMP/dp2.csv" <<'PY' || fail=$((fail + 1))
import csv, math, sys
def dev(path):
    rows = list(csv.reader(open(path)))
    assert rows[0] == ["t", "L1.f", "L2.f"] and len(rows) == 502, rows[0]
    worst = 0
    for r in rows[1:]:
        i1 = (1 - math.exp(-float(r[0]) / 3)) / 2
        worst = max(worst, abs(float(r[1]) - i1), abs(float(r[2]) - (1 - i1)))
    return worst
d1, d2 = dev(sys.argv[1]), dev(sys.argv[2])
assert d1 < 5e-3, "delta with a parasitic C against the hand solution: %g" % d1
assert d2 < d1 / 5, "delta: C 100 times smaller, %g vs %g" % (d2, d1)
PY
"$BG" examples/rlc.bg --transform parasitic -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "parasitic on rlc refused" '[ $rc -eq 3 ] && grep -qF "it has no algebraic loop between resistors (class 2 causal path), no causal loop and no conflict" "$TMP/err"'
# a type 2 conflict of degree 2 (Figure 4.28): a 0-junction with a C in two of
# the three bonds that want to set j's flow
SCD=examples/series_conductances.bg
"$BG" $SCD --transform parasitic -o "$TMP/sd.bg" 2>"$TMP/err"; rc=$?
check "parasitic on a type 2 conflict: new junctions in bonds 3 and 4" '[ $rc -eq 0 ] && grep -qxF "bond 3 j -> jp_Rb" "$TMP/sd.bg" && grep -qxF "bond 9 jp_Rb -> Rb" "$TMP/sd.bg" && grep -qxF "bond 10 jp_Rc -> Rc" "$TMP/sd.bg" && grep -qxF "bond 7 jp_Rb -> Cp_Rb" "$TMP/sd.bg" && grep -qxF "0   jp_Rc" "$TMP/sd.bg"'
"$BG" "$TMP/sd.bg" --check >"$TMP/check" 2>&1
check "parasitic on a type 2 conflict: no conflict, an ODE" 'grep -qxF "conflicts: 0" "$TMP/check" && grep -qF "form: ode" "$TMP/check"'
"$BG" $SCD --simulate -o "$TMP/sd0.csv" 2>/dev/null
"$BG" "$TMP/sd.bg" --simulate -o "$TMP/sd1.csv" 2>/dev/null
python3 - "$TMP/sd0.csv" "$TMP/sd1.csv" <<'PY' || fail=$((fail + 1))
import csv, sys
a, b = (list(csv.reader(open(p))) for p in sys.argv[1:])
assert a[0] == b[0] == ["t", "Cl.e"] and len(a) == len(b) == 502, (a[0], len(b))
col = [float(r[1]) for r in a[1:]]
d = max(abs(float(x[1]) - float(y[1])) for x, y in zip(a[1:], b[1:])) / (max(col) - min(col))
assert d < 1e-5, "parasitic on series_conductances: deviation %g" % d
PY

# --- relax-junction: Figure 4.26, a flow source forcing a conductance ----------
FR=$D/forced.bg
"$BG" $FR --transform relax-junction -o "$TMP/fr.bg" 2>"$TMP/err"; rc=$?
check "relax exit 0" '[ $rc -eq 0 ]'
check "relax: a 0-junction in bond 1, the bond split, relaxed causality" 'grep -qxF "0   jRg" "$TMP/fr.bg" && grep -qxF "bond 1 S -> jRg" "$TMP/fr.bg" && grep -qxF "bond 5 jRg -> Rg" "$TMP/fr.bg" && grep -qxF "causality relaxed" "$TMP/fr.bg" && grep -q "^# .*Figure 4.26" "$TMP/fr.bg"'
"$BG" $FR --check >"$TMP/check0" 2>&1
"$BG" "$TMP/fr.bg" --check >"$TMP/check" 2>&1; rc=$?
check "relax: the original solves Rg's law implicitly" 'grep -qF "inverted resistor law solved implicitly (Rg)" "$TMP/check0"'
check "relax: the violation is at the new junction, Rg keeps its law" '[ $rc -eq 0 ] && grep -qxF "conflicts: 1 (type 1 at jRg)" "$TMP/check" && ! grep -qF "inverted" "$TMP/check"'
"$BG" "$TMP/fr.bg" --equations text >"$TMP/eq"
# Equation 4.46's form: the balance at the 0-junction determines its effort
check "relax: Rg in conductance causality, the junction's balance" 'grep -qxF "f5 = G0*e5^3" "$TMP/eq" && grep -qxF "0 = f1 - f5    (solved for S.e)" "$TMP/eq"'
"$BG" $FR --simulate -o "$TMP/fr0.csv" 2>/dev/null
"$BG" "$TMP/fr.bg" --simulate -o "$TMP/fr1.csv" 2>/dev/null
python3 - "$TMP/fr0.csv" "$TMP/fr1.csv" <<'PY' || fail=$((fail + 1))
import csv, sys
a, b = (list(csv.reader(open(p))) for p in sys.argv[1:])
assert a[0] == b[0] == ["t", "C1.e", "Rg.e"] and len(a) == len(b) > 100, (a[0], b[0])
for j in (1, 2):
    col = [float(r[j]) for r in a[1:]]
    d = max(abs(float(x[j]) - float(y[j])) for x, y in zip(a[1:], b[1:])) / (max(col) - min(col))
    assert d < 1e-6, "relax: %s deviates by %g" % (a[0][j], d)
# Rg.e = cbrt(i/G0) exactly: the same law, now solved at the junction
import math
for r in b[1:]:
    t, e = float(r[0]), float(r[2])
    assert abs(e - ((1 + 0.5 * math.sin(t)) / 2) ** (1 / 3)) < 1e-6, (t, e)
PY
"$BG" examples/hydraulic_bridge.bg --transform relax-junction -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "relax on hydraulic_bridge refused (no source forces a resistor)" '[ $rc -eq 3 ] && grep -qF "no source forces a resistor against its law" "$TMP/err"'

# --- the report: section "Transformation", the bond graph before and after --------
"$BG" $HB --transform parasitic --report "$TMP/r1.pdf" 2>"$TMP/err"; rc=$?
"$BG" $HB --transform parasitic --report "$TMP/r2.pdf" 2>/dev/null
check "report with --transform alone: exit 0, no .bg needed" '[ $rc -eq 0 ] && [ -s "$TMP/r1.pdf" ]'
check "report rerun identical" 'cmp -s "$TMP/r1.pdf" "$TMP/r2.pdf"'
pdftotext -layout "$TMP/r1.pdf" "$TMP/r.txt"
check "report: the section, what changed, before and after" 'grep -qE "^ *[0-9]+ +Transformation" "$TMP/r.txt" && grep -qF -- "--transform parasitic wrote a new model. A small C store Cp_n1" "$TMP/r.txt" && grep -qx " *Before" "$TMP/r.txt" && grep -qx " *After" "$TMP/r.txt"'
check "report: the comparison table (2 class 2 paths before, 0 after; DAE -> ODE)" 'grep -qE "class 2 causal paths +2 +0" "$TMP/r.txt" && grep -qE "form +DAE +ODE" "$TMP/r.txt"'
check "report: the new stores drawn" '[ $(grep -c "Cp" "$TMP/r.txt") -ge 3 ]'
"$BG" $HB --report "$TMP/r0.pdf" 2>/dev/null
pdftotext "$TMP/r0.pdf" "$TMP/r0.txt"
check "report without --transform has no such section" '! grep -q "Transformation" "$TMP/r0.txt"'

# --- misuse ---------------------------------------------------------------------
"$BG" $D/gear.bg --transform merge-store -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "unknown transformation: exit 2" '[ $rc -eq 2 ] && grep -qF "unknown transformation '"'"'merge-store'"'"': --transform takes one of: merge-stores, parasitic, relax-junction" "$TMP/err"'
"$BG" $D/gear.bg -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check ".bg without --transform: exit 2" '[ $rc -eq 2 ] && grep -qF "a .bg output is the model rewritten by --transform" "$TMP/err"'
"$BG" $D/gear.bg --transform merge-stores -o "$TMP/x.svg" 2>"$TMP/err"; rc=$?
check "--transform without .bg: exit 2" '[ $rc -eq 2 ] && grep -qF "add -o NEW.bg" "$TMP/err"'
"$BG" $D/gear.bg --transform merge-stores --check 2>"$TMP/err"; rc=$?
check "--check --transform: exit 2" '[ $rc -eq 2 ]'
"$BG" examples/rlc.bg --transform merge-stores -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "merge on rlc refused: exit 3, the reason" '[ $rc -eq 3 ] && grep -qF "bgdraw: error: --transform merge-stores does not apply to rlc: it has no class 1 causal path" "$TMP/err"'
check "refusal writes nothing" '[ ! -e "$TMP/x.bg" ]'
"$BG" examples/class12_paths.bg --transform merge-stores -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "merge with two class 1 paths to one store refused" '[ $rc -eq 3 ] && grep -qF "the dependent store C2 ends 2 class 1 causal paths" "$TMP/err"'
cp $D/gear.bg "$TMP/in.bg"
"$BG" "$TMP/in.bg" --transform merge-stores -o "$TMP/in.bg" 2>"$TMP/err"; rc=$?
check "writing onto the model refused" '[ $rc -eq 2 ] && cmp -s $D/gear.bg "$TMP/in.bg"'
"$BG" $D/gear.bg --transform merge-stores -T bg >"$TMP/stdout.bg"
check "-T bg writes to stdout" 'cmp -s "$TMP/stdout.bg" "$TMP/gear.bg"'

if [ "$fail" -ne 0 ]; then echo "transform_cli: $fail failures"; exit 1; fi
echo "transform_cli: ok"
