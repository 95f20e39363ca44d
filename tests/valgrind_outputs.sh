#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# bgdraw's own memory on every output kind (issue 20): one run writes every
# -o format (svg pdf png dot json tex c csv), the plot and the report of the
# RLC example; --check and --equations text run too; then the exports, the
# FMU (bgdraw itself; the C compiler it runs is not traced), the linear
# outputs, a transformation, events, index reduction, fields and a
# collapsed submodel. Under valgrind: no
# invalid read, write or free, and no block definitely lost that bgdraw
# itself allocated (its first frame above the allocator is in bgdraw's code;
# fontconfig's and pango's process-wide caches are theirs; the loader's over-reads
# of a RUNPATH in a dlopen are suppressed: tests/valgrind.supp). In a sanitizer
# build (valgrind cannot run those) the same runs go through ASan with leak
# detection on, the libraries' caches suppressed (tests/lsan.supp).
# Usage: bash tests/valgrind_outputs.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
m=$root/examples/rlc.bg
d=$root/tests/data
runs=("$m --simulate -o x.svg -o x.pdf -o x.png -o x.dot -o x.json -o x.tex -o x.c -o x.csv --plot p.svg --report r.pdf"
      "$m --check" "$m --equations text"
      # the exports, the linear analysis and its plots, a transformation,
      # state events, an index-reduced DAE, n-port fields, a collapsed submodel
      "$m -o x.m -o x.py -o x.mo -o x.fmu --verify -o v.csv"
      "$d/linear_rlc.bg --linear json --bode b.svg --nyquist n.pdf --step s.png"
      "$root/examples/hydraulic_bridge.bg --transform parasitic -o t.bg"
      "$d/bouncing_ball.bg --simulate -o e.csv -o e.json"
      "$root/examples/delta.bg --simulate -o i.csv"
      "$d/fields/transducer.bg --simulate -o f.csv -o f.svg --report f.pdf"
      "$root/examples/components/motor_drive.bg --collapse all -o c.svg")
cd "$tmp"
if grep -qa __asan_init "$BGDRAW"; then
  for i in "${!runs[@]}"; do
    ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$root/tests/lsan.supp \
      $BGDRAW ${runs[$i]} >out 2>log; st=$?
    check "ASan+LSan run $i exits 0 (got $st)" $st
    ! grep -q "ERROR: \(Address\|Leak\)Sanitizer" log; check "ASan+LSan run $i: no report" $?
  done
else
  for i in "${!runs[@]}"; do
    valgrind -q --leak-check=full --show-leak-kinds=definite --num-callers=40 --suppressions="$root/tests/valgrind.supp" \
      --log-file=vg$i.log $BGDRAW ${runs[$i]} >out 2>err; st=$?
    check "valgrind run $i exits 0 (got $st)" $st
    ! grep -q "Invalid read\|Invalid write\|Invalid free\|Mismatched free\|overlap" vg$i.log
    check "valgrind run $i: no invalid access" $?
    # a definite leak is bgdraw's when the frame above malloc has a source line of ours
    own=$(awk '/definitely lost in loss record/ { rec = 1; first = 1; next }
               rec && /by 0x/ { if (first && $0 ~ /\([a-z_0-9]+\.c:[0-9]+\)/) n++; first = 0 }
               /^==[0-9]+== $/ { rec = 0 }
               END { print n + 0 }' vg$i.log)
    check "valgrind run $i: no leak of bgdraw's own memory ($own)" $((own != 0))
    [ "$own" -eq 0 ] || grep -A12 "definitely lost" vg$i.log | head -40
  done
  for f in x.svg x.pdf x.png x.dot x.json x.tex x.c x.csv p.svg r.pdf x.m x.py x.mo b.svg n.pdf \
           s.png t.bg v.csv e.csv e.json i.csv f.csv f.svg f.pdf c.svg x.fmu; do
    [ -s $f ] || { echo "FAIL $f not written"; fail=$((fail + 1)); }
  done
fi
echo "valgrind_outputs: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
