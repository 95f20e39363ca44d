#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The command line in the habits of documentation builds (docs/cli.md):
# pipes (model from stdin, diagram to stdout), GNU option forms, --version,
# options that would be ignored are errors, --show overlays, make depfiles,
# diagnostics (notes, colour only on a terminal, NO_COLOR, JSON), relative
# model path in the report, and e<N>/f<N> names free unless bond N exists.
# Usage: bash tests/cli_habits.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
ROOT=$PWD
M=examples/rlc.bg

# ---- pipes: bgdraw -T svg < m.bg > m.svg is the file bgdraw m.bg -o m.svg writes
"$BGDRAW" "$M" -o "$tmp/ref.svg" 2>/dev/null
"$BGDRAW" -T svg <"$M" >"$tmp/pipe.svg"; st=$?
check "-T svg < model > out: exit 0 (got $st)" $st
cmp -s "$tmp/ref.svg" "$tmp/pipe.svg"; check "stdin + stdout SVG = the file output" $?
"$BGDRAW" - -Tpng <"$M" >"$tmp/pipe.png"
"$BGDRAW" "$M" -o "$tmp/ref.png"
cmp -s "$tmp/ref.png" "$tmp/pipe.png"; check "'-' and -Tpng (attached value): same PNG" $?
"$BGDRAW" "$M" -o - -T json >"$tmp/o.json"
"$BGDRAW" "$M" -o "$tmp/ref.json"
cmp -s "$tmp/ref.json" "$tmp/o.json"; check "-o - -T json writes the analysis to stdout" $?
grep -v '^model' "$M" | "$BGDRAW" -T json | grep -q '"model": *"stdin"'
check "a model from stdin without a model statement is called stdin" $?
printf 'Se U = 1\n1 j\nR R2 = 2\nbond U -> j\nbond j -> R3\n' >"$tmp/bad.bg"
"$BGDRAW" - -T svg <"$tmp/bad.bg" >"$tmp/bad.out" 2>"$tmp/err"; st=$?
check "bad model from stdin exits 1 (got $st)" $((st != 1))
grep -q "^<stdin>:5:11: error: undefined name 'R3' (did you mean 'R2'?)" "$tmp/err"
check "diagnostics name <stdin>" $?
[ ! -s "$tmp/bad.out" ]; check "nothing on stdout after model errors" $?
# tables from stdin resolve against the current directory
mkdir -p "$tmp/tbl"
printf '0, 0\n1, 2\n' >"$tmp/tbl/k.csv"
printf 'Se U = table(t, "k.csv")\n1 j\nR R1 = 1\nC C1 = 1\nbond U -> j\nbond j -> R1\nbond j -> C1\n' \
  >"$tmp/tbl/m.bg"
(cd "$tmp/tbl" && "$BGDRAW" -T json <m.bg >/dev/null 2>"$tmp/err"); st=$?
check "stdin model reads its table from the current directory (got $st)" $st
"$BGDRAW" "$M" --equations text >/dev/full 2>"$tmp/err"; st=$?
check "--equations to a full stdout exits 4 (got $st)" $((st != 4))
"$BGDRAW" "$M" -T svg >/dev/full 2>/dev/null; st=$?
check "-T svg to a full stdout exits 4 (got $st)" $((st != 4))

