#!/usr/bin/env bash
# The CLI's simulation end to end (docs/cli.md, docs/simulation.md):
# `--simulate -o X.csv` writes the CSV (header, one row per output time,
# last time = t_end), reruns are
# byte-identical, a failing run exits 3 and still writes the rows it has
# with a final "# partial:" line, a refused model writes nothing and says why.
# Usage: bash tests/simulate_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"


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

# parallel_conductance (relaxed causality, IDA): 1 = G0 e^3 + p, p' = e gives
# p(t) = 1 - (1 - 2t/3)^(3/2) for G0 = 1; compare every row to 1e-4
"$BGDRAW" examples/parallel_conductance.bg -o "$tmp/pc.csv" 2>/dev/null; st=$?
check "parallel_conductance exit status 0 (got $st)" $((st != 0))
awk -F, 'NR > 1 { p = 1 - (1 - 2 * $1 / 3) ^ 1.5; d = $2 - p; if (d < 0) d = -d
                  if (d > 1e-4) bad++; n++ }
         END { exit !(n > 100 && bad == 0) }' "$tmp/pc.csv"
check "parallel_conductance Lk.f = 1 - (1 - 2t/3)^1.5" $?

# refused for a conflict that constrains states (delta with R1 forced to
# conductance, Figure 4.17): the remedy is a store at the junction, not vandijk
sed 's/^R   R1 = R10/R   R1 = R10 [causality = conductance]/' examples/delta.bg >"$tmp/delta_c.bg"
"$BGDRAW" "$tmp/delta_c.bg" --simulate -o "$tmp/delta_c.csv" 2>"$tmp/err"; st=$?
check "delta R1 conductance refused, exit 3 (got $st)" $((st != 3))
grep -q 'type 1 conflict at nC' "$tmp/err" && grep -q 'small store (C at a 0-junction' "$tmp/err" &&
  ! grep -q -- '--causality vandijk' "$tmp/err"
check "conflict refusal names the junction and its own remedy" $?

# lagrange_rlc: Lagrange causality (mass-matrix DAE) and SCAP give the same
# response to 1e-4
"$BGDRAW" examples/lagrange_rlc.bg -o "$tmp/lr.csv" 2>/dev/null; st1=$?
"$BGDRAW" examples/lagrange_rlc.bg --causality scap -o "$tmp/lr2.csv" 2>/dev/null; st2=$?
check "lagrange_rlc both methods run (got $st1, $st2)" $((st1 != 0 || st2 != 0))
paste -d, "$tmp/lr.csv" "$tmp/lr2.csv" | awk -F, 'NR > 1 { for (i = 2; i <= 3; i++) {
    d = $i - $(i + 3); if (d < 0) d = -d; if (d > 1e-4) bad++ }; n++ }
    END { exit !(n == 1001 && bad == 0) }'
check "lagrange_rlc: Lagrange and SCAP responses agree" $?

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
check "refused run exits 3 (got $st)" $((st != 3))
[ ! -e "$tmp/delta.csv" ]; check "refused run writes no CSV" $?
grep -q 'causal loop 1' "$tmp/err" && grep -q -- '--causality vandijk' "$tmp/err"
check "refused run names the loop and the remedy" $?

