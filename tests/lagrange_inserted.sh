#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Lagrange causality with a 1-junction inserted into a bond (docs/equations.md,
# "Lagrange causality"): each model below gets an inserted junction under
# --causality lagrange; its simulation must agree with the same model's SCAP
# run. Tolerance: every CSV column within 1e-4 of that column's largest
# magnitude over the run, at every output time (the solvers run at the
# models' rtol of 1e-6 or their own default; measured differences are below
# 2e-5, bridge_compliance's piston velocity the largest).
# Usage: bash tests/lagrange_inserted.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"


# model and the bonds that get an inserted 1-junction
for spec in "bridge_compliance 1,4" "internal_mod_r 4" "internal_mod_tf 3" \
            "mod_no_loop 4" "parallel_conductance 2"; do
  set -- $spec
  x=$1 bonds=$2
  "$BGDRAW" "examples/$x.bg" --causality lagrange -o "$tmp/$x.json" 2>"$tmp/err"
  cs_=$?; check "$x lagrange JSON (got: $(head -c 300 "$tmp/err"))" $cs_
  python3 - "$tmp/$x.json" "$bonds" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
want = ["bond %s" % b for b in sys.argv[2].split(",")]
got = [c for c in d["lagrange"]["coordinates"] if c.startswith("bond ")]
sys.exit(0 if got == want and d["index"]["numeric"] == 1 else 1)
PY
  check "$x: inserted 1-junctions in bonds $bonds, numeric index 1" $?
  "$BGDRAW" "examples/$x.bg" --causality lagrange --simulate -o "$tmp/$x.L.csv" 2>"$tmp/err"
  cs_=$?; check "$x lagrange run (got: $(head -c 300 "$tmp/err"))" $cs_
  "$BGDRAW" "examples/$x.bg" --causality scap --simulate -o "$tmp/$x.S.csv" 2>"$tmp/err"
  cs_=$?; check "$x scap run (got: $(head -c 300 "$tmp/err"))" $cs_
  python3 - "$tmp/$x.L.csv" "$tmp/$x.S.csv" <<'PY'
import csv, sys
def rows(p):
    return list(csv.reader(l for l in open(p) if not l.startswith("#")))
L, S = rows(sys.argv[1]), rows(sys.argv[2])
if L[0] != S[0] or len(L) != len(S) or len(S) < 100:
    sys.exit("headers or row counts differ")
for i, name in enumerate(S[0]):
    scale = max(abs(float(r[i])) for r in S[1:]) or 1.0
    worst = max(abs(float(a[i]) - float(b[i])) for a, b in zip(L[1:], S[1:]))
    if worst > 1e-4 * scale:
        sys.exit("%s differs by %g (scale %g)" % (name, worst, scale))
PY
  check "$x: Lagrange and SCAP simulations agree to 1e-4" $?
done

finish