# ---- GNU option forms
"$BGDRAW" --show=paths --output="$tmp/eq1.svg" "$M" -q
"$BGDRAW" --show paths -o "$tmp/eq2.svg" "$M" -q
cmp -s "$tmp/eq1.svg" "$tmp/eq2.svg"; check "--opt=value equals --opt value" $?
"$BGDRAW" -qv -o"$tmp/b.svg" "$M" 2>"$tmp/err"; st=$?
check "bundled -qv and attached -oFILE (got $st)" $((st != 0))
[ -s "$tmp/b.svg" ] && grep -q "bgdraw: causality" "$tmp/err"; check "-qv: -v took effect" $?
cp "$M" "$tmp/-dash.bg"
(cd "$tmp" && "$BGDRAW" -o d.svg -- -dash.bg); st=$?
check "-- ends the options (model '-dash.bg', got $st)" $st
"$BGDRAW" "$M" --simulat -o "$tmp/x.csv" 2>"$tmp/err"; st=$?
check "unambiguous prefix --simulat accepted (got $st)" $st
"$BGDRAW" "$M" --smulate 2>"$tmp/err"; st=$?
check "unknown option exits 2 (got $st)" $((st != 2))
grep -q "unknown option '--smulate' (did you mean '--simulate'?)" "$tmp/err"; check "did-you-mean kept" $?
"$BGDRAW" "$M" --stlye=print 2>"$tmp/err"
grep -q "unknown option '--stlye' (did you mean '--style'?)" "$tmp/err"; check "hint for --opt=value" $?
"$BGDRAW" "$M" -o 2>"$tmp/err"; st=$?
grep -q -- "-o needs a value" "$tmp/err" && [ $st -eq 2 ]; check "missing value of -o" $?
"$BGDRAW" -V >"$tmp/v"; st=$?
grep -Eq '^bgdraw [0-9]+\.[0-9]+' "$tmp/v" &&
  grep -Eq 'SUNDIALS [0-9]+\.[0-9]+.*Graphviz [0-9]+\.[0-9]+.*cairo [0-9]+\.[0-9]+.*pango [0-9]+\.[0-9]+' "$tmp/v"
check "-V names bgdraw and the library versions" $?
cmp -s "$tmp/v" <("$BGDRAW" --version); check "--version = -V" $?

# ---- options that would be ignored are errors with a hint (exit 2, nothing written)
usage() { # usage NAME PATTERN ARGS...
  local name=$1 pat=$2
  shift 2
  rm -f "$tmp/ig".*
  "$BGDRAW" "$@" 2>"$tmp/err" >"$tmp/out"; local st=$?
  [ $st -eq 2 ] && grep -q -- "$pat" "$tmp/err" && [ ! -s "$tmp/out" ] && ! ls "$tmp"/ig.* >/dev/null 2>&1
  check "$name (exit $st)" $?
}
usage "-T png with -o x.svg" "the extension says svg" "$M" -T png -o "$tmp/ig.svg"
usage "--simulate with no simulation output" "add --plot FILE" "$M" --simulate -o "$tmp/ig.svg"
usage "--check with -o" "--check writes nothing" "$M" --check -o "$tmp/ig.svg"
usage "-o - without -T" "name its format with -T" "$M" -o -
usage "two outputs to stdout" "only one output can go to stdout" "$M" -T svg --equations text
usage "--depfile with stdout only" "add -o FILE" "$M" -T svg -M "$tmp/ig.d"

# ---- --show: overlays add to the default layers, a base layer replaces them
D=strokes,numbers,conflicts,signals,labels
b=examples/hydraulic_bridge.bg
"$BGDRAW" "$b" -q --show paths --highlight path:2 -T dot >"$tmp/s1.dot"
"$BGDRAW" "$b" -q --show $D,paths --highlight path:2 -T dot >"$tmp/s2.dot"
"$BGDRAW" "$b" -q --show +paths --highlight path:2 -T dot >"$tmp/s3.dot"
"$BGDRAW" "$b" -q --show strokes,paths -T svg >"$tmp/s4.svg"
"$BGDRAW" "$b" -q --show $D,paths -T svg >"$tmp/s5.svg"
"$BGDRAW" "$b" -q --show paths -T svg >"$tmp/s6.svg"
cmp -s "$tmp/s5.svg" "$tmp/s6.svg"; check "--show paths = the default layers + paths" $?
cmp -s "$tmp/s1.dot" "$tmp/s2.dot" && cmp -s "$tmp/s1.dot" "$tmp/s3.dot"
check "--show +paths = --show paths = default + paths (with a highlight)" $?
! cmp -s "$tmp/s4.svg" "$tmp/s5.svg"; check "--show strokes,paths replaces the default" $?

