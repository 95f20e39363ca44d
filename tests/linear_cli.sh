#!/usr/bin/env bash
# The linear analysis on the command line (docs/linear.md): --linear text,
# latex and json with the hand-derived transfer functions of an RLC circuit,
# the "linear" key of the analysis JSON, refusals (exit 3), examples without
# a linearise statement keep their JSON.
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
"$BG" $M --linear yaml 2>/dev/null; rc=$?
check "bad form: exit 2" '[ $rc -eq 2 ]'
echo "linear_cli: $fail failures"
[ "$fail" -eq 0 ]
