#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The CLI's simulation plots end to end (docs/cli.md, docs/plots.md): `--plot
# FILE.svg|pdf|png` for every example with a simulate block that simulates,
# well-formed SVG (xmllint), file signatures, byte-identical reruns, the
# print style, a partial run (plot written, exit 3), a refused model (no
# plot, exit 3), an unknown extension (exit 2), an unwritable file (exit 4),
# and `--plot` alone writing no diagram.
# Usage: bash tests/plot_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
case "$BGDRAW" in /*) ;; *) BGDRAW="$PWD/$BGDRAW" ;; esac

sig() { head -c "$2" "$1" 2>/dev/null | od -An -c | tr -d ' \n'; }

# every example with a simulate block: refused ones (exit 3, nothing written)
# are expected for the models whose analysis forbids a run
nplotted=0
for f in $(grep -l '^simulate' examples/*.bg); do
  n=$(basename "$f" .bg)
  "$BGDRAW" "$f" --plot "$tmp/$n.svg" 2>"$tmp/err"; st=$?
  if [ "$st" -eq 3 ] && [ ! -e "$tmp/$n.svg" ]; then
    grep -q 'simulation refused' "$tmp/err"; check "$n refused says so" $?
    continue
  fi
  if [ "$st" -eq 3 ]; then # failed on the way: the partial plot
    grep -q 'simulation failed' "$tmp/err"; check "$n partial run says so" $?
    st=0
  fi
  check "$n --plot svg exit 0 (got $st: $(head -c 300 "$tmp/err"))" $((st != 0))
  xmllint --noout "$tmp/$n.svg" 2>/dev/null; check "$n svg well-formed" $?
  "$BGDRAW" "$f" --plot "$tmp/$n.2.svg" 2>/dev/null
  cmp -s "$tmp/$n.svg" "$tmp/$n.2.svg"; check "$n svg rerun byte-identical" $?
  nplotted=$((nplotted + 1))
done
[ "$nplotted" -ge 8 ]; check "at least 8 examples plotted (got $nplotted)" $?

# pdf and png, default and print style, reruns identical
for n in rlc bond_loop slider_crank; do
  for style in default print; do
    for fmt in pdf png; do
      out="$tmp/$n.$style.$fmt"
      "$BGDRAW" "examples/$n.bg" --style "$style" --plot "$out" 2>"$tmp/err"; st=$?
      check "$n $style $fmt exit 0 (got $st: $(head -c 300 "$tmp/err"))" $((st != 0))
      "$BGDRAW" "examples/$n.bg" --style "$style" --plot "$tmp/again.$fmt" 2>/dev/null
      cmp -s "$out" "$tmp/again.$fmt"; check "$n $style $fmt rerun byte-identical" $?
    done
    [ "$(sig "$tmp/$n.$style.pdf" 5)" = "%PDF-" ]; check "$n $style pdf signature" $?
    [ "$(sig "$tmp/$n.$style.png" 4)" = "211PNG" ]; check "$n $style png signature" $?
  done
done

# --plot together with -o: the CSV and the plot from one run
"$BGDRAW" examples/rlc.bg -o "$tmp/rlc.csv" --plot "$tmp/rlc.both.svg" 2>/dev/null; st=$?
check "csv + plot exit 0 (got $st)" $((st != 0))
[ -s "$tmp/rlc.csv" ] && [ -s "$tmp/rlc.both.svg" ]; check "csv + plot both written" $?
# --plot alone writes no diagram (out/<model>.svg)
mkdir -p "$tmp/cwd"
root=$PWD
(cd "$tmp/cwd" && "$BGDRAW" "$root/examples/rlc.bg" --plot p.svg 2>/dev/null); st=$?
check "--plot alone exit 0 (got $st)" $((st != 0))
[ -s "$tmp/cwd/p.svg" ] && [ ! -e "$tmp/cwd/out/rlc.svg" ]; check "--plot alone: no diagram" $?

# a partial run: exit 3, the plot is still written
cat >"$tmp/blow.bg" <<'BG'
model blow "A capacitor charged past its law's domain"
param I0 = 2, R0 = 1
Sf S = I0
0  n
C  C1 : e = sqrt(1 - q)
R  R1 = R0
bond 1 S -> n
bond 2 n -> C1
bond 3 n -> R1
simulate t_end = 2, dt = 0.05
plot C1.q
plot C1.e, R1.f [ylabel = "e, f"]
BG
"$BGDRAW" "$tmp/blow.bg" --plot "$tmp/blow.svg" 2>"$tmp/err"; st=$?
check "partial run exits 3 (got $st)" $((st != 3))
xmllint --noout "$tmp/blow.svg" 2>/dev/null; check "partial run: plot written and well-formed" $?
"$BGDRAW" "$tmp/blow.bg" --plot "$tmp/blow.png" 2>/dev/null; st=$?
[ "$st" = 3 ] && [ "$(sig "$tmp/blow.png" 4)" = "211PNG" ]; check "partial run: png written" $?

# refused: two flow sources in series (the index reduction fails): no plot, exit 3
"$BGDRAW" tests/data/twosf.bg --causality relaxed --plot "$tmp/twosf.svg" 2>"$tmp/err"; st=$?
check "refused run exits 3 (got $st)" $((st != 3))
[ ! -e "$tmp/twosf.svg" ]; check "refused run writes no plot" $?
grep -q 'simulation refused' "$tmp/err"; check "refused run says why" $?

# an unknown extension: exit 2 with a message, nothing written
"$BGDRAW" examples/rlc.bg --plot "$tmp/rlc.gif" 2>"$tmp/err"; st=$?
check "unknown plot extension exits 2 (got $st)" $((st != 2))
grep -q 'svg, pdf or png' "$tmp/err"; check "unknown plot extension: message" $?
[ ! -e "$tmp/rlc.gif" ]; check "unknown plot extension: nothing written" $?
# a usage error is found before any work: the diagram asked beside it is not written
"$BGDRAW" examples/rlc.bg -o "$tmp/beside.svg" --plot "$tmp/rlc.gif" 2>/dev/null; st=$?
[ "$st" = 2 ] && [ ! -e "$tmp/beside.svg" ]; check "unknown plot extension: no other output either" $?

# an unwritable file: exit 4, no temporary left behind
"$BGDRAW" examples/rlc.bg --plot "$tmp/no/such/dir/p.svg" 2>"$tmp/err"; st=$?
check "unwritable plot exits 4 (got $st)" $((st != 4))
grep -q 'cannot write' "$tmp/err"; check "unwritable plot: message" $?

finish
