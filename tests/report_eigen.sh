#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The report's eigenvalue table (docs/report.md): a complex pair is one
# "re ± im" row however many rows precede it (two pairs and a real
# eigenvalue give three rows, not five), and a conserved quantity's
# eigenvalue (1e-17 of the largest) reads "zero (a conserved quantity)",
# never "unstable". Usage: bash tests/report_eigen.sh PATH_TO_BGDRAW
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
command -v pdftotext >/dev/null || { echo "SKIP: pdftotext not installed"; exit 0; }
# the rows of the table: from its header to the next blank line
rows() { pdftotext -layout "$1" - | sed -n '/Eigenvalue λ/,/^$/p' | grep -E '^ *[0-9]+ '; }

cat >"$tmp/pairs.bg" <<'M'
Se U = step(t)
1 j1
R R1 = 0.1
I L1 = 1
C C1 = 1
1 j2
R R2 = 0.2
I L2 = 1
C C2 = 0.25
0 k
R R3 = 1
C C3 = 2
bond U -> j1
bond j1 -> R1
bond j1 -> L1
bond j1 -> C1
bond j1 -> k
bond k -> C3
bond k -> R3
bond k -> j2
bond j2 -> R2
bond j2 -> L2
bond j2 -> C2
M
"$BGDRAW" "$tmp/pairs.bg" --report "$tmp/pairs.pdf" 2>/dev/null; check "pairs: exit status" $?
rows "$tmp/pairs.pdf" >"$tmp/pairs.txt"
[ "$(wc -l <"$tmp/pairs.txt")" -eq 3 ]; cs_=$?; check "pairs: three rows ($(tr '\n' '|' <"$tmp/pairs.txt"))" $cs_
[ "$(grep -c '±' "$tmp/pairs.txt")" -eq 2 ]; check "pairs: two ± rows" $?
[ "$(grep -c 'ω = ' "$tmp/pairs.txt")" -eq 2 ]; check "pairs: two frequencies" $?

cat >"$tmp/zero.bg" <<'M'
C C1 = 0.7 [q0 = 1]
C C2 = 0.3
R R1 = 3
0 a
0 b
1 j
bond C1 -> a
bond a -> j
bond j -> R1
bond j -> b
bond b -> C2
M
"$BGDRAW" "$tmp/zero.bg" --report "$tmp/zero.pdf" 2>/dev/null; check "zero: exit status" $?
rows "$tmp/zero.pdf" >"$tmp/zero.txt"
[ "$(wc -l <"$tmp/zero.txt")" -eq 2 ]; check "zero: two rows" $?
grep -q 'zero (a conserved quantity)' "$tmp/zero.txt"; check "zero: named a conserved quantity" $?
! grep -q 'unstable' "$tmp/zero.txt"; check "zero: not unstable" $?
# the other eigenvalue, -(1/C1 + 1/C2)/R = -1.587, with its time constant 0.63 s
grep -q -- '−1.587 .*τ = 0.63 s' "$tmp/zero.txt"; check "zero: the decaying mode" $?

echo "report_eigen: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
