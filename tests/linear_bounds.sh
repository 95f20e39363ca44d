#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The linear analysis on its edges (issue 28):
# - a frequency range beyond the limit (w_min = 1e-200, w_max = 1e200 once
#   made every frequency inf and the Bode plot loop) is refused at --check
#   with the position of w_max; non-finite bounds (1/0, 0/0) are refused;
#   25 decades within the limit draw a Bode plot (a decade label every
#   third decade), SVG and report, under a CPU limit;
# - a model without states linearised at the steady state calls no LAPACK
#   routine with n = 0 and adds no note; its output line says none;
# - without an output statement the outputs are the stores' states, a
#   dependent store's too: the symbolic form expresses it through the others
#   (C2.q = 2 C1.q) instead of calling the model non-LTI.
# Usage: bash tests/linear_bounds.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
cpu() { bash -c 'ulimit -t 20; exec "$@"' _ "$@"; }
rc_model() { # W_OPTIONS
  printf 'model rc\nSe U = 1\n1 j\nR R1 = 2\nC C1 = 1\nbond U -> j\nbond j -> R1\nbond j -> C1\nlinearise %s\n' "$1"
}

# ------------------------------------------------------ frequency ranges
rc_model "w_min = 1e-200, w_max = 1e200" > wide.bg
cpu "$BGDRAW" wide.bg --bode wide.svg 2>err; st=$?
check "30+ decades: refused with status 1 (got $st)" $((st != 1))
grep -q "^wide.bg:9:35: error: w_max / w_min (1e+200 / 1e-200) spans more than 30 decades, the limit of a frequency response" err
check "30+ decades: the diagnostic at w_max names the limit" $?
[ ! -e wide.svg ]; check "30+ decades: no plot written" $?
for bad in "w_max = 1/0" "w_min = 0/0" "t_end = 1/0"; do
  rc_model "$bad" > bad.bg
  cpu "$BGDRAW" bad.bg --check > /dev/null 2>err; st=$?
  key=${bad%% *}
  check "$bad: refused with status 1 (got $st)" $((st != 1))
  grep -q "^bad.bg:9:[0-9]*: error: $key must be a positive finite number, not " err
  check "$bad: the diagnostic says positive finite" $?
done
rc_model "w_min = 1e-200, w_max = 1e-175" > deep.bg
cpu "$BGDRAW" deep.bg --bode deep.svg 2>err; st=$?
check "25 decades: Bode exits 0 within 20 s of CPU (got $st)" $st
labels=$(grep -o '<text class="tick" [^>]*><tspan>10</tspan><tspan[^>]*>[^<]*' deep.svg | sed 's/.*>//' | tr '\n' ' ')
[ "$labels" = "−200 −197 −194 −191 −188 −185 −182 −179 −176 " ]
check "25 decades: a decade label every third decade, 10^-200 .. 10^-176 (got $labels)" $?
# the exponent is a superscript in the SVG too: raised by a few points (pango's rise is in
# 1/1024 pt: read as points it put the exponent 3 784 pt above its 10) and smaller
sup=$(grep -o '<text class="tick" [^>]*font-size="\([0-9.]*\)"[^>]*><tspan>10</tspan><tspan[^>]*>' deep.svg | head -1)
fs=$(echo "$sup" | sed 's/.*<text[^>]*font-size="\([0-9.]*\)".*/\1/')
dy=$(echo "$sup" | sed -n 's/.*<tspan dy="\([-0-9.]*\)" font-size="\([0-9.]*\)">$/\1 \2/p')
awk -v fs="$fs" -v d="$dy" 'BEGIN { split(d, a, " "); exit !(a[1] < -0.2 * fs && a[1] > -fs && a[2] > 0.5 * fs && a[2] < fs) }'
check "25 decades: the exponent raised by less than its font size and smaller (font $fs, dy and size: $dy)" $?
grep -q '<tspan>magnitude \[dB\]' deep.svg && grep -q '<text class="tick t1" [^>]*><tspan>0<' deep.svg
check "25 decades: the magnitude panel is drawn (|H| = 1: around 0 dB)" $?
cpu "$BGDRAW" deep.bg --report deep.pdf 2>err; st=$?
check "25 decades: the report exits 0 within 20 s of CPU (got $st)" $st

# ------------------------------------------------------ no states
printf 'model z\nSe U = 1 + t\nR R1 = 2\nbond U -> R1\nlinearise at = steady\n' > nostate.bg
cpu "$BGDRAW" nostate.bg --linear text > lin.txt 2>err; st=$?
check "no states, steady: exits 0 (got $st)" $st
! grep -qi "parameter\|DGETRF\|DGELSD" err lin.txt; check "no states: LAPACK is not called with n = 0" $?
! grep -q "not unique\|note" err lin.txt; check "no states: no note about the steady state" $?
grep -q "^outputs: none (no output statement and no states)$" lin.txt; check "no states: outputs none" $?
grep -q "^states: none$" lin.txt; check "no states: states none" $?

printf 'model d\nSe U = 1 + t\nC C1 = 3\nbond U -> C1\nlinearise at = steady\n' > dep0.bg
cpu "$BGDRAW" dep0.bg --linear text > lin.txt 2>err; st=$?
check "a dependent store alone: exits 0 (got $st)" $st
grep -q "^D = \[3\]$" lin.txt; check "a dependent store alone: D = C = 3" $?
grep -q "^C1.q/U = (3) / (1)$" lin.txt && ! grep -q "does not match" lin.txt
check "a dependent store alone: the symbolic form matches (no non-LTI note)" $?

# ------------------------------------------------------ dependent store as an output
printf 'model two\nSf F = 1\n0 j\nC C1 = 1\nC C2 = 2\nbond F -> j\nbond j -> C1\nbond j -> C2\n' > two.bg
"$BGDRAW" two.bg --linear text > lin.txt 2>err; st=$?
check "two stores on a 0-junction: exits 0 (got $st)" $st
grep -q "^C2.q/F = (0.6666666666666667) / (s)$" lin.txt
check "two stores: C2.q/F = (2/3)/s symbolically (q2 = 2 q1, q1' + q2' = F)" $?
! grep -q "does not match" lin.txt; check "two stores: no non-LTI note" $?
finish
