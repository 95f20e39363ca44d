#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Large inputs stay cheap or are refused early (issue 28):
# - 10^5 stores on one 0-junction (one integral store, 99 999 dependent
#   ones): --check finishes within 10 s of CPU (the Jacobian pattern's
#   colouring and the signal flow graph's parallel-edge test were quadratic
#   in the junction's size: 49 s before), and the summary is right;
# - submodels: a 1.8 KB file of 7 levels x 10 instances (10^7 resistors) is
#   refused at once, at the instance that crosses the flat model's limit
#   (BG_FLAT_MAX, 10^6 statements), with a caret; instances of a
#   333 332-statement submodel (five of them): the fourth is refused, naming the count
#   before it; 5 levels (10^5 resistors) flatten, and -v reports progress.
# Under AddressSanitizer the 5-level run is 4 levels (10^4 resistors). Measured
# on 2026-12-04: the release peak of the 5-level --check was the flattening
# (310 MB, valgrind massif: the statements held twice); one copy now, 226 MB.
# Under ASan the same run still took 3.1 GB and 3 min on a loaded machine (its
# shadow memory, redzones and quarantine on top of every stage); the 4-level
# case takes 0.8 GB there. The release run keeps the size, the progress line
# and the CPU bound; ASan checks the same code paths.
# Usage: bash tests/bounded_size.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
cpu() { bash -c 'ulimit -t 10; exec "$@"' _ "$@"; }

asan=0
grep -qa __asan_init "$BGDRAW" && asan=1 # gcc links libasan.so, clang links it in
python3 - <<'P'
N = 100000
out = ["model junction", "Sf F = 1", "0 j"] + [f"C C{i} = 1" for i in range(1, N + 1)]
out += ["bond F -> j"] + [f"bond j -> C{i}" for i in range(1, N + 1)]
open("junction.bg", "w").write("\n".join(out) + "\n")

def levels(top, name, extra=()):
    lines = [f"model {name}", "submodel L0", "port a", "R R1 = 1", "bond a -> R1", "end"]
    for lv in range(1, 8):
        lines += [f"submodel L{lv}", "port a", "0 j"] + [f"L{lv - 1} M{i}" for i in range(10)]
        lines += ["bond a -> j"] + [f"bond j -> M{i}.a" for i in range(10)] + ["end"]
    lines += ["Se U = 1"] + list(top)
    open(name + ".bg", "w").write("\n".join(lines) + "\n")

levels(["L7 top", "bond U -> top.a"], "deep")
levels(["0 k"] + [f"L5 {x}" for x in "abcde"] + ["bond U -> k"] + [f"bond k -> {x}.a" for x in "abcde"], "five_l5")
levels(["L5 top", "bond U -> top.a"], "five")
levels(["L4 top", "bond U -> top.a"], "four")
P

# ------------------------------------------------------ one junction
cpu "$BGDRAW" junction.bg --check > sum.txt 2>err; st=$?
check "10^5 stores on one junction: --check within 10 s of CPU (got $st)" $st
grep -q "^junction: 100001 elements (Sf 1, C 100000), 1 junction, 100001 bonds" sum.txt
check "10^5 stores: the model summary" $?
grep -q "^states (1): C1.q$" sum.txt; check "10^5 stores: one state, C1.q" $?
grep -q "^dependent stores: C2, C3, C4, C5, C6, C7, C8, C9, C10, C11, ... and 99989 more$" sum.txt
check "10^5 stores: 99 999 dependent stores" $?

# ------------------------------------------------------ submodels
cpu "$BGDRAW" deep.bg --check > /dev/null 2>err; st=$?
check "7 levels x 10: refused with status 1 within 10 s of CPU (got $st)" $((st != 1))
grep -q "^deep.bg:183:4: error: instance top of L7 expands to more than 1000000 statements, the limit of a flat model" err
check "7 levels x 10: the error at the instance" $?
grep -q "^  183 | L7 top$" err && grep -q "^      |    ^$" err; check "7 levels x 10: the line and a caret" $?
n=$(grep -c "error:" err); check "7 levels x 10: one error (got $n)" $((n != 1))
cpu "$BGDRAW" five_l5.bg --check > /dev/null 2>err; st=$?
check "five of L5: refused with status 1 (got $st)" $((st != 1))
grep -q "^five_l5.bg:187:4: error: instance d of L5 (333332 statements) would make the flat model larger than the limit of 1000000 statements (999999 before it)" err
check "five of L5: the fourth instance crosses, with the counts" $?
n=$(grep -c "error:" err); check "five of L5: one error (got $n)" $((n != 1))
if [ $asan -eq 0 ]; then
  cpu "$BGDRAW" five.bg --check -v > sum.txt 2>err; st=$?
  check "5 levels: flattens and checks within 10 s of CPU (got $st)" $st
  grep -q "^five: 100001 elements (Se 1, R 100000), 11111 junctions, 111111 bonds" sum.txt
  check "5 levels: 10^5 resistors, 11 111 junctions, 111 111 bonds" $?
  grep -q "^bgdraw: flattening: 300000 statements, 100007 instances so far$" err
  check "5 levels: -v reports the flattening's progress" $?
else # ASan: 4 levels (see the header)
  "$BGDRAW" four.bg --check > sum.txt 2>err; st=$?
  check "4 levels (ASan): flattens and checks (got $st)" $st
  grep -q "^four: 10001 elements (Se 1, R 10000), 1111 junctions, 11111 bonds" sum.txt
  check "4 levels (ASan): 10^4 resistors, 1 111 junctions, 11 111 bonds" $?
fi
finish