# ---- make dependency file
mkdir -p "$tmp/mk/sub dir"
cp "$tmp/tbl/k.csv" "$tmp/mk/sub dir/k.csv"
sed 's/"k.csv"/"sub dir\/k.csv"/' "$tmp/tbl/m.bg" >"$tmp/mk/m.bg"
cp styles/print.style "$tmp/mk/my.style"
(cd "$tmp/mk" && "$BGDRAW" m.bg --style my.style -o m.svg -o m.json -M m.d); st=$?
check "--depfile run (got $st)" $st
head -1 "$tmp/mk/m.d" | grep -qx 'm.svg m.json: m.bg my.style \./sub\\ dir/k.csv'
check "depfile rule: outputs: model style table (blank escaped)" $?
grep -qx 'my.style:' "$tmp/mk/m.d"; check "depfile: empty rule per input (as gcc -MP)" $?
cat >"$tmp/mk/Makefile" <<EOF
m.svg: ; "$BGDRAW" m.bg --style my.style -o m.svg -o m.json -M m.d
-include m.d
EOF
(cd "$tmp/mk" && make -s -q m.svg); st=$?
check "make: m.svg is up to date after the run (got $st)" $st
sleep 1; touch "$tmp/mk/sub dir/k.csv"
(cd "$tmp/mk" && make -s -q m.svg); st=$?
check "make: touching the table CSV makes m.svg out of date (got $st)" $((st != 1))
(cd "$tmp/mk" && "$BGDRAW" m.bg --depfile=d2 -o m.json)
grep -qx 'm.json: m.bg \./sub\\ dir/k.csv' "$tmp/mk/d2"; check "no style dependency without a drawing" $?

# ---- diagnostics: notes, colour, JSON, no consequential errors
printf 'Se U = 1\n1 j\nR R2 = 2\nR R2 = 3\nbond U -> j\nbond j -> R2\n' >"$tmp/dup.bg"
"$BGDRAW" "$tmp/dup.bg" --check 2>"$tmp/err"
grep -A3 "dup.bg:4:3: error: 'R2' already defined at line 3" "$tmp/err" |
  grep -q "dup.bg:3:3: note: 'R2' first defined here"
check "a duplicate name has a note at the first definition" $?
! grep -q $'\033' "$tmp/err"; check "no colour when stderr is not a terminal" $?
if script -qc true /dev/null >/dev/null 2>&1; then
  script -qc "'$BGDRAW' '$tmp/dup.bg' --check" /dev/null >"$tmp/tty" 2>&1
  grep -q $'\033\[1;31merror' "$tmp/tty"; check "colour on a terminal" $?
  NO_COLOR=1 script -qc "'$BGDRAW' '$tmp/dup.bg' --check" /dev/null >"$tmp/tty" 2>&1
  ! grep -q $'\033' "$tmp/tty" && grep -q "error: 'R2' already" "$tmp/tty"
  check "NO_COLOR: no colour on a terminal" $?
fi
"$BGDRAW" "$tmp/dup.bg" --color=always --check 2>&1 | grep -q $'\033\[1;31merror'
check "--color=always" $?
"$BGDRAW" "$tmp/dup.bg" --check --diagnostics-format=json 2>"$tmp/err.json"; st=$?
python3 - "$tmp/err.json" "$tmp/dup.bg" <<'PY'; check "--diagnostics-format=json: one object with its note (exit $st)" $(($? || st != 1))
import json, sys
lines = open(sys.argv[1]).read().splitlines()
d = [json.loads(l) for l in lines]
assert len(d) == 1, d
e = d[0]
assert e["file"] == sys.argv[2] and e["line"] == 4 and e["column"] == 3, e
assert e["severity"] == "error" and e["message"] == "'R2' already defined at line 3", e
n = e["notes"]
assert len(n) == 1 and n[0]["line"] == 3 and n[0]["severity"] == "note", n
PY
"$BGDRAW" "$tmp/bad.bg" --check 2>"$tmp/err"
grep -q "did you mean 'R2'" "$tmp/err" && ! grep -q "'R2' has no bond" "$tmp/err"
check "a misspelled bond end is reported, not the intended element's missing bond" $?

# ---- the report shows the model path relative to the current directory
"$BGDRAW" "$ROOT/$M" --report "$tmp/r.pdf" 2>/dev/null
pdftotext "$tmp/r.pdf" - | grep -q "from $M\$"; check "report: relative model path" $?
! pdftotext "$tmp/r.pdf" - | grep -qF "$ROOT"; check "report: no absolute path" $?
(cd "$tmp" && "$BGDRAW" "$ROOT/$M" --report r2.pdf 2>/dev/null)
pdftotext "$tmp/r2.pdf" - | grep -q "from rlc.bg\$"; check "report: file name outside the cwd" $?

