#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The planted-bug demonstration (docs/property.md): copies the engine to a
# temporary folder, plants a sign error in the transformer's equations there
# (f1 = -n f2 where the TF's side 1 receives the effort; nothing in the
# repository changes), builds that bgdraw and runs a campaign on it, which
# must find the error and shrink it to a handful of bonds.
# Usage: bash tests/property/plant.sh [N] [DIR]   (from the project root;
# N models, default 200; DIR keeps the copy, its build and the shrunk models)
set -eu
n=${1:-200}
dir=${2:-$(mktemp -d)}
root=$PWD
mkdir -p "$dir"
git -C "$root" archive HEAD | tar -x -C "$dir"
f=$dir/src/equations/eqsys.c
# the first TF branch: set_eq(d, fa, ..., n_mul(modulus, fb)) -> -(n_mul(...))
python3 - "$f" <<'PY'
import sys
p = sys.argv[1]
s = open(p).read()
old = "set_eq(d, fa, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb)), e, w);"
new = "set_eq(d, fa, EQF_EXPLICIT, n_signed(s, -1, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb))), e, w);"
assert s.count(old) >= 1, "the planted line moved"
s = s.replace(old, new, 1)
open(p, "w").write(s)
PY
cmake -S "$dir" -B "$dir/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$dir/build" -j"$(nproc)" --target bgdraw >/dev/null
python3 "$root/tests/property/prop.py" "$dir/build/bgdraw" --count "$n" --max-elems 30 \
  --found "$dir/found" && { echo "plant.sh: the planted error was not found"; exit 1; }
ls "$dir/found"
echo "plant.sh: found and shrunk; models in $dir/found"