# the refusals of docs/examples.md, each with its reason; exit 3 and no CSV
"$BGDRAW" examples/loop_class1.bg -o "$tmp/lc.csv" 2>"$tmp/err"; st=$?
check "loop_class1 refused with exit 3 (got $st)" $((st != 3))
grep -q 'index above 1' "$tmp/err" && grep -q 'Proposition 5.10' "$tmp/err"
check "loop_class1: index above 1, Proposition 5.10" $?
[ ! -e "$tmp/lc.csv" ]; check "loop_class1 writes no CSV" $?
"$BGDRAW" examples/bond_loop.bg --set n=1 -o "$tmp/bl.csv" 2>"$tmp/err"; st=$?
check "bond_loop --set n=1 refused with exit 3 (got $st)" $((st != 3))
grep -q 'causal loop 1 (bonds 1, 2, 3, 4) has gain +1' "$tmp/err"
check "bond_loop --set n=1 names the loop" $?
"$BGDRAW" examples/modulated_source.bg --set k=2 -o "$tmp/ms.csv" 2>"$tmp/err"; st=$?
check "modulated_source --set k=2 refused with exit 3 (got $st)" $((st != 3))
grep -q 'Equation 4.45' "$tmp/err"; check "modulated_source --set k=2: singular loop (Eq. 4.45)" $?
# --set changes the run: an overdamped rlc is stiff, auto picks BDF
"$BGDRAW" examples/rlc.bg --set R0=1e4 -o "$tmp/rlc_o.csv" -v 2>"$tmp/err"; st=$?
check "rlc --set R0=1e4 exit 0 (got $st)" $((st != 0))
grep -q 'solver cvode_bdf' "$tmp/err"; check "rlc --set R0=1e4: auto chose BDF" $?
! cmp -s "$tmp/rlc.csv" "$tmp/rlc_o.csv"; check "rlc --set R0=1e4: other results" $?
# -v: the solver choice and the summary with the statistics; a short run is
# below the progress lines' throttle
grep -q 'bgdraw: simulate: done in .* steps, .* function and .* Jacobian evaluations, .* error test failures' "$tmp/err"
check "-v prints the summary with solver statistics" $?
! grep -q '% of the span' "$tmp/err"; check "-v: no progress lines for a short run" $?

# the analysis JSON gets a "simulation" object when the run simulated
"$BGDRAW" examples/rlc.bg --simulate -o "$tmp/rlc.json" 2>/dev/null; st=$?
check "rlc --simulate -o .json exit 0 (got $st)" $((st != 0))
grep -q '^  "simulation": {$' "$tmp/rlc.json"; check "JSON has the simulation object" $?
grep -q '"status": "ok"' "$tmp/rlc.json" && grep -q '"solver": "cvode_adams"' "$tmp/rlc.json"
check "JSON simulation: status and solver" $?
grep -Eq '"statistics": \{"steps": [1-9][0-9]*, "function_evaluations": [1-9][0-9]*, "jacobian_evaluations": [0-9]+, "error_test_failures": [0-9]+, "nonlinear_iterations": [0-9]+\}' "$tmp/rlc.json"
check "JSON simulation: statistics" $?
"$BGDRAW" examples/rlc.bg -o "$tmp/rlc_plain.json" 2>/dev/null
! grep -q '"simulation"' "$tmp/rlc_plain.json"; check "JSON without --simulate has no simulation object" $?
"$BGDRAW" examples/delta.bg --simulate -o "$tmp/delta.json" 2>/dev/null; st=$?
check "delta --simulate -o .json: exit 3 (got $st)" $((st != 3))
grep -q '"status": "refused"' "$tmp/delta.json"; check "JSON simulation: refused" $?
"$BGDRAW" "$tmp/blow.bg" -o "$tmp/blow.json" -o "$tmp/blow2.csv" 2>/dev/null
grep -q '"status": "failed"' "$tmp/blow.json" && grep -q '"partial": true' "$tmp/blow.json"
check "JSON simulation: failed, partial" $?
if command -v python3 >/dev/null; then
  for j in rlc delta blow; do
    python3 -m json.tool "$tmp/$j.json" >/dev/null 2>&1; check "$j.json is valid JSON" $?
  done
fi

# initial values the equations override are reported (class12_paths: the
# dependent store C2 starts at 1/3, not at the model's default 0); -q hides it
"$BGDRAW" examples/class12_paths.bg -o "$tmp/c12.csv" 2>"$tmp/err"
grep -q 'note: initial values made consistent: C2.q 0 -> 0.333333' "$tmp/err"
check "class12_paths: consistent initial value reported" $?
"$BGDRAW" examples/class12_paths.bg -o "$tmp/c12.csv" -q 2>"$tmp/err"
[ ! -s "$tmp/err" ]; check "-q: no note" $?

finish
