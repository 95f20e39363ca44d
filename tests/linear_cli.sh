#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The linear analysis on the command line (docs/linear.md): --linear text,
# latex and json with the hand-derived transfer functions of an RLC circuit,
# the "linear" key of the analysis JSON, refusals (exit 3), examples without
# a linearise statement keep their JSON; Bode, Nyquist and step plots (svg,
# pdf, png, reruns identical, errors); the .m and .py exports (parsed; run
# when octave or numpy are installed).
# Usage: bash tests/linear_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
BG=${1:?usage: linear_cli.sh PATH_TO_BGDRAW}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail=0
check() { if eval "$2"; then :; else echo "FAIL $1"; fail=$((fail + 1)); fi; }
M=tests/data/linear_rlc.bg

"$BG" $M --linear text >"$TMP/t.txt" 2>"$TMP/err"; rc=$?
check "text exit 0" '[ $rc -eq 0 ]'
check "vC/U" 'grep -qxF "vC/U = (20) / (s^2 + 4*s + 20)" "$TMP/t.txt"'
check "i/U" 'grep -qxF "i/U = (2*s) / (s^2 + 4*s + 20)" "$TMP/t.txt"'
check "poles" 'grep -qF -- "-2 ± 4j   wn = 4.47214 rad/s, zeta = 0.447214" "$TMP/t.txt"'
# a coefficient that prints as 1 is left out before s (in the examples' rlc the
# numerator of L1.p/U is 1 within rounding; it printed "(1*s)")
"$BG" examples/rlc.bg --linear text >"$TMP/rlc.txt" 2>/dev/null
check "rlc: no 1*s" 'grep -qxF "L1.p/U = (s) / (s^2 + 10000*s + 1e+09)" "$TMP/rlc.txt"'
check "no diagram written" '[ ! -e out/linear_rlc.svg ]'
"$BG" $M --linear latex >"$TMP/t.tex"
check "latex" 'grep -qF "\frac{vC}{U} &= \frac{20}{s^{2} + 4 s + 20}" "$TMP/t.tex"'
"$BG" $M --linear json >"$TMP/l.json"
"$BG" $M -o "$TMP/a.json"
"$BG" $M -o "$TMP/b.json"
check "json rerun identical" 'cmp -s "$TMP/a.json" "$TMP/b.json"'
python3 - "$TMP/l.json" "$TMP/a.json" <<'PY' || fail=$((fail + 1))
import json, sys
lin = json.load(open(sys.argv[1]))
doc = json.load(open(sys.argv[2]))
assert doc["linear"] == lin, "the JSON key differs from --linear json"
assert lin["status"] == "ok" and lin["operating_point"]["kind"] == "steady"
assert lin["operating_point"]["outputs"] == [1, 0], lin["operating_point"]
ss = lin["state_space"]
assert ss["states"] == ["L1.p", "C1.q"] and ss["A"] == [[-4, -10], [2, 0]], ss
tf = lin["transfer_functions"]
assert [t["output"] for t in tf] == ["vC", "i"] and tf[0]["den"] == [1, 4, 20]
assert abs(tf[0]["num"][0] - 20) < 1e-12 and abs(tf[0]["dc_gain"] - 1) < 1e-12
assert abs(lin["poles"][1]["zeta"] - 0.2 * 5 ** 0.5) < 1e-12
PY
"$BG" examples/rlc.bg -o "$TMP/e.json"
check "no linear key without linearise" '! grep -q "\"linear\"" "$TMP/e.json"'
printf 'Se F = 1\n1 j\nI m = 2\nbond F -> j\nbond j -> m\nlinearise at = steady\n' >"$TMP/mass.bg"
"$BG" "$TMP/mass.bg" --linear text >/dev/null 2>"$TMP/err"; rc=$?
check "refused: exit 3" '[ $rc -eq 3 ]'
check "refused: message" 'grep -q "linear analysis refused: no steady state" "$TMP/err"'
"$BG" "$TMP/mass.bg" -o "$TMP/m.json" 2>/dev/null; rc=$?
check "JSON of a refused linearisation: exit 0" '[ $rc -eq 0 ] && grep -q "\"status\": \"refused\"" "$TMP/m.json"'
# plots: Bode, Nyquist, step in every format, well-formed, byte-identical reruns
"$BG" $M --bode "$TMP/b.svg" --nyquist "$TMP/n.svg" --step "$TMP/s.svg"; rc=$?
check "plots exit 0" '[ $rc -eq 0 ]'
for f in b n s; do
  check "$f.svg well-formed" 'xmllint --noout "$TMP/$f.svg" 2>/dev/null'
