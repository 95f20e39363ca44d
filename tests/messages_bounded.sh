#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Messages that name the cause (issue 28):
# - --set a=inf and --set a=nan are errors naming the param; a param that
#   is infinite in the file is a warning at the param (a NaN param is an
#   error: tests/bad/param_nan.bg);
# - the predicted index does not count a capped list of causal paths as if
#   it were complete: "at least N class 1 causal paths";
# - --transform keeps the CRLF line endings of a CRLF file in every line it
#   writes, and the LF ones of an LF file;
# - a switching condition that is not a number (sqrt of a negative) names
#   the operation, the condition, its line and the time (the analytic one:
#   R1 switches from 1 to 2 at q = 0.75, and q reaches 1, where sqrt(1 - q)
#   leaves its domain, at t = ln(1/0.625) + 2 ln(1.25) = 0.9163), with CVODE
#   and with IDA, instead of SUNDIALS' raw IDA_RTFUNC_FAIL text;
# - extreme time axes name the real cause: t0 = 1e308 (t + h == t there), a
#   span that overflows (refused), a span of 1e308 for a model of time scale 1.
# Usage: bash tests/messages_bounded.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
printf 'model m\nparam a = 1, big = 1/0\nSe U = 1\nR R1 = a\nbond U -> R1\n' > m.bg
for v in inf nan -inf; do
  "$BGDRAW" m.bg --check --set a=$v > /dev/null 2>err; st=$?
  check "--set a=$v: status 1 (got $st)" $((st != 1))
  grep -q "^m.bg: error: --set a=$v: a param takes a finite number$" err
  cs_=$?; check "--set a=$v: the error names the param and the value ($(head -1 err))" $cs_
done
"$BGDRAW" m.bg --check > /dev/null 2>err; st=$?
check "an infinite param in the file: still exit 0 (got $st)" $st
grep -q "^m.bg:2:14: warning: param 'big' is infinite (inf)$" err; check "an infinite param: a warning at it" $?

python3 -c '
n = 1200
print("\n".join(["model j", "Sf F = 1", "0 j"] + ["C C%d = 1" % i for i in range(1, n + 1)]
                + ["bond F -> j"] + ["bond j -> C%d" % i for i in range(1, n + 1)]))' > j.bg
"$BGDRAW" j.bg --check --max-list 5 > sum.txt
grep -q "^form: dae; predicted index: 1 (at least 4 class 1 causal paths (dependent stores))$" sum.txt
check "a capped path list: the index reason says at least" $?
"$BGDRAW" j.bg --check > sum.txt
grep -q "^form: dae; predicted index: 1 (at least 999 class 1 causal paths (dependent stores))$" sum.txt
check "the default cap too (1199 dependent stores)" $?
"$BGDRAW" "$root/examples/class12_paths.bg" --check | grep -q "predicted index: 1 (2 class 1 causal paths (dependent stores); 1 class 2"
check "a complete list keeps its plain count" $?

sed 's/$/\r/' "$root/tests/data/transform/gear.bg" > crlf.bg
"$BGDRAW" crlf.bg --transform merge-stores -o merged.bg 2>err; st=$?
check "--transform on a CRLF file: exit 0 (got $st; $(head -c 200 err))" $st
lf=$(grep -c $'[^\r]$\|^$' merged.bg) all=$(wc -l < merged.bg)
check "--transform: every one of the $all lines ends in CR LF ($lf do not)" $((lf != 0 || all < 5))
"$BGDRAW" merged.bg --check > /dev/null; check "the CRLF result reads back" $?
mkdir lf && tr -d '\r' < crlf.bg > lf/crlf.bg # the same name: the header names the file
"$BGDRAW" lf/crlf.bg --transform merge-stores -o merged_lf.bg
! grep -q $'\r' merged_lf.bg; check "--transform on an LF file writes no CR" $?
cmp <(tr -d '\r' < merged.bg) merged_lf.bg; check "the CRLF and LF results differ only in line endings" $?
# ------------------------------------------------------ a NaN switching condition
for form in 'R R1 = if(sqrt(1 - C1.q) > 0.5, 1, 2)' 'R R1 : e = if(sqrt(1 - C1.q) > 0.5, f, 2*f)'; do
  printf 'model rootnan\nSe U = 2\n1 j\nC C1 = 1\n%s\nbond U -> j\nbond j -> C1\nbond j -> R1\nsimulate t_end = 5\n' "$form" > root.bg
  "$BGDRAW" root.bg --simulate -o root.csv 2>err; st=$?
  check "NaN condition ($form): status 3 (got $st)" $((st != 3))
  grep -q "the search for state events stopped: sqrt of a negative number in the switching condition '[a-z]* of R1[.f]*: sqrt(1 - C1.q) > 0.5' (line 5) at t = " err
  cs_=$?; check "NaN condition ($form): the operation, the condition and its line ($(head -c 300 err))" $cs_
  ! grep -q 'RTFUNC_FAIL: \|, ,' err; check "NaN condition ($form): no raw SUNDIALS text" $?
  tc=$(sed -n 's/.*(line 5) at t = \([0-9.e+-]*\).*/\1/p' err)
  python3 -c "import math,sys; t=math.log(1/0.625)+2*math.log(1.25); sys.exit(abs(float('$tc')-t) > 0.01)"
  check "NaN condition ($form): at t = $tc, the analytic 0.9163" $?
done

# ------------------------------------------------------ extreme time axes
rc() { printf 'model span\nSe U = 1\n1 j\nC C1 = 1\nR R1 = 1\nbond U -> j\nbond j -> C1\nbond j -> R1\nsimulate %s\n' "$1" > span.bg; }
rc "t0 = 1e308, t_end = 1.5e308"
"$BGDRAW" span.bg --simulate -o span.csv 2>err; st=$?
check "t0 = 1e308: status 3 (got $st)" $((st != 3))
grep -q "is below the spacing of the time values at t = 1e+308 (adjacent doubles there are 2e+292 apart, so t + h == t).*start it nearer 0 (t0 = 0, t_end = 5e+307)" err
cs_=$?; check "t0 = 1e308: the time axis' resolution named ($(head -c 300 err))" $cs_
! grep -q "singular" err; check "t0 = 1e308: not blamed on a singular point" $?
rc "t0 = -1e308, t_end = 1e308"
"$BGDRAW" span.bg --simulate -o span.csv 2>err; st=$?
check "a span beyond the largest double: refused, status 3 (got $st)" $((st != 3))
grep -q "simulation refused: the span from t0 = -1e+308 to t_end = 1e+308 is larger than the largest number" err
cs_=$?; check "a span beyond the largest double: the message ($(head -c 200 err))" $cs_
rc "t_end = 1e308"
"$BGDRAW" span.bg --simulate -o span.csv 2>err; st=$?
check "a span of 1e308: status 3 (got $st)" $((st != 3))
grep -q "the model's time scale is far shorter than a span this long" err
cs_=$?; check "a span of 1e308: the span named ($(head -c 300 err))" $cs_
rc "t0 = 1e15, t_end = 2e15"
"$BGDRAW" span.bg --simulate -o span.csv 2>err; st=$?
check "t0 = 1e15 (adjacent times 0.125 apart): simulates (got $st)" $st
last=$(tail -1 span.csv | cut -d, -f2)
python3 -c "import sys; sys.exit(abs(float('$last') - 1) > 1e-6)"; check "t0 = 1e15: C1.q settles at 1 (got $last)" $?
finish
