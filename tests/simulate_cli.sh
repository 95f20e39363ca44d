#!/usr/bin/env bash
# The CLI's simulation end to end (CLI.md): `--simulate -o X.csv` writes the
# CSV (header, one row per output time, last time = t_end), reruns are
# byte-identical, a failing run exits 3 and still writes the rows it has
# with a final "# partial:" line, a refused model writes nothing and says why.
# Usage: bash tests/simulate_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: simulate_cli.sh PATH_TO_BGDRAW}
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

check() { # check NAME CONDITION-STATUS
  if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL $1"; fi
}

# rlc: t_end = 2e-3, dt = 1e-6 -> 2001 rows, plot C1.e, L1.f
"$BGDRAW" examples/rlc.bg --simulate -o "$tmp/rlc.csv" 2>"$tmp/err"; st=$?
check "rlc exit status 0 (got $st: $(head -c 300 "$tmp/err"))" $((st != 0))
[ "$(head -n 1 "$tmp/rlc.csv" 2>/dev/null)" = "t,C1.e,L1.f" ]; check "rlc header" $?
[ "$(grep -vc '^#' "$tmp/rlc.csv" 2>/dev/null)" = 2002 ]; check "rlc 2001 rows + header" $?
last=$(tail -n 1 "$tmp/rlc.csv" 2>/dev/null | cut -d, -f1)
awk -v t="$last" 'BEGIN { exit !(t + 0 == 0.002) }'; check "rlc last time = t_end (got $last)" $?
! grep -q '^#' "$tmp/rlc.csv" 2>/dev/null; check "rlc complete run has no comment line" $?
# C1.e at t_end is close to the final value V = 1 (analytic: 1 - 4.5e-5)
v=$(tail -n 1 "$tmp/rlc.csv" 2>/dev/null | cut -d, -f2)
awk -v v="$v" 'BEGIN { exit !(v > 0.99 && v < 1.01) }'; check "rlc C1.e(t_end) ~ 1 (got $v)" $?

# byte-identical reruns
"$BGDRAW" examples/rlc.bg --simulate -o "$tmp/rlc2.csv" 2>/dev/null
cmp -s "$tmp/rlc.csv" "$tmp/rlc2.csv"; check "rlc rerun byte-identical" $?
# a DAE through IDA, -o .csv implies --simulate
"$BGDRAW" examples/hydraulic_bridge.bg -o "$tmp/hb.csv" 2>/dev/null; st=$?
check "hydraulic_bridge exit status 0 (got $st)" $((st != 0))
[ "$(head -n 1 "$tmp/hb.csv" 2>/dev/null)" = "t,v.f,n1.e,n4.e" ]; check "hydraulic_bridge header" $?
[ "$(wc -l <"$tmp/hb.csv" 2>/dev/null)" = 502 ]; check "hydraulic_bridge 501 rows + header" $?
"$BGDRAW" examples/hydraulic_bridge.bg -o "$tmp/hb2.csv" 2>/dev/null
cmp -s "$tmp/hb.csv" "$tmp/hb2.csv"; check "hydraulic_bridge rerun byte-identical" $?

# a failing run: exit 3, partial rows and the reason in the file and on stderr
cat >"$tmp/blow.bg" <<'BG'
model blow "A capacitor charged past its law's domain"
param I0 = 2, R0 = 1
Sf S = I0
0  n
C  C1 : e = sqrt(1 - q)
R  R1 = R0
bond 1 S -> n
bond 2 n -> C1
bond 3 n -> R1
simulate t_end = 2, dt = 0.05
plot C1.q
BG
"$BGDRAW" "$tmp/blow.bg" --simulate -o "$tmp/blow.csv" 2>"$tmp/err"; st=$?
check "failing run exits 3 (got $st)" $((st != 3))
grep -q 'failed at t = 0.77' "$tmp/err"; check "failing run: stderr names the time reached" $?
[ "$(head -n 1 "$tmp/blow.csv" 2>/dev/null)" = "t,C1.q" ]; check "failing run: CSV header" $?
[ "$(grep -vc '^#' "$tmp/blow.csv" 2>/dev/null)" = 17 ]; check "failing run: rows to t = 0.75" $?
tail -n 1 "$tmp/blow.csv" 2>/dev/null | grep -q '^# partial: simulation failed at t = 0.77'
check "failing run: final '# partial:' line" $?

# refused: delta with SCAP (class 5 loop): no CSV, the reason and the remedy
"$BGDRAW" examples/delta.bg --simulate -o "$tmp/delta.csv" 2>"$tmp/err"; st=$?
check "refused run exits non-zero (got $st)" $((st == 0 || st == 2))
[ ! -e "$tmp/delta.csv" ]; check "refused run writes no CSV" $?
grep -q 'causal loop 1' "$tmp/err" && grep -q -- '--causality vandijk' "$tmp/err"
check "refused run names the loop and the remedy" $?

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
