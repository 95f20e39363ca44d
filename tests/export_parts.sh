#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The C export that compiles quickly (issue 34, "Exports that compile";
# docs/export.md, "Compile time"): runs of a repeated pattern of statements
# are written as loops over tables of slots, the straight code between them
# in functions of at most 100 instructions. On a chain of 120 masses with
# parameters varying from mass to mass (239 states): the right-hand side,
# the residual, the Jacobian and its derivatives come as loops, straight
# parts have at most 100 assignments, and the compiled right-hand side equals
# the Python export's bit for bit (the same operations in the same order,
# printed by another printer) at 20 random points. On that chain, a chain of
# masses in pairs (a dependent inertia in each pair: a DAE) and a chain
# whose dampers switch (state events; an event's number comes from the table
# like a slot): every function of the C
# export (initial values, right-hand side, residual, Jacobian, outputs, root
# functions) with loops equals the same export written straight
# (BGDRAW_EXPORT_LOOPS=0, the code of before) bit for bit at 20 random points.
# Usage: bash tests/export_parts.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
# chains of n masses: chain (masses and springs varying from mass to mass),
# pairs (two masses on each 1-junction: a dependent inertia, a DAE), switch
# (two dampers in three stiffer one way: state events)
cat >gen.py <<'PY'
import sys
kind, n = sys.argv[1], int(sys.argv[2])
print(f'model {kind} "a chain of {n} masses"')
print("param m0 = 1, k0 = 100, b0 = 2")
print("Se F = step(t)")
for i in range(1, n + 1):
    mass = f"m0 * (1 + {i % 7} / 10)" if kind != "switch" else "m0"
    extra = f"\nI n{i} = m0 / 2" if kind == "pairs" else ""
    law = ": e = if(f > 0, b0 * f, 3 * b0 * f)" if kind == "switch" and i % 3 else "= b0"
    print(f"1 v{i}\nI m{i} = {mass}{extra}\nR d{i} {law}")
    if i < n:
        spring = f"1 / (k0 * (1 + {i % 5} / 10))" if kind == "chain" else "1 / k0"
        print(f"0 s{i}\nC k{i} = {spring}")
print("bond F -> v1")
for i in range(1, n + 1):
    print(f"bond v{i} -> m{i}\nbond v{i} -> d{i}")
    if kind == "pairs":
        print(f"bond v{i} -> n{i}")
    if i < n:
        print(f"bond v{i} -> s{i}\nbond s{i} -> k{i}\nbond s{i} -> v{i + 1}")
PY
/usr/bin/python3 gen.py chain 120 >chain.bg
"$BGDRAW" chain.bg -o chain.c -o chain.py; check "exports written" $?
for fn in bg_main bg_deriv; do
  loops=$(grep -c "^static const int ${fn}_[0-9]*_slots\[" chain.c)
  [ "$loops" -ge 1 ]; check "$fn: the repeated pattern as a loop over a table ($loops)" $?
done
longest=$(awk '/^static BG_NOINLINE void/ {n = 0; inside = 1; next}
  inside && /^}/ {if (n > m) m = n; inside = 0} inside && /^  [vd]\[[0-9]+\] = / {n++}
  END {print m + 0}' chain.c)
[ "$longest" -le 100 ]; check "at most 100 straight assignments a part (longest $longest)" $?
lines=$(wc -l <chain.c)
BGDRAW_EXPORT_LOOPS=0 "$BGDRAW" chain.bg -o straight.c
straight=$(wc -l <straight.c)
[ "$lines" -lt $((straight / 2)) ]; check "loops: $lines lines, straight $straight" $?
cat >drv.c <<'C'
#include <stdio.h>
#include "chain.h"
int main(void) {
  static double y[CHAIN_N], yd[CHAIN_N], work[CHAIN_NWORK];
  double t;
  while (scanf("%la", &t) == 1) {
    for (int i = 0; i < CHAIN_N; i++) if (scanf("%la", &y[i]) != 1) return 1;
    if (chain_rhs(&chain_default_params, t, y, yd, work) != 0) return 2;
    for (int i = 0; i < CHAIN_N; i++) printf("%a\n", yd[i]);
  }
  return 0;
}
C
gcc -std=c11 -O2 -Wall -Werror drv.c chain.c -lm -o drv 2>cerr; cs_=$?
check "the parts compile with -Wall -Werror ($(head -c 200 cerr))" $cs_
/usr/bin/python3 - >points.txt <<'PY'
import random
import chain
random.seed(5)
for k in range(20):
    print(float.hex(random.uniform(0, 2)))
    for i in range(chain.N):
        print(float.hex(random.uniform(-1, 1)))
PY
./drv <points.txt >c.txt; check "the C right-hand side runs" $?
/usr/bin/python3 - points.txt >py.txt <<'PY'
import sys
import chain
vals = [float.fromhex(s) for s in open(sys.argv[1]).read().split()]
k = 1 + chain.N
for j in range(0, len(vals), k):
    for d in chain.rhs(vals[j], vals[j + 1:j + k]):
        print(float.hex(float(d)))