done
"$BG" $M --bode "$TMP/b.pdf" --nyquist "$TMP/n.png" --step "$TMP/s.pdf" --style print
"$BG" $M --bode "$TMP/b2.pdf" --nyquist "$TMP/n2.png" --step "$TMP/s2.pdf" --style print
check "pdf signature" '[ "$(head -c 4 "$TMP/b.pdf")" = "%PDF" ]'
check "png signature" '[ "$(head -c 4 "$TMP/n.png" | tail -c 3)" = "PNG" ]'
check "plot reruns identical" 'cmp -s "$TMP/b.pdf" "$TMP/b2.pdf" && cmp -s "$TMP/n.png" "$TMP/n2.png" && cmp -s "$TMP/s.pdf" "$TMP/s2.pdf"'
"$BG" $M --bode "$TMP/b.txt" 2>/dev/null; rc=$?
check "bode bad extension: exit 2" '[ $rc -eq 2 ]'
"$BG" $M --bode /nonexistent/dir/b.svg 2>/dev/null; rc=$?
check "bode unwritable: exit 4" '[ $rc -eq 4 ]'
"$BG" "$TMP/mass.bg" --bode "$TMP/never.svg" 2>/dev/null; rc=$?
check "refused: no plot, exit 3" '[ $rc -eq 3 ] && [ ! -e "$TMP/never.svg" ]'

# exports: Octave and Python state space with the hand-derived matrices
"$BG" $M --linear octave >"$TMP/rlc.m" && "$BG" $M --linear python >"$TMP/rlc.py"; rc=$?
check "exports exit 0" '[ $rc -eq 0 ]'
check "octave A" 'grep -qxF "A = [-4 -10;" "$TMP/rlc.m" && grep -qxF "     2 0];" "$TMP/rlc.m"'
check "octave names" 'grep -qxF "state_names = {'"'"'L1.p'"'"', '"'"'C1.q'"'"'};" "$TMP/rlc.m"'
python3 - "$TMP/rlc.py" <<'PY' || fail=$((fail + 1))
import ast, sys
tree = ast.parse(open(sys.argv[1]).read())
vals = {}
for node in tree.body:
    if isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Name):
        v = node.value
        if isinstance(v, ast.Call):  # np.array(LIST, dtype=float)
            v = v.args[0]
        vals[node.targets[0].id] = ast.literal_eval(v)
assert vals["A"] == [[-4, -10], [2, 0]], vals["A"]
assert vals["B"] == [[1], [0]] and vals["C"] == [[0, 10], [2, 0]] and vals["D"] == [[0], [0]]
assert vals["states"] == ["L1.p", "C1.q"] and vals["inputs"] == ["U"] and vals["outputs"] == ["vC", "i"]
assert vals["x0"] == [0, 0.1] and vals["y0"] == [1, 0]
PY
if python3 -c "import numpy" 2>/dev/null; then
  (cd "$TMP" && python3 -c "import rlc, numpy as np; assert np.allclose(np.linalg.eigvals(rlc.A), [-2+4j, -2-4j]) or np.allclose(np.linalg.eigvals(rlc.A), [-2-4j, -2+4j])") || { echo "FAIL python module"; fail=$((fail + 1)); }