# ---- e<N>/f<N>: ordinary names unless bond N exists
cat >"$tmp/f0.bg" <<'EOF'
param f0 = 1.5, e9 = 1
Se U = f0 * e9
1 f5
R R1 = 1
C C1 = 1
bond U -> f5
bond f5 -> R1
bond f5 -> C1
simulate t_end = 1, dt = 0.5
plot C1.e
EOF
"$BGDRAW" "$tmp/f0.bg" -o "$tmp/f0.csv" 2>"$tmp/err"; st=$?
check "param f0, e9 and junction f5 accepted with 3 bonds (got $st)" $st
awk -F, 'NR == 4 { d = $2 - 1.5 * (1 - exp(-1)); exit !(d < 1e-4 && d > -1e-4) }' "$tmp/f0.csv"
check "param f0 = 1.5 drives the RC: C1.e(1) = 1.5 (1 - e^-1)" $?

# ---- the TF, GY and one-port sign conventions of docs/format.md
printf 'Se U = 10\nTF T = 2\nR R1 = 4\nbond 1 U -> T\nbond 2 T -> R1\n' >"$tmp/tf.bg"
"$BGDRAW" "$tmp/tf.bg" --equations text >"$tmp/tf.txt"
grep -qx 'e2 = 2\*e1' "$tmp/tf.txt" && grep -qx 'f1 = 2\*f2' "$tmp/tf.txt" && grep -qx 'f2 = 0.25\*e2' "$tmp/tf.txt"
check "TF: e2 = n e1, f1 = n f2 (format.md worked example)" $?
printf 'Se U = 10\nGY G = 2\nR R1 = 4\nbond 1 U -> G\nbond 2 G -> R1\n' >"$tmp/gy.bg"
"$BGDRAW" "$tmp/gy.bg" --equations text >"$tmp/gy.txt"
grep -qx 'f2 = 0.5\*e1' "$tmp/gy.txt" && grep -qx 'f1 = 0.5\*e2' "$tmp/gy.txt" && grep -qx 'e2 = 4\*f2' "$tmp/gy.txt"
check "GY: e1 = r f2, e2 = r f1 (format.md worked example)" $?
printf 'Se U = 1\n1 j\nR R1 = 2\nC C1 = 1\nbond U -> j\nbond R1 -> j\nbond j -> C1\n' >"$tmp/out.bg"
"$BGDRAW" "$tmp/out.bg" --equations text | grep -qx 'f2 = -0.5\*e2'
check "a value-form R whose bond points out of it: e = -R f" $?
# A law is written for the element's own variables (power into it): with the bond
# pointing out, `e = 2*f` and `f = e/2` are the same resistor as `R R1 = 2`.
for law in '= 2' ': e = 2*f' ': f = e/2'; do
  printf 'Se U = 1\n1 j\nR R1 %s\nC C1 = 1\nbond U -> j\nbond R1 -> j\nbond j -> C1\nsimulate t_end = 1, dt = 1\n' \
    "$law" >"$tmp/outlaw.bg"
  "$BGDRAW" "$tmp/outlaw.bg" -q -o "$tmp/outlaw.csv" -o "$tmp/outlaw.json"
  awk -F, 'NR == 3 { d = $2 - (1 - exp(-0.5)); exit !(d < 1e-5 && d > -1e-5) }' "$tmp/outlaw.csv" &&
    grep -q '"kind": "time_constant", "path": [0-9]*, "value": 2}' "$tmp/outlaw.json"
  check "outward R1 $law: C1.e(1) = 1 - e^-0.5 and the path estimate RC = 2" $?
done

