#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The nonlinear iteration of large Adams runs (docs/simulation.md, "Nonlinear
# iteration"): above 200 unknowns CVODE's Adams method iterates by fixed point
# (no Jacobian, no sparse LU), and a run that needs more than 2 000 steps in an
# output interval that way is made again with Newton's method and KLU.
# (1) a chain of 121 damped masses (241 unknowns, auto: Adams) against the
#     exact solution of its linear ODE from SciPy's matrix exponential, built
#     here from the chain's physics, not from bgdraw's equations;
# (2) the same chain with a damper of 1e5 on the first mass and solver =
#     cvode_adams (rtol 1e-8, atol 1e-12: its velocities are about 1e-5):
#     fixed point would need millions of steps; the run goes
#     back to Newton and agrees with the exact solution too.
# Usage: bash tests/sim_iteration.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
PY=/usr/bin/python3
chain() { # N B1 EXTRA: masses m = 1 on 1-junctions, springs k = 1 between, dampers b
  local n=$1 b1=$2 extra=$3
  echo "model chain"
  echo "param k = 1, b = 0.1, m = 1"
  echo "Se F = 1"
  for ((i = 1; i <= n; i++)); do
    echo "1 v$i"; echo "I M$i = m"
    if ((i == 1)); then echo "R B$i = $b1"; else echo "R B$i = b"; fi
  done
  for ((i = 1; i < n; i++)); do echo "0 s$i"; echo "C K$i = 1/k"; done
  echo "bond F -> v1"
  for ((i = 1; i <= n; i++)); do echo "bond v$i -> M$i"; echo "bond v$i -> B$i"; done
  for ((i = 1; i < n; i++)); do echo "bond v$i -> s$i"; echo "bond s$i -> K$i"; echo "bond s$i -> v$((i + 1))"; done
  echo "simulate t_end = 10, dt = 0.5$extra"
  echo "plot M1.f, M3.f, K1.q"
}
# exact: x' = A x + e F with x = (p_1..p_N, q_1..q_N-1), from x(0) = 0
exact() { # CSV N B1
  $PY - "$@" <<'PY'
import csv, sys
import numpy as np
from scipy.linalg import expm
path, n, b1 = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
m, k, b = 1.0, 1.0, 0.1
N = 2 * n - 1
A = np.zeros((N + 1, N + 1))          # the last row/column carries the constant force
for i in range(n):
    A[i, i] = -(b1 if i == 0 else b) / m
    if i > 0: A[i, n + i - 1] += k     # spring i-1 pushes mass i forward
    if i < n - 1: A[i, n + i] -= k     # spring i holds mass i back
for j in range(n - 1):                 # q_j' = v_j - v_j+1
    A[n + j, j] = 1 / m
    A[n + j, j + 1] = -1 / m
A[0, N] = 1.0                          # F = 1 on mass 1
rows = list(csv.reader(open(path)))[1:]
worst = scale = 0
E = expm(A * 0.5)                      # one output step (dt = 0.5)
x = np.zeros(N + 1)
x[N] = 1.0                             # x(0) = 0 with the augmented state 1
for i, r in enumerate(rows):
    if abs(float(r[0]) - 0.5 * i) > 1e-12: sys.exit(1)
    if i: x = E @ x
    want = [x[0] / m, x[2] / m, x[n]]  # M1.f, M3.f, K1.q
    got = [float(v) for v in r[1:4]]
    worst = max(worst, max(abs(g - w) for g, w in zip(got, want)))
    scale = max(scale, max(abs(w) for w in want))
print("largest deviation %.3g of %.3g" % (worst, scale))
sys.exit(0 if len(rows) == 21 and worst <= 1e-5 * scale else 1)
PY
}
chain 121 b "" >"$tmp/c.bg"
"$BGDRAW" "$tmp/c.bg" --simulate -o "$tmp/c.csv" -o "$tmp/c.json" -v 2>"$tmp/c.err"; st=$?
check "chain: exit 0 (got $st)" $st
grep -q "241 unknowns, solver cvode_adams, fixed-point iteration (no Jacobian) (auto:" "$tmp/c.err"
check "chain: auto chose Adams, iterated by fixed point" $?
$PY -c "import json,sys; s=json.load(open(sys.argv[1]))['simulation']; sys.exit(not (s['linear_solver'] == 'none' and s['statistics']['jacobian_evaluations'] == 0))" "$tmp/c.json"
check "chain: JSON says no linear solver, no Jacobian" $?
exact "$tmp/c.csv" 121 0.1; check "chain: the exact solution" $?
"$BGDRAW" "$tmp/c.bg" -q --report "$tmp/c.pdf"
pdftotext "$tmp/c.pdf" - | tr -s ' \n' ' ' | grep -q "cvode_adams, fixed-point iteration (no Jacobian)"
check "chain: the report's solver row" $?

chain 121 1e5 ", solver = cvode_adams, rtol = 1e-8, atol = 1e-12" >"$tmp/s.bg"
"$BGDRAW" "$tmp/s.bg" --simulate -o "$tmp/s.csv" -o "$tmp/s.json" -v 2>"$tmp/s.err"; st=$?
check "stiff chain: exit 0 (got $st)" $st
grep -q "fixed-point iteration failed (.*maximum number of steps.*); again with Newton's method and KLU" "$tmp/s.err"
check "stiff chain: back to Newton, saying why" $?
$PY -c "import json,sys; s=json.load(open(sys.argv[1]))['simulation']; sys.exit(not (s['linear_solver'] == 'klu' and s['statistics']['jacobian_evaluations'] > 0 and s['statistics']['steps'] < 20000))" "$tmp/s.json"
check "stiff chain: JSON says KLU, the Newton run's statistics" $?
exact "$tmp/s.csv" 121 1e5; check "stiff chain: the exact solution" $?
"$BGDRAW" "$tmp/s.bg" --simulate -o "$tmp/s2.csv" 2>"$tmp/s2.err"
cmp -s "$tmp/s.csv" "$tmp/s2.csv"; check "stiff chain: the same CSV without -v" $?
[ ! -s "$tmp/s2.err" ]; check "stiff chain: nothing on stderr without -v" $?
finish
