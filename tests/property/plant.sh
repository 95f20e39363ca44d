#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The planted-bug demonstrations (docs/property.md): copies the engine to a
# temporary folder, plants one error there (nothing in the repository
# changes), builds that bgdraw and runs a campaign on it, which must find the
# error (and shrink it to a handful of bonds).
# Usage: bash tests/property/plant.sh [N] [DIR] [PLANT] [SEED] [MAX_ELEMS]
#   (from the project root; N models from SEED (default 1; a comma list: those
#   seeds, N ignored), up to MAX_ELEMS elements (default 30); DIR keeps the
#   copy, its build and the shrunk models)
# PLANT:
#   tf          (default) src/equations/eqsys.c: in the TF whose side 1
#               receives the effort, f1 = n f2 becomes f1 = -n f2
#   integrator  src/simulate/simulate_run.c: CVODE's right-hand side 0.1 %
#               too large (bgdraw's own ODE runs go 0.1 % fast; the exports,
#               the reduced form and the linear model do not share it)
#   indexred    src/equations/indexred.c: the index reduction differentiates
#               with every chain-rule term 1 % too large (the reduced system
#               no longer has the model's dynamics; the parasitic stores'
#               runs still do)
#   busy        src/equations/eqsys.c: deriving a GY's equations never ends
#               (a busy loop): `robust` stops each such run at its CPU bound
#               (tests/property/limits.py), whatever the machine's load
#   block       the same place waits for a signal (pause(): no CPU used):
#               the wall-time guard stops it (set PROP_WALL=20 to see it
#               soon; its default is 600 s or more)
set -eu
n=${1:-200}
dir=${2:-$(mktemp -d)}
plant=${3:-tf}
seed=${4:-1}
max=${5:-30}
root=$PWD
mkdir -p "$dir"
git -C "$root" archive HEAD | tar -x -C "$dir"
python3 - "$dir" "$plant" <<'PY'
import sys
root, plant = sys.argv[1:3]
f, old, new = {
    "tf": ("src/equations/eqsys.c",
           "set_eq(d, fa, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb)), e, w);",
           "set_eq(d, fa, EQF_EXPLICIT, n_signed(s, -1, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb))), e, w);"),
    "integrator": ("src/simulate/simulate_run.c",
                   "  if (bg_eqsys_rhs(R->s, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) == 0) return 0;",
                   "  if (bg_eqsys_rhs(R->s, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) == 0) "
                   "{ for (int i = 0; i < R->n; i++) N_VGetArrayPointer(ydot)[i] *= 1.001; return 0; }"),
    "indexred": ("src/equations/indexred.c",
                 "    t[k++] = bg_sym_mul(S, d, ir_var_leaf(W, W->v_der[v]));",
                 "    t[k++] = bg_sym_mul(S, bg_sym_mul(S, bg_sym_num(S, 1.01), d), ir_var_leaf(W, W->v_der[v]));"),
    "busy": ("src/equations/eqsys.c", '  w = "ratio";',
             '  w = "ratio"; { volatile unsigned long spin = 0; while (k == BG_ELEM_GY) spin++; }'),
    "block": ("src/equations/eqsys.c", '  w = "ratio";',
              '  w = "ratio"; if (k == BG_ELEM_GY) { extern int pause(void); for (;;) pause(); }'),
}[plant]
p = root + "/" + f
s = open(p).read()
assert s.count(old) >= 1, "the planted line moved: " + f
open(p, "w").write(s.replace(old, new, 1))
PY
cmake -S "$dir" -B "$dir/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$dir/build" -j"$(nproc)" --target bgdraw >/dev/null
case $seed in *,*) which=(--seeds "$seed") ;; *) which=(--count "$n" --seed "$seed") ;; esac
rm -rf "$dir/found"
st=0
python3 "$root/tests/property/prop.py" "$dir/build/bgdraw" "${which[@]}" --max-elems "$max" \
  --found "$dir/found" --known reorder_reduced --known shuffled_outcome --known merge_stores_outcome || st=$?
# found means: the campaign failed (exit 1, not a crash of its own) and kept a shrunk model
[ "$st" = 1 ] && ls "$dir"/found/*.bg 2>/dev/null ||
  { echo "plant.sh: the planted error ($plant) was not found (exit status $st)"; exit 1; }
echo "plant.sh: found and shrunk ($plant); models in $dir/found"