# ---- habits of the ecosystem (issue 32): dot's -K, case-blind extensions,
# the diagram on standard output when it is not a terminal, hints for short options
usage "-t suggests -T" "did you mean '-T'" "$M" -t svg
usage "-c lists the long options beginning with c" "did you mean one of --causality, --color, --collapse, --collect, --check" "$M" -c
usage "-T svg:cairo is a sentence" "one renderer for each format.*write -T svg" "$M" -T svg:cairo
"$BGDRAW" "$M" -K neato -o "$tmp/k.svg" && "$BGDRAW" "$M" --layout neato -o "$tmp/l.svg" &&
  cmp -s "$tmp/k.svg" "$tmp/l.svg" && ! cmp -s "$tmp/k.svg" <("$BGDRAW" "$M" -T svg)
check "-K neato is --layout neato" $?
"$BGDRAW" "$M" -o "$tmp/upper.SVG" && "$BGDRAW" "$M" -o "$tmp/lower.svg" && cmp -s "$tmp/upper.SVG" "$tmp/lower.svg"
check ".SVG is an SVG" $?
mkdir -p "$tmp/habits"
(cd "$tmp/habits" && "$BGDRAW" "$root/$M" >redirected.svg && [ ! -e out ] &&
  cmp -s redirected.svg ../lower.svg)
check "bgdraw m.bg > m.svg: the diagram on standard output, no out/ folder" $?
(cd "$tmp/habits" && "$BGDRAW" "$root/$M" -M dep.d >/dev/null && [ -s out/rlc.svg ])
check "with -M the default diagram stays a file (the depfile names it)" $?
# docs/cli.md's diagnostic sample is what bgdraw prints for the file it names
awk '/^    tests\/bad\/duplicate_name.bg:5:3/{on=1} on && /^$/{exit} on{print substr($0, 5)}' \
  docs/cli.md >"$tmp/sample.txt"
"$BGDRAW" tests/bad/duplicate_name.bg --check --color=never 2>"$tmp/sample.got" >/dev/null
[ -s "$tmp/sample.txt" ] && cmp -s "$tmp/sample.txt" "$tmp/sample.got"
check "docs/cli.md's diagnostic sample = the program's output" $?
# ---- named warnings: on by default, -Wno-NAME, -Werror
printf 'param a = 1, unused = 3\nSe U = a\n1 j\nC C1 = 0\nbond U -> j\nbond j -> C1\n' >"$tmp/w.bg"
"$BGDRAW" "$tmp/w.bg" --check >/dev/null 2>"$tmp/w.err"; st=$?
[ $st -eq 0 ] && grep -q "1:14: warning: param 'unused' is never used \[-Wunused-param\]" "$tmp/w.err" &&
  grep -q "4:3: warning: the capacitance of C 'C1' is 0 .*\[-Wdegenerate-value\]" "$tmp/w.err"
check "warnings: unused param and a zero capacitance, status 0 (got $st)" $?
"$BGDRAW" "$tmp/w.bg" --check -Wno-unused-param -Werror >/dev/null 2>"$tmp/w.err"; st=$?
[ $st -eq 1 ] && ! grep -q unused "$tmp/w.err" && grep -q "error: .*\[-Werror=degenerate-value\]" "$tmp/w.err"
check "-Wno-unused-param -Werror: the other warning an error, status 1 (got $st)" $?
usage "-W with an unknown name" "unknown warning '-Wfoo'" "$M" -Wfoo
printf 'submodel S\n  port p\n  R r = 1\n  bond p -> r\nend\n' >"$tmp/only_sub.bg" # a valid submodel: an unused one is checked
"$BGDRAW" "$tmp/only_sub.bg" --check >/dev/null 2>"$tmp/w.err"
grep -q "defines 1 submodel but no model uses them.*\[-Wempty-model\]" "$tmp/w.err"
check "a file of submodels only: -Wempty-model" $?
printf 'param Ra = 2\nSe U = 1\n1 j\nR Ra = Ra\nbond U -> j\nbond j -> Ra\n' >"$tmp/shadow.bg"
"$BGDRAW" "$tmp/shadow.bg" --check >/dev/null 2>"$tmp/w.err"; st=$?
[ $st -eq 1 ] && [ "$(grep -c 'error:' "$tmp/w.err")" = 1 ] && grep -q "the element 'Ra' has the name of the param 'Ra'" "$tmp/w.err"
cs_=$?; check "an element named like a param: one clear error (got $st, $(grep -c 'error:' "$tmp/w.err") errors)" $cs_
finish
