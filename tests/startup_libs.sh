#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Start-up (issue 19): a run that draws nothing loads none of the render
# libraries (Graphviz, cairo, pango) and not the render module; a run that
# draws loads the module once and gives the same diagram; a missing module
# is an error with status 4, not a crash. LAPACK and SUNDIALS (issue 34) are
# opened only by a run that calls them; missing, each is an error with status 4. Checked with the loader's own list
# of the files it maps (LD_DEBUG=files), never with a clock.
# Usage: bash tests/startup_libs.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: startup_libs.sh PATH_TO_BGDRAW}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }

mapped() { # ARGS... -> the shared objects the loader maps, one a line
  LD_DEBUG=files "$BGDRAW" "$@" 2>&1 >/dev/null | sed -n 's/.*file=\([^ ]*\) \[[0-9]*\];  generating link map.*/\1/p'
}

render_libs='libgvc|libcgraph|libcairo|libpango|bgdraw_render'
for args in "--check" "--equations text" "-o $tmp/x.json" "--simulate -o $tmp/x.csv"; do
  # shellcheck disable=SC2086
  libs=$(mapped examples/rlc.bg $args)
  if echo "$libs" | grep -Eq "$render_libs"; then bad "rlc $args maps render libraries: $(echo "$libs" | grep -E "$render_libs" | tr '\n' ' ')"
  else ok; fi
  n=$(echo "$libs" | grep -c .)
  if [ "$n" -le 30 ]; then ok; else bad "rlc $args maps $n shared objects"; fi
done

libs=$(mapped examples/rlc.bg -o "$tmp/a.svg")
if [ "$(echo "$libs" | grep -c 'bgdraw_render')" = 1 ] && echo "$libs" | grep -q libcairo; then ok
else bad "a diagram run does not map the render module once"; fi
if grep -q '<svg' "$tmp/a.svg" && [ "$(grep -c 'stroke' "$tmp/a.svg")" -gt 4 ]; then ok; else bad "no diagram drawn"; fi
# LAPACK is opened on first use (src/base/lapack.h): Debian's liblapacke and
# liblapack are BIND_NOW, 4 000 symbol lookups at every start otherwise
if echo "$libs" | grep -q 'liblapack'; then bad "a diagram run maps LAPACK: $(echo "$libs" | grep lapack | tr '\n' ' ')"
else ok; fi
if mapped examples/rlc.bg --linear text | grep -q 'liblapacke'; then ok; else bad "--linear text does not map liblapacke"; fi
"$BGDRAW" examples/rlc.bg --linear text >"$tmp/lin.txt" 2>&1 && grep -q "eigenvalues\|poles" "$tmp/lin.txt" && ok ||
  bad "--linear text with LAPACK opened on first use: $(head -c 200 "$tmp/lin.txt")"
BGDRAW_LAPACKE=$tmp/none.so "$BGDRAW" examples/rlc.bg --linear text >/dev/null 2>"$tmp/err"
st=$?
if [ $st = 4 ] && grep -q "cannot load LAPACK ($tmp/none.so)" "$tmp/err"; then ok
else bad "LAPACK missing: status $st, $(head -1 "$tmp/err")"; fi
BGDRAW_LAPACKE=$tmp/none.so "$BGDRAW" examples/rlc.bg -o "$tmp/d.svg" 2>/dev/null && ok ||
  bad "a diagram needs LAPACK"
# SUNDIALS likewise (src/simulate/simulate_sundials_int.h): 845 BIND_NOW
# references and nine libraries in the global scope otherwise
if echo "$libs" | grep -q 'libsundials'; then bad "a diagram run maps SUNDIALS: $(echo "$libs" | grep sundials | tr '\n' ' ')"
else ok; fi
if mapped examples/rlc.bg --check | grep -q 'libsundials'; then bad "--check maps SUNDIALS"; else ok; fi
sim=$(mapped examples/rlc.bg --simulate -o "$tmp/s.csv")
for lib in cvode ida nvecserial sunmatrixdense sunlinsoldense sunmatrixsparse sunlinsolklu; do
  if [ "$(echo "$sim" | grep -c "libsundials_$lib\.")" = 1 ]; then ok; else bad "--simulate does not map libsundials_$lib once"; fi
done
# through the table the run gives its full grid of finite numbers (their
# accuracy against exact solutions is tests/sim_accuracy.sh's)
if [ "$(grep -c . "$tmp/s.csv")" -gt 100 ] && ! grep -qi 'nan\|inf' "$tmp/s.csv"; then ok
else bad "--simulate with SUNDIALS opened on first use: $(head -c 200 "$tmp/s.csv")"; fi
for var in CVODE IDA SUNLINSOLKLU; do
  env "BGDRAW_SUNDIALS_$var=$tmp/none.so" "$BGDRAW" examples/rlc.bg --simulate -o "$tmp/m.csv" 2>"$tmp/err"
  st=$?
  if [ $st = 4 ] && grep -q "cannot load SUNDIALS ($tmp/none.so)" "$tmp/err" && [ ! -s "$tmp/m.csv" ]; then ok
  else bad "SUNDIALS $var missing: status $st, $(head -1 "$tmp/err")"; fi
done
BGDRAW_SUNDIALS_CVODE=$tmp/none.so "$BGDRAW" examples/rlc.bg -o "$tmp/e.svg" 2>/dev/null && cmp -s "$tmp/e.svg" "$tmp/a.svg" && ok ||
  bad "a diagram needs SUNDIALS"

# --show alone must be checked by the module (an unknown layer is a usage error)
if "$BGDRAW" examples/rlc.bg --show nonsense -o "$tmp/b.svg" 2>/dev/null; then bad "--show nonsense accepted"
else [ $? = 2 ] && ok || bad "--show nonsense: status not 2"; fi

BGDRAW_RENDER_MODULE=$tmp/none.so "$BGDRAW" examples/rlc.bg -o "$tmp/c.svg" 2>"$tmp/err"
st=$?
if [ $st = 4 ] && grep -q 'cannot load the renderer module' "$tmp/err" && [ ! -e "$tmp/c.svg" ]; then ok
else bad "missing module: status $st, $(head -1 "$tmp/err")"; fi
BGDRAW_RENDER_MODULE=$tmp/none.so "$BGDRAW" examples/rlc.bg --check >/dev/null 2>&1 && ok ||
  bad "--check needs the render module"

# The module is opened with RTLD_LAZY (src/cli/cli_render.c): every engine
# function it calls must be one the executable exports, or a drawing would
# stop half-way at the first call of a missing one.
module=$(dirname "$BGDRAW")/bgdraw_render.so
if [ -f "$module" ] && command -v nm >/dev/null; then
  nm -D --undefined-only "$module" | awk '$2 ~ /^bg_/ {print $2}' | sort -u >"$tmp/needs"
  nm -D --defined-only "$BGDRAW" | awk '$3 ~ /^bg_/ {print $3}' | sort -u >"$tmp/has"
  missing=$(comm -23 "$tmp/needs" "$tmp/has" | tr '\n' ' ')
  if [ -s "$tmp/needs" ] && [ -z "$missing" ]; then ok
  else bad "the render module needs engine functions the executable lacks: '$missing'"; fi
fi

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
