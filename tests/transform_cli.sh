#!/usr/bin/env bash
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

# --- misuse ---------------------------------------------------------------------
"$BG" $D/gear.bg --transform merge-store -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "unknown transformation: exit 2" '[ $rc -eq 2 ] && grep -qF "unknown transformation '"'"'merge-store'"'"': --transform takes one of: merge-stores" "$TMP/err"'
"$BG" $D/gear.bg -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check ".bg without --transform: exit 2" '[ $rc -eq 2 ] && grep -qF "a .bg output is the model rewritten by --transform" "$TMP/err"'
"$BG" $D/gear.bg --transform merge-stores -o "$TMP/x.svg" 2>"$TMP/err"; rc=$?
check "--transform without .bg: exit 2" '[ $rc -eq 2 ] && grep -qF "add -o NEW.bg" "$TMP/err"'
"$BG" $D/gear.bg --transform merge-stores --check 2>"$TMP/err"; rc=$?
check "--check --transform: exit 2" '[ $rc -eq 2 ]'
"$BG" examples/rlc.bg --transform merge-stores -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "merge on rlc refused: exit 3, the reason" '[ $rc -eq 3 ] && grep -qF "bgdraw: error: --transform merge-stores does not apply to rlc: it has no class 1 causal path" "$TMP/err"'
check "refusal writes nothing" '[ ! -e "$TMP/x.bg" ]'
"$BG" examples/slider_crank.bg --transform merge-stores -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "merge through an MTF refused with the reason" '[ $rc -eq 3 ] && grep -qF "passes MTF T, which is not a transformer with a constant modulus" "$TMP/err"'
"$BG" examples/class12_paths.bg --transform merge-stores -o "$TMP/x.bg" 2>"$TMP/err"; rc=$?
check "merge with two class 1 paths to one store refused" '[ $rc -eq 3 ] && grep -qF "the dependent store C2 ends 2 class 1 causal paths" "$TMP/err"'
cp $D/gear.bg "$TMP/in.bg"
"$BG" "$TMP/in.bg" --transform merge-stores -o "$TMP/in.bg" 2>"$TMP/err"; rc=$?
check "writing onto the model refused" '[ $rc -eq 2 ] && cmp -s $D/gear.bg "$TMP/in.bg"'
"$BG" $D/gear.bg --transform merge-stores -T bg >"$TMP/stdout.bg"
check "-T bg writes to stdout" 'cmp -s "$TMP/stdout.bg" "$TMP/gear.bg"'

if [ "$fail" -ne 0 ]; then echo "transform_cli: $fail failures"; exit 1; fi
echo "transform_cli: ok"