PY
/usr/bin/python3 -c "
import sys
a = [float.fromhex(s) for s in open('c.txt').read().split()]
b = [float.fromhex(s) for s in open('py.txt').read().split()]
sys.exit(not (len(a) == len(b) == 20 * 239 and a == b and any(x != 0 for x in a)))"
check "C in parts equals the Python export bit for bit at 20 points" $?

# Every function, loops against straight, on three shapes of model
/usr/bin/python3 gen.py pairs 60 >pairs.bg
/usr/bin/python3 gen.py switch 60 >switch.bg
for mdl in chain pairs switch; do
  mkdir -p "l_$mdl" "s_$mdl"
  "$BGDRAW" $mdl.bg -o "l_$mdl/m.c" --prefix m; check "$mdl: exported with loops" $?
  BGDRAW_EXPORT_LOOPS=0 "$BGDRAW" $mdl.bg -o "s_$mdl/m.c" --prefix m; check "$mdl: exported straight" $?
  grep -q '_slots\[' "l_$mdl/m.c"; check "$mdl: the export has loops" $?
  ! grep -q '_slots\[' "s_$mdl/m.c"; check "$mdl: BGDRAW_EXPORT_LOOPS=0 writes none" $?
  cat >"drv_$mdl.c" <<'C'
#include <stdio.h>
#include <stdlib.h>
#include "m.h"
/* every function of the export at the points on stdin, each number as %a */
#ifdef M_NROOT
#define MD &md,
#else
#define MD
#endif
int main(void) {
  static double y[M_N], yp[M_N], r[M_N], jac[M_NNZ + 1], out[M_NOUT + 1], work[M_NWORK];
  double t, cj;
#ifdef M_NROOT
  static double g[M_NROOT + 1];
  m_modes md;
#endif
  m_initial(&m_default_params, 0, y, work);
  for (int i = 0; i < M_N; i++) printf("%a\n", y[i]);
  while (scanf("%la %la", &t, &cj) == 2) {
    for (int i = 0; i < M_N; i++) if (scanf("%la %la", &y[i], &yp[i]) != 2) return 1;
#ifdef M_NROOT
    m_modes_start(&m_default_params, t, y, yp, 1e-6, &md, work);
    for (int k = 0; k < M_NMODE; k++) printf("mode %a\n", md.m[k]);
    printf("%d\n", m_roots(&m_default_params, &md, t, y, yp, g, work));
    for (int k = 0; k < M_NROOT; k++) printf("%a\n", g[k]);
#endif
#if M_IS_ODE
    printf("%d\n", m_rhs(&m_default_params, MD t, y, r, work));
    for (int i = 0; i < M_NX; i++) printf("%a\n", r[i]);
#endif
    printf("%d\n", m_residual(&m_default_params, MD t, y, yp, r, work));
    for (int i = 0; i < M_N; i++) printf("%a\n", r[i]);
    printf("%d\n", m_jacobian(&m_default_params, MD t, y, yp, cj, jac, work));
    for (int k = 0; k < M_NNZ; k++) printf("%a\n", jac[k]);
    printf("%d\n", m_outputs(&m_default_params, MD t, y, yp, out, work));
    for (int k = 0; k < M_NOUT; k++) printf("%a\n", out[k]);
  }
  return 0;
}
C
  n=$(sed -n 's/^#define M_N \([0-9]*\).*/\1/p' "l_$mdl/m.h")
  /usr/bin/python3 - "$n" >"pts_$mdl.txt" <<'PY'
import random, sys
random.seed(7)
for k in range(20):
    print(float.hex(random.uniform(0, 2)), float.hex(random.uniform(1, 1e3)))
    for i in range(int(sys.argv[1])):
        print(float.hex(random.uniform(-1, 1)), float.hex(random.uniform(-1, 1)))
PY
  for how in l s; do
    gcc -std=c11 -O2 -Wall -Werror -I"${how}_$mdl" "drv_$mdl.c" "${how}_$mdl/m.c" -lm -o "${how}_$mdl/drv" 2>"${how}_$mdl/cerr"
    st=$?
    check "$mdl ($how): compiles with -Wall -Werror ($(head -c 200 "${how}_$mdl/cerr"))" $st
    "${how}_$mdl/drv" <"pts_$mdl.txt" >"${how}_$mdl/out.txt"; check "$mdl ($how): runs" $?
  done
  nums=$(grep -c . "l_$mdl/out.txt")
  [ "$nums" -gt $((20 * n)) ] && cmp -s "l_$mdl/out.txt" "s_$mdl/out.txt"
  check "$mdl ($n unknowns): loops equal straight code bit for bit ($nums numbers)" $?
done
grep -q '^#define M_IS_ODE 0' l_pairs/m.h; check "pairs is a DAE" $?
grep -q '^#define M_NROOT [1-9]' l_switch/m.h; check "switch has root functions" $?
grep -q 'bg_at(c, x\[[0-9]*\], ' l_switch/m.c && grep -q 'if (bg_held(c, x\[[0-9]*\])) d\[x\[' l_switch/m.c
check "switch: its switching instructions and their derivatives loop too" $?
finish
