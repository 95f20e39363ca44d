#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Where outputs go (issue 28, "Outputs"; docs/cli.md, "Output files"): two
# outputs on one file are refused before anything is computed (status 2, no
# file written); /dev/stdout into a pipe gets the bytes and with `>> file`
# appends; a reader that closes the pipe early makes status 4 with a message,
# not a death by SIGPIPE.
# Usage: bash tests/outputs_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
M=examples/rlc.bg
cd "$tmp"

same() { # NAME ARGS...: refused with status 2, the message, nothing written
  local name=$1; shift
  rm -f x.pdf m.svg y.svg a.json
  "$BGDRAW" "$root/$M" "$@" >out 2>err; st=$?
  [ $st -eq 2 ] && grep -q "two outputs go to one file" err && ! ls x.pdf m.svg y.svg a.json >/dev/null 2>&1
  cs_=$?; check "$name: refused with status 2 before writing (got $st: $(head -1 err))" $cs_
}
same "-o x.pdf --report x.pdf" -o x.pdf --report x.pdf
same "-o m.svg -M m.svg" -o m.svg -M m.svg
same "--bode y.svg --step ./y.svg" --bode y.svg --step ./y.svg
same "-o a.json -o a.json" -o a.json -o a.json
mkdir -p sub && ln -sf ../y.svg sub/link.svg
same "--plot y.svg --simulate -o sub/link.svg (a link to it)" --simulate --plot y.svg -o sub/link.svg
"$BGDRAW" "$root/$M" -o m.svg -o m.pdf >/dev/null 2>&1; check "two different files are fine" $?

# /dev/stdout: into a pipe, and appended with >>
"$BGDRAW" "$root/$M" -T json -o /dev/stdout | cat >pipe.json
st=${PIPESTATUS[0]}
[ $st -eq 0 ] && head -2 pipe.json | grep -q '"format": "bgdraw-analysis"'
check "-o /dev/stdout into a pipe (got $st)" $?
echo "first line" >app.txt
"$BGDRAW" "$root/$M" -T json -o /dev/stdout >>app.txt; st=$?
[ $st -eq 0 ] && [ "$(head -1 app.txt)" = "first line" ] && grep -q '"format": "bgdraw-analysis"' app.txt
cs_=$?; check "-o /dev/stdout with >> appends (got $st, first line '$(head -1 app.txt)')" $cs_
"$BGDRAW" "$root/$M" -T json -o /dev/fd/1 >>app.txt; st=$?
[ $st -eq 0 ] && [ "$(grep -c '"format": "bgdraw-analysis"' app.txt)" = 2 ]
check "-o /dev/fd/1 appends too (got $st)" $?

# a closed pipe: a model whose equations are larger than a pipe's buffer
{ echo "model chain"; echo "Se U = 1"; for i in $(seq 1 3000); do echo "1 j$i"; echo "I m$i = 1"; echo "R r$i = 1"; done
  echo "bond 1 U -> j1"; b=2
  for i in $(seq 1 3000); do echo "bond $b j$i -> m$i"; echo "bond $((b + 1)) j$i -> r$i"; b=$((b + 2)); done; } >chain.bg
"$BGDRAW" chain.bg --equations text 2>err | head -c 100 >/dev/null
st=${PIPESTATUS[0]}
[ $st -eq 4 ] && grep -q "cannot write to stdout" err
cs_=$?; check "a reader that closes the pipe: status 4 and a message (got $st: $(head -1 err))" $cs_
finish
