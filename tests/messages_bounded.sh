#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Messages that name the cause (issue 28):
# - --set a=inf and --set a=nan are errors naming the param; a param that
#   is infinite in the file is a warning at the param (a NaN param is an
#   error: tests/bad/param_nan.bg);
# - the predicted index does not count a capped list of causal paths as if
#   it were complete: "at least N class 1 causal paths";
# - --transform keeps the CRLF line endings of a CRLF file in every line it
#   writes, and the LF ones of an LF file.
# Usage: bash tests/messages_bounded.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
printf 'model m\nparam a = 1, big = 1/0\nSe U = 1\nR R1 = a\nbond U -> R1\n' > m.bg
for v in inf nan -inf; do
  "$BGDRAW" m.bg --check --set a=$v > /dev/null 2>err; st=$?
  check "--set a=$v: status 1 (got $st)" $((st != 1))
  grep -q "^m.bg: error: --set a=$v: a param takes a finite number$" err
  check "--set a=$v: the error names the param and the value ($(head -1 err))" $?
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
finish
