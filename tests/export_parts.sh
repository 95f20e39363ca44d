#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The C export in parts (issue 34, "Exports that compile"): a model's code is
# cut into functions of at most 100 instructions (docs/export.md), so that
# the compile time grows linearly with the model instead of superlinearly.
# On a chain of 120 masses (239 states, 242 instructions a function of the
# right-hand side before the cut): every part has at most 100 assignments,
# and the compiled right-hand side equals the Python export's bit for bit
# (the same operations in the same order, printed by another printer) at
# 20 random points.
# Usage: bash tests/export_parts.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
/usr/bin/python3 - >chain.bg <<'PY'
n = 120
print('model chain "a mass-spring-damper chain"')
print("param m0 = 1, k0 = 100, b0 = 2")
print("Se F = step(t)")
for i in range(1, n + 1):
    print(f"1 v{i}\nI m{i} = m0 * (1 + {i % 7} / 10)\nR d{i} = b0")
    if i < n:
        print(f"0 s{i}\nC k{i} = 1 / (k0 * (1 + {i % 5} / 10))")
print("bond F -> v1")
for i in range(1, n + 1):
    print(f"bond v{i} -> m{i}\nbond v{i} -> d{i}")
    if i < n:
        print(f"bond v{i} -> s{i}\nbond s{i} -> k{i}\nbond s{i} -> v{i + 1}")
PY
"$BGDRAW" chain.bg -o chain.c -o chain.py; check "exports written" $?
parts=$(grep -c '^static BG_NOINLINE void bg_main_' chain.c)
[ "$parts" -ge 3 ]; check "the equations come in parts (got $parts)" $?
longest=$(awk '/^static BG_NOINLINE void/ {n = 0; inside = 1; next}
  inside && /^}/ {if (n > m) m = n; inside = 0} inside && /^  [vd]\[[0-9]+\] = / {n++}
  END {print m + 0}' chain.c)
[ "$longest" -le 100 ] && [ "$longest" -ge 50 ]; check "at most 100 assignments a part (longest $longest)" $?
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
finish
