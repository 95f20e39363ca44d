#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Multiport fields end to end (docs/format.md, "Multiport fields"; docs/drawing.md):
# the --check summary reports each field's port causalities (mixed causality
# said); the diagram draws a field as one node "C : K" with its ports' names
# at their bonds (SVG and DOT), never one node per port; every output of the
# reference models is written, twice byte for byte the same.
# Usage: bash tests/fields_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
d=tests/data/fields

"$BGDRAW" $d/transducer.bg --check >"$tmp/check" 2>&1
grep -qx "field K (C, 2 ports): K.el integral, K.mech integral" "$tmp/check"
cs_=$?; check "transducer --check field line (got: $(grep field "$tmp/check"))" $cs_
"$BGDRAW" $d/dependent.bg --check >"$tmp/check" 2>&1
grep -qx "field K (C, 2 ports): K.1 integral, K.2 derivative (mixed causality)" "$tmp/check"
cs_=$?; check "dependent --check mixed causality (got: $(grep field "$tmp/check"))" $cs_
"$BGDRAW" $d/implicit.bg --check >"$tmp/check" 2>&1
grep -qx "field Rf (R, 2 ports): Rf.1 conductance, Rf.2 conductance" "$tmp/check"
cs_=$?; check "implicit --check R field (got: $(grep field "$tmp/check"))" $cs_

"$BGDRAW" $d/transducer.bg -o "$tmp/t.svg" -o "$tmp/t.dot" -o "$tmp/t.pdf" -o "$tmp/t.png"
check "transducer diagrams" $?
# one node for the field, drawn by its first port; the second port has no node
[ "$(grep -c '<title>C K.el:' "$tmp/t.svg")" -eq 1 ] && ! grep -q '<title>C K.mech:' "$tmp/t.svg"
check "SVG: one node for field K" $?
grep -q '>C : K<' "$tmp/t.svg" || grep -q 'C : K' "$tmp/t.svg"
check "SVG: the field's label C : K" $?
[ "$(grep -c 'class="port"' "$tmp/t.svg")" -eq 2 ]
check "SVG: two port labels" $?
grep -q '^  "K" \[label="C : K"' "$tmp/t.dot" && ! grep -q '"K.el" \[' "$tmp/t.dot"
check "DOT: node K" $?
grep -q '"je" -> "K" \[label="3".*headlabel="el"' "$tmp/t.dot" &&
  grep -q '"jm" -> "K" \[label="4".*headlabel="mech"' "$tmp/t.dot"
check "DOT: bonds 3 and 4 at ports el and mech" $?

# the ports' laws in the JSON: the energy's gradient, simplified
"$BGDRAW" $d/transducer.bg -o "$tmp/t.json"
grep -q '"element": "K.el", "bond": 3, "causality": "integral", "law": "K.el.q\*K.mech.q/(eps\*A)", "law_form": "e"' "$tmp/t.json" &&
  grep -q '"law": "0.5\*K.el.q^2/(eps\*A)"' "$tmp/t.json"
check "JSON: the gradient's components e_el = q x/(eps A), e_mech = q^2/(2 eps A)" $?

for m in transducer reaction dependent implicit transducer_sub; do
  for k in 1 2; do
    "$BGDRAW" $d/$m.bg -q -o "$tmp/$m.$k.svg" -o "$tmp/$m.$k.json" -o "$tmp/$m.$k.csv" \
      --report "$tmp/$m.$k.pdf" 2>"$tmp/err" >/dev/null
    cs_=$?; check "$m outputs (run $k): $(head -c 300 "$tmp/err")" $cs_
  done
  cmp -s "$tmp/$m.1.svg" "$tmp/$m.2.svg" && cmp -s "$tmp/$m.1.json" "$tmp/$m.2.json" &&
    cmp -s "$tmp/$m.1.csv" "$tmp/$m.2.csv"
  check "$m: reruns byte-identical" $?
done
pdftotext "$tmp/transducer.1.pdf" - 2>/dev/null | grep -q "C field K: 2 ports"
check "report: the Multiport fields section" $?
pdftotext "$tmp/dependent.1.pdf" - 2>/dev/null | grep -q "C field K: 2 ports, mixed causality"
check "report: mixed causality" $?
# --collapse and fields are not combined yet: a clean refusal, no output
"$BGDRAW" $d/transducer_sub.bg --collapse T1 -o "$tmp/coll.svg" 2>"$tmp/err"
[ $? -ne 0 ] && [ ! -e "$tmp/coll.svg" ] && grep -q "cannot draw a model with multiport fields" "$tmp/err"
check "--collapse with a field refused" $?
finish
