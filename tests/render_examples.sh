#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Every examples/*.bg renders to SVG, PDF, PNG and DOT under every style
# through the bgdraw CLI; the SVG is well-formed XML (xmllint); a second run
# gives byte-identical files; the DOT output agrees with the analysis JSON
# (one stroke per causal bond, one conflict mark per conflict, one entry per
# causal path and topological loop). The scene itself is counted item by
# item in tests/unit/test_render.c. Usage: bash tests/render_examples.sh BGDRAW
set -u
BGDRAW=${1:?usage: render_examples.sh PATH_TO_BGDRAW}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail=0

# The CLI gains diagram output in its own step: until then there is nothing to test.
if ! "$BGDRAW" examples/rlc.bg -o "$out/probe.svg" >/dev/null 2>"$out/probe.err"; then
  if grep -q "not implemented" "$out/probe.err"; then
    echo "SKIP: bgdraw cannot write diagrams yet"
    exit 0
  fi
fi

render() { # MODEL STYLE SHOW TAG
  local n; n=$(basename "$1" .bg)
  "$BGDRAW" "$1" --style "$2" --show "$3" -o "$out/$n.$2.$4.svg" -o "$out/$n.$2.$4.pdf" \
    -o "$out/$n.$2.$4.png" -o "$out/$n.$2.$4.dot" 2>"$out/err"
}

# DOT against the analysis JSON: strokes, conflicts, paths, loops.
counts() { # MODEL DOT
  command -v python3 >/dev/null || return 0
  "$BGDRAW" "$1" -o "$out/counts.json" 2>/dev/null || { echo "FAIL: $1: no JSON"; return 1; }
  local want got
  want=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1]))
print(sum(b["stroke"] != "none" for b in d["bonds"]), len(d["conflicts"]),
      len(d["causal_paths"]), len(d["topological_loops"]))' "$out/counts.json")
  got="$(grep -c 'bg_stroke=\(head\|tail\)' "$2") $(grep -c 'bg_conflict="' "$2") \
$(grep -c '^  bg_path[0-9]*=' "$2") $(grep -c '^  bg_loop[0-9]*=' "$2")"
  [ "$want" = "$got" ] || { echo "FAIL: $1: DOT has strokes/conflicts/paths/loops $got, JSON $want"; return 1; }
}

for f in examples/*.bg; do
  n=$(basename "$f" .bg)
  for style in default print slides; do
    for show in all strokes,numbers,conflicts,signals,labels; do
      tag=$([ "$show" = all ] && echo all || echo dflt)
      for run in 1 2; do
        if ! render "$f" "$style" "$show" "$tag$run"; then
          echo "FAIL: $f --style $style --show $show: exit $?"; cat "$out/err"; fail=1; continue 2
        fi
      done
      for ext in svg pdf png dot; do
        a="$out/$n.$style.${tag}1.$ext" b="$out/$n.$style.${tag}2.$ext"
        if [ ! -s "$a" ]; then echo "FAIL: $a is empty or missing"; fail=1; continue; fi
        cmp -s "$a" "$b" || { echo "FAIL: $f ($style, $show) .$ext differs between runs"; fail=1; }
      done
      xmllint --noout "$out/$n.$style.${tag}1.svg" || { echo "FAIL: $f ($style): SVG not well-formed"; fail=1; }
      head -c 8 "$out/$n.$style.${tag}1.png" | od -An -c | grep -q "P   N   G" ||
        { echo "FAIL: $f ($style): not a PNG"; fail=1; }
      head -c 5 "$out/$n.$style.${tag}1.pdf" | grep -q "%PDF-" || { echo "FAIL: $f ($style): not a PDF"; fail=1; }
      grep -q "^digraph" "$out/$n.$style.${tag}1.dot" || { echo "FAIL: $f ($style): not DOT"; fail=1; }
    done
  done
  counts "$f" "$out/$n.default.all1.dot" || fail=1
done

# Errors: an unknown style is a usage-level diagnostic, an unwritable output exits 4.
if "$BGDRAW" examples/rlc.bg --style nosuchstyle -o "$out/x.svg" 2>/dev/null; then
  echo "FAIL: unknown style accepted"; fail=1
fi
"$BGDRAW" examples/rlc.bg -o /nonexistent-dir/x.svg 2>/dev/null
rc=$?
[ $rc -eq 4 ] || { echo "FAIL: unwritable output: exit $rc, expected 4"; fail=1; }

[ $fail -eq 0 ] && echo "render_examples: all examples render identically in every format and style"
exit $fail