fi
if command -v octave >/dev/null; then
  octave -q --no-gui --eval "run('$TMP/rlc.m'); assert(max(abs(sort(eig(A)) - [-2-4i; -2+4i])) < 1e-12)" 2>"$TMP/octave.err" || { echo "FAIL octave"; fail=$((fail + 1)); }
fi
"$BG" "$TMP/mass.bg" --linear octave >"$TMP/never.m" 2>/dev/null; rc=$?
check "refused export: exit 3, nothing written" '[ $rc -eq 3 ] && [ ! -s "$TMP/never.m" ]'

# report: section 10 with the poles beside the chapter's estimates and the transfer functions
"$BG" $M --report "$TMP/r.pdf"; rc=$?
check "report exit 0" '[ $rc -eq 0 ]'
pdftotext -layout "$TMP/r.pdf" "$TMP/r.txt"
check "report section" 'grep -q "10  *Linear analysis" "$TMP/r.txt"'
check "report pole beside estimate" 'grep -q "ω0 = 4.472 rad/s (path P3): the same to 0.5 %" "$TMP/r.txt"'
check "report transfer function" 'grep -q "vC ← U" "$TMP/r.txt" && grep -q "Bode diagram" "$TMP/r.txt"'
"$BG" examples/rlc.bg --report "$TMP/e.pdf"
pdftotext "$TMP/e.pdf" "$TMP/e.txt"
check "no linear section without linearise" '! grep -q "Linear analysis" "$TMP/e.txt"'

# dependent stores: eliminated (text, JSON), the merged inertia J1 + n^2 J2 = 14
G=tests/data/linear_gear.bg
"$BG" $G --linear text >"$TMP/g.txt"; rc=$?
check "gear exit 0" '[ $rc -eq 0 ]'
check "gear states" 'grep -qxF "states: I1.p (dependent stores eliminated: I2.p)" "$TMP/g.txt"'
check "gear symbolic A" 'grep -qxF "A = [ -b1/(J1 + J2*n^2) ]" "$TMP/g.txt"'
"$BG" $G --linear json >"$TMP/g.json"
python3 - "$TMP/g.json" <<'PY' || fail=$((fail + 1))
import json, sys
ss = json.load(open(sys.argv[1]))["state_space"]
assert ss["states"] == ["I1.p"] and ss["eliminated"] == ["I2.p"], ss
assert abs(ss["A"][0][0] + 1 / 28) < 1e-15, ss["A"]
PY
sed -e 's/^output .*/output w = I1.f, tq = T.e/' -e 's/^Se T = 1/Sf T = 1/' $G >"$TMP/gf.bg"
"$BG" "$TMP/gf.bg" --linear text >"$TMP/gf.txt"; rc=$?
check "flow-driven gear: improper torque named" 'grep -qF "not reduced: output tq needs the derivative of input T (an improper transfer function)" "$TMP/gf.txt"'
"$BG" "$TMP/gf.bg" --step "$TMP/gf.svg" 2>"$TMP/gf.err"; rc=$?
check "flow-driven gear: no step plot (exit 3)" '[ $rc -eq 3 ] && grep -q "descriptor form only" "$TMP/gf.err"'
sed -e 's/^output .*/output w = I1.f/' "$TMP/gf.bg" >"$TMP/gf2.bg"
"$BG" "$TMP/gf2.bg" --linear text >"$TMP/gf2.txt" 2>&1
check "flow-driven gear without the torque: no states left, w = T" 'grep -qxF "states: none" "$TMP/gf2.txt" && grep -qxF "w/T = (1) / (1)" "$TMP/gf2.txt" && ! grep -q "incorrect" "$TMP/gf2.txt"'

"$BG" $M --linear yaml 2>/dev/null; rc=$?
check "bad form: exit 2" '[ $rc -eq 2 ]'
echo "linear_cli: $fail failures"
[ "$fail" -eq 0 ]
