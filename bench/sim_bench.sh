#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Benchmark (not a test): a 10 000-state RC ladder through `bgdraw --simulate`
# and through bench/rc_ladder_hand.c (hand-written right-hand side and sparse
# Jacobian, same CVODE BDF + KLU settings, the same rtol 1e-6 and atol 1e-9:
# the model says so, bgdraw's size-scaled default would be tighter); prints
# both times, wall and CPU (the machine may be shared), and the ratios:
# end to end (parse, analysis, equations, simulation, CSV) and the
# simulation alone (bgdraw's own "done in" figure, same work as the
# hand-written program). Best of RUNS runs (default 3).
# Usage: bash bench/sim_bench.sh PATH_TO_BGDRAW [N] [T_END]   (from the project root)
set -eu
BGDRAW=${1:?usage: sim_bench.sh PATH_TO_BGDRAW [N] [T_END]}
N=${2:-10000}
TEND=${3:-10}
RUNS=${RUNS:-3}
case $BGDRAW in */*) BGDRAW=$(cd "$(dirname "$BGDRAW")" && pwd)/$(basename "$BGDRAW") ;; esac
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Se U -> 1 j1 (R1) -> 0 n1 (C1) -> 1 j2 (R2) -> 0 n2 (C2) ... -> 0 nN (CN)
awk -v n="$N" -v tend="$TEND" 'BEGIN {
  print "model rc_ladder \"RC ladder of " n " stages\""
  print "param R0 = 1, C0 = 1, U0 = 1"
  print "Se U = U0"
  b = 0
  for (k = 1; k <= n; k++) {
    printf "1 j%d\n0 n%d\nR R%d = R0\nC C%d = C0\n", k, k, k, k
    printf "bond %d %s -> j%d\n", ++b, (k == 1 ? "U" : "n" (k - 1)), k
    printf "bond %d j%d -> R%d\n", ++b, k, k
    printf "bond %d j%d -> n%d\n", ++b, k, k
    printf "bond %d n%d -> C%d\n", ++b, k, k
  }
  print "simulate t_end = " tend ", solver = cvode_bdf, rtol = 1e-6, atol = 1e-9"
  print "plot C" n ".e"
}' >"$tmp/rc_ladder.bg"

cc -O2 -o "$tmp/hand" bench/rc_ladder_hand.c -I/usr/include/suitesparse -lsundials_cvode \
  -lsundials_nvecserial -lsundials_sunmatrixsparse -lsundials_sunlinsolklu -lm

now() { date +%s.%N; }
min() { awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b < a) ? b : a }'; }
tool='' sim='' hand='' simcpu='' handcpu=''
for ((i = 0; i < RUNS; i++)); do
  s=$(now)
  "$BGDRAW" "$tmp/rc_ladder.bg" --simulate -o "$tmp/out.csv" -v 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
  e=$(now)
  tool=$(min "$tool" "$(echo "$e - $s" | bc -l)")
  sim=$(min "$sim" "$(sed -n 's/.*simulate: done in \([0-9.]*\) s.*/\1/p' "$tmp/err")")
  simcpu=$(min "$simcpu" "$(sed -n 's/.*simulate: done in [0-9.]* s (CPU \([0-9.]*\) s).*/\1/p' "$tmp/err")")
  read -r h hsteps hlast hcpu < <("$tmp/hand" "$N" "$TEND")
  hand=$(min "$hand" "$h")
  handcpu=$(min "$handcpu" "$hcpu")
done
tlast=$(tail -n 1 "$tmp/out.csv" | cut -d, -f2)
grep -E 'simulate: [0-9]+ unknowns|done in' "$tmp/err" | sed 's/^/  /' | cut -c1-160
grep -q 'sparse Jacobian, KLU' "$tmp/err" || echo "  WARNING: bgdraw did not use KLU"
printf 'states %d, t_end %s, best of %d runs\n' "$N" "$TEND" "$RUNS"
printf 'bgdraw end to end (parse, analysis, equations, simulation, CSV): %.3f s, last C%d.e %s\n' "$tool" "$N" "$tlast"
printf 'bgdraw simulation alone (integration and output rows):          %.3f s, CPU %.3f s\n' "$sim" "$simcpu"
printf 'hand-written C + CVODE BDF + KLU:                                %.3f s, CPU %.3f s (%d steps), last %s\n' "$hand" "$handcpu" "$hsteps" "$hlast"
printf 'ratio, simulation alone: %.2f wall, %.2f CPU (goal <= 1.2)\n' "$(echo "$sim / $hand" | bc -l)" "$(echo "$simcpu / $handcpu" | bc -l)"
printf 'ratio, end to end:       %.2f wall\n' "$(echo "$tool / $hand" | bc -l)"
