#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Exports that compile whatever the names (issue 28): every example gets
# params named after each keyword of C (C11, C23 and the object-like macros
# of the headers the export includes), Python (keyword.kwlist, read from
# Python), Octave (iskeyword(), read from Octave) and Modelica (keywords,
# predefined types, built-in operators); each is exported to C, Python,
# Octave and Modelica, and
# - the C compiles with gcc -Wall -Werror, in C11 and in gcc's default GNU mode;
# - the Python module imports and evaluates its right-hand side or residual;
# - the Octave function runs and evaluates m.f at the initial point;
# - the Modelica file passes the structural check (tests/export/
#   check_modelica.py) and declares no reserved name;
# - the renamed params keep their names in a table (C param_names, Python
#   PARAM_NAMES, Octave m.param_names, Modelica descriptions).
# A model named "é-1 x" (from its file name) gives a Python module whose
# docstring imports it with importlib, and which compiles.
# Usage: bash tests/export_keywords.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
PY=/usr/bin/python3 # Debian's, with numpy and scipy (tools/deps.sh)
C_WORDS="auto break case char const continue default do double else enum extern float for goto if
inline int long register restrict return short signed sizeof static struct switch typedef union
unsigned void volatile while alignas alignof bool constexpr false nullptr static_assert
thread_local true typeof NAN INFINITY HUGE_VAL FP_NAN FP_ZERO M_PI M_E NULL EXIT_SUCCESS RAND_MAX
errno unix linux"
MO_WORDS="algorithm and annotation block break class connect connector constant constrainedby der
discrete each else elseif elsewhen encapsulated end enumeration equation expandable extends
external false final flow for function if import impure in initial inner input loop model not
operator or outer output package parameter partial protected public pure record redeclare
replaceable return stream then true type when while within time Real Integer Boolean String sin
cos exp log sqrt abs min max pre edge sample"
PY_WORDS=$($PY -c "import keyword; print(' '.join(keyword.kwlist))")
OCT_WORDS=$(octave-cli --no-gui --norc --quiet --eval "k = iskeyword(); printf('%s ', k{:})" 2>/dev/null)
words=$(echo $C_WORDS $MO_WORDS $PY_WORDS $OCT_WORDS | tr ' ' '\n' | sort -u)
cd "$tmp"
# the names bgdraw itself accepts as params (t is time)
ok_words=""
for w in $words; do
  printf 'model p\nparam %s = 1\nSe U = 1\nR R1 = 2\nbond U -> R1\n' "$w" > probe.bg
  "$BGDRAW" probe.bg --check > /dev/null 2>&1 && ok_words="$ok_words $w"
done
n=$(echo $ok_words | wc -w)
check "at least 150 reserved names are valid bgdraw params (got $n)" $((n < 150))
params=$(i=0; for w in $ok_words; do i=$((i + 1)); printf '%s%s = %d.5' "$([ $i -gt 1 ] && echo ', ')" "$w" "$i"; done)

for f in "$root"/examples/*.bg; do
  b=ex_$(basename "$f" .bg)
  { cat "$f"; printf '\nparam %s\n' "$params"; } > "$b.bg"
  "$BGDRAW" "$b.bg" -q -o "$b.c" -o "$b.py" -o "$b.m" -o "$b.mo" 2>err; st=$?
  if [ $st -ne 0 ]; then # a model whose equations cannot be exported says why
    grep -q "error" err; cs_=$?; check "$b: an export refused says why ($(head -c 150 err))" $cs_
    continue
  fi
  gcc -std=c11 -Wall -Werror -c "$b.c" -o c11.o 2>cerr && gcc -Wall -Werror -c "$b.c" -o gnu.o 2>>cerr
  cs_=$?; check "$b: the C export compiles in C11 and GNU mode ($(grep -m1 error cerr))" $cs_
  grep -q '"for"' "$b.c" && grep -q "double for_;" "$b.h"
  check "$b: C keeps the original names (param_names) beside the fields (for_)" $?
  $PY - "$b" > pyout 2>&1 <<'P'
import importlib, math, sys
sys.path.insert(0, ".")
m = importlib.import_module(sys.argv[1])
assert m.PARAM_NAMES["for_"] == "for" and m.PARAM_NAMES["class_"] == "class"
p = dict(m.PARAMS, for_=2.0, lambda_=3.0)  # the renamed keys work as keyword arguments
y = m.initial(p)
r = m.rhs(0.0, y, p) if m.IS_ODE else m.residual(0.0, y, 0 * y, p)
assert all(math.isfinite(float(x)) for x in r)
P
  cs_=$?; check "$b: the Python module imports and evaluates ($(tail -1 pyout))" $cs_
  octave-cli --no-gui --norc --quiet --eval "
    m = $b(); y0 = m.initial(m.params, m.t0); r = m.f(m.t0, y0, m.params);
    assert(all(isfinite(r))); assert(m.params.for_ == m.params.for_);
    k = find(strcmp(m.param_names(:, 1), 'end_')); assert(strcmp(m.param_names{k, 2}, 'end'));" > oout 2>&1
  cs_=$?; check "$b: the Octave function runs ($(grep -m1 -i error oout))" $cs_
  $PY "$root/tests/export/check_modelica.py" "$b.mo" > mout 2>&1; st=$?
  check "$b: the Modelica file passes the structural check ($(head -c 150 mout))" $st
  $PY - "$b.mo" $MO_WORDS <<'P'; check "$b: Modelica declares no reserved name; renamed ones keep theirs" $?
import re, sys
text = open(sys.argv[1]).read()
reserved = set(sys.argv[2:])
declared = re.findall(r"^  (?:parameter )?Real (\w+)", text, re.M)
bad = [d for d in declared if d in reserved]
ok = not bad and 'parameter Real Real_ = ' in text and '"bgdraw param Real"' in text
sys.exit(0 if ok else 1)
P
done

# a model named after its file, not a module name
printf 'param lambda = 1\nSe U = 1\nR R1 = lambda\nbond U -> R1\n' > "é-1 x.bg"
"$BGDRAW" "é-1 x.bg" -q -o odd.py; check "é-1 x: Python export exits 0" $?
grep -q '^    model = importlib.import_module("é-1 x")  # this file' odd.py
check "é-1 x: the docstring imports it with importlib" $?
$PY -m py_compile odd.py; check "é-1 x: the module compiles" $?
finish
