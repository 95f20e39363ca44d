#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# --report FILE.pdf end to end (docs/report.md): every example gives a
# report whose text (pdftotext) has every section title and whose page
# count is sensible; the key numbers are the analysis' own (read from the
# JSON of the same run): bond_loop's causal loop gain, loop_class1's index 2
# and its index reduction, a refusal that remains, hydraulic_bridge's conflicts
# under --causality relaxed; reruns are byte-identical; an unwritable path
# exits 4 and leaves no file; --report alone writes no default diagram and
# exits 0 for a refused simulation; a large model's diagram is tiled.
# Usage: bash tests/report_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"

for tool in pdftotext pdfinfo python3; do
  command -v $tool >/dev/null || { echo "SKIP: $tool not installed"; exit 0; }
done
pages() { pdfinfo "$1" 2>/dev/null | awk '/^Pages:/ { print $2 }'; }
text() { pdftotext -layout "$1" - 2>/dev/null | tr -s ' '; }

sections=("Contents" "Summary" "2 Diagram" "3 Highlighted paths, loops and conflicts"
  "4 Causality trace" "5 Paths, loops and conflicts" "6 Model form and index" "7 Equations"
  "8 Time constants and frequencies" "9 Simulation")

# ---------------------------------------------------------------- every example
for f in examples/*.bg; do
  n=$(basename "$f" .bg)
  "$BGDRAW" "$f" --report "$tmp/$n.pdf" 2>"$tmp/$n.err"; st=$?
  # 3 only when the solver failed (results partial); a refusal is explained in the report
  ok=$((st != 0))
  [ $st -eq 3 ] && grep -q "simulation failed" "$tmp/$n.err" && ok=0
  check "$n: exit status $st ($(head -c 200 "$tmp/$n.err"))" $ok
  [ -s "$tmp/$n.pdf" ] || { check "$n: no report written" 1; continue; }
  text "$tmp/$n.pdf" >"$tmp/$n.txt"
  for s in "${sections[@]}"; do
    grep -qF "$s" "$tmp/$n.txt"; check "$n: section '$s'" $?
  done
  p=$(pages "$tmp/$n.pdf")
  [ "${p:-0}" -ge 4 ] && [ "${p:-0}" -le 30 ]; check "$n: $p pages (4 to 30)" $?
  # the summary's numbers are the analysis': states and form
  "$BGDRAW" "$f" -o "$tmp/$n.json" 2>/dev/null
  want=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1]))
print("States %d:" % len(d["states"]), "Form " + d["form"])' "$tmp/$n.json")
  grep -qF "${want% Form*}" "$tmp/$n.txt"; check "$n: summary '${want% Form*}'" $?
  grep -qF "Form ${want#*Form }" "$tmp/$n.txt"; check "$n: summary 'Form ${want#*Form }'" $?
  grep -q "^Numeric index" "$tmp/$n.txt"; check "$n: numeric index line" $?
done

# ---------------------------------------------------------------- key numbers
# bond_loop: causal loop 1 through bonds 1-4 with gain n = 2, class 4
row=$(python3 -c 'import json,sys; l=json.load(open(sys.argv[1]))["causal_loops"][0]
print(" %d %s %s %g %d" % (l["id"], ", ".join(map(str, l["bonds"])), l["gain"], l["gain_value"], l["class"]))' \
  "$tmp/bond_loop.json")
[ "$row" = " 1 1, 2, 3, 4 n 2 4" ]; check "bond_loop JSON loop row (got '$row')" $?
grep -qF "$row" "$tmp/bond_loop.txt"; check "bond_loop: causal loop row '$row' in the report" $?
grep -q "Index-1 DAE with 2 states: one causal loop with a gain other than +1" "$tmp/bond_loop.txt"
check "bond_loop: verdict" $?
grep -q "Rosenberg–Andry condition" "$tmp/bond_loop.txt"; check "bond_loop: Rosenberg-Andry line" $?

# loop_class1: numeric index 2, the simulation refused with the analysis' reason
idx=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["index"]["numeric"])' "$tmp/loop_class1.json")
[ "$idx" = 2 ]; check "loop_class1: JSON numeric index 2 (got $idx)" $?
grep -q "^Numeric index $idx (A of full rank after 2 reduction steps" "$tmp/loop_class1.txt"
check "loop_class1: numeric index $idx in the summary" $?
tr '\n' ' ' <"$tmp/loop_class1.txt" | tr -s ' ' | grep -q "Index-2 DAE, reduced to index 1 by differentiating 2 constraints (Pantelides, dummy derivatives)"
check "loop_class1: verdict names the index reduction" $?
tr '\n' ' ' <"$tmp/loop_class1.txt" | tr -s ' ' | grep -q "Index reduction: index reduced (Pantelides, dummy derivatives): 2 equations differentiated"
check "loop_class1: the index reduction in section 6" $?
tr '\n' ' ' <"$tmp/loop_class1.txt" | tr -s ' ' | grep -q "Lost its state: C2 (a dependent store already)"
check "loop_class1: the store that lost its state in section 6" $?
# a refusal that remains (the reduction fails) is explained in the report
"$BGDRAW" tests/data/twosf.bg --causality relaxed --report "$tmp/tw.pdf" --simulate 2>/dev/null; st=$?
check "twosf --report --simulate exits 3 (got $st)" $((st != 3))
[ -s "$tmp/tw.pdf" ]; check "twosf --report --simulate still writes the report" $?
text "$tmp/tw.pdf" | tr '\n' ' ' | tr -s ' ' >"$tmp/tw.txt"
grep -q "Simulation refused (no solver was called)" "$tmp/tw.txt" && grep -q "Index reduction: index reduction failed: the equations are structurally singular" "$tmp/tw.txt"
check "twosf: the refusal and the failed reduction in the report" $?

# hydraulic_bridge, relaxed (Figure 4.25): type 2 of degree 1 at ja, type 1 at n4
"$BGDRAW" examples/hydraulic_bridge.bg --causality relaxed -o "$tmp/hbr.json" --report "$tmp/hbr.pdf" 2>/dev/null
check "hydraulic_bridge relaxed: exit status" $?
text "$tmp/hbr.pdf" >"$tmp/hbr.txt"
rows=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1]))
for i, c in enumerate(d["conflicts"]):
    print(" %d %s %d %s %s" % (i + 1, c["node"], c["type"], c["degree"] if c["type"] == 2 else "–",
                              ", ".join(map(str, c["bonds"]))))' "$tmp/hbr.json")
[ "$(echo "$rows" | wc -l)" = 2 ]; check "hydraulic_bridge relaxed: two conflicts in the JSON" $?
while read -r r; do
  grep -qF " $r" "$tmp/hbr.txt"; check "hydraulic_bridge relaxed: conflict row ' $r'" $?
done <<<"$rows"
grep -q "Index-1 DAE with 1 state: two causal conflicts" "$tmp/hbr.txt"; check "hydraulic_bridge relaxed: verdict" $?
grep -q "Conflict 1 at ja" "$tmp/hbr.txt"; check "hydraulic_bridge relaxed: highlighted conflict" $?

# rlc: an explicit ODE simulated, plots and statistics
grep -q "Explicit ODE of order 2; simulated to t = 0.002 s with cvode" "$tmp/rlc.txt"; check "rlc: verdict" $?
grep -q "^ *Plots" "$tmp/rlc.txt" && grep -q "^ *Steps [0-9]" "$tmp/rlc.txt"; check "rlc: plots and statistics" $?

# ---------------------------------------------------------------- determinism, outlines
for n in bond_loop rlc; do
  "$BGDRAW" "examples/$n.bg" --report "$tmp/$n.again.pdf" 2>/dev/null
  cmp -s "$tmp/$n.pdf" "$tmp/$n.again.pdf"; check "$n: rerun byte-identical" $?
done
grep -aq "/Outlines" "$tmp/bond_loop.pdf"; check "bond_loop: PDF outlines" $?
grep -aq "CreationDate (20000101000000Z)" "$tmp/bond_loop.pdf"; check "bond_loop: fixed creation date" $?
grep -q "page 1 of $(pages "$tmp/bond_loop.pdf")" "$tmp/bond_loop.txt"; check "bond_loop: page numbers" $?

# ---------------------------------------------------------------- errors
"$BGDRAW" examples/rlc.bg --report /nonexistent-dir/r.pdf 2>"$tmp/err"; st=$?
check "unwritable path exits 4 (got $st)" $((st != 4))
grep -q "cannot write '/nonexistent-dir/r.pdf'" "$tmp/err"; check "unwritable path: message" $?
touch "$tmp/file"
"$BGDRAW" examples/rlc.bg --report "$tmp/file/r.pdf" 2>/dev/null; st=$?
check "path under a file exits 4 (got $st)" $((st != 4))
mkdir "$tmp/adir.pdf"
"$BGDRAW" examples/rlc.bg --report "$tmp/adir.pdf" 2>/dev/null; st=$?
check "a directory as the report path exits 4 (got $st)" $((st != 4))
[ -z "$(ls -A "$tmp" | grep '^\.')" ] && [ -z "$(ls "$tmp/adir.pdf")" ]; check "no temporary file left" $?

"$BGDRAW" examples/rlc.bg --report "$tmp/r.svg" 2>/dev/null; st=$?
check "--report x.svg is a usage error (got $st)" $((st != 2))
[ ! -e "$tmp/r.svg" ]; check "--report x.svg writes nothing" $?

# --report alone: no default out/<model>.svg; a refused simulation exits 0
mkdir "$tmp/cwd"
(cd "$tmp/cwd" && "$BGDRAW" "$root/examples/loop_class1.bg" --report r.pdf 2>/dev/null); st=$?
check "loop_class1 --report alone exits 0 (got $st)" $st
[ -s "$tmp/cwd/r.pdf" ] && [ ! -e "$tmp/cwd/out" ]; check "--report alone writes only the report" $?

# ---------------------------------------------------------------- a large model: tiles
{
  echo 'model chain "generated chain"'
  echo "Se U = 1"
  for ((i = 1; i <= 40; i++)); do
    if ((i % 2)); then echo "1 j$i"; else echo "0 j$i"; fi
    case $((i % 3)) in 0) echo "R r$i = 1" ;; 1) echo "I m$i = 1" ;; 2) echo "C c$i = 1" ;; esac
  done
  echo "bond U -> j1"
  for ((i = 1; i <= 40; i++)); do
    case $((i % 3)) in 0) e=r$i ;; 1) e=m$i ;; 2) e=c$i ;; esac
    echo "bond j$i -> $e"
    ((i < 40)) && echo "bond j$i -> j$((i + 1))"
  done
} >"$tmp/chain.bg"
"$BGDRAW" "$tmp/chain.bg" --report "$tmp/chain.pdf" 2>/dev/null; check "chain: exit status" $?
text "$tmp/chain.pdf" >"$tmp/chain.txt"
grep -q "Diagram, part 1 of [0-9]* (row 1, column 1), at [0-9]* %" "$tmp/chain.txt"; check "chain: diagram in tiles" $?
scale=$(grep -o "Diagram, part 1 of [0-9]* (row 1, column 1), at [0-9]* %" "$tmp/chain.txt" | head -1 | sed 's/.* at \([0-9]*\) %/\1/')
[ "${scale:-0}" -ge 70 ]; check "chain: tiles at a readable scale (got ${scale:-?} %)" $?
grep -q "more not drawn here" "$tmp/chain.txt"; check "chain: highlights capped with the rest counted" $?

# a diagram that needs a page of its own but no more: one page, no parts, no map
"$BGDRAW" examples/hydraulic_bridge.bg -q --report "$tmp/hb.pdf"; check "bridge: exit status" $?
text "$tmp/hb.pdf" | tr -s ' \n' ' ' >"$tmp/hb.txt"
grep -q "so it follows on a page of its own at [0-9]* %\. .*Diagram, at [0-9]* %" "$tmp/hb.txt"
check "bridge: the diagram on a page of its own" $?
! grep -q "part 1 of 1\|in 1 parts\|on 1 pages\|where each part lies" "$tmp/hb.txt"
check "bridge: not called one part of one" $?

echo "report_cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
