#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Linear analysis benchmark (not a test): an RC ladder of N sections (default
# 1000 states) with `linearise` and the last capacitor's voltage as output,
# through bench/linear_bench.c (linearisation + 200-frequency Bode data) and
# through `bgdraw --bode` end to end (400 frequencies, SVG). Release build of
# the engine into build-bench-linear/.
# Usage: bash bench/linear_bench.sh [N]   (from the project root)
set -eu
N=${1:-1000}
cd "$(dirname "$0")/.."
B=build-bench-linear
cmake -S . -B $B -DCMAKE_BUILD_TYPE=Release >/dev/null
nice cmake --build $B -j2 --target bgengine bgdraw >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 bench/gen_ladder.py "$N" "$tmp/ladder.bg"
printf 'output v = C%d.e\nlinearise\n' "$N" >>"$tmp/ladder.bg"
cc -O2 -o "$tmp/linear_bench" bench/linear_bench.c -Isrc $B/libbgengine.a -llapacke \
  -lsundials_cvode -lsundials_ida -lsundials_nvecserial -lsundials_sunmatrixdense \
  -lsundials_sunlinsoldense -lsundials_sunmatrixsparse -lsundials_sunlinsolklu -lm
"$tmp/linear_bench" "$tmp/ladder.bg"
s=$(date +%s.%N)
$B/bgdraw "$tmp/ladder.bg" --bode "$tmp/bode.svg"
e=$(date +%s.%N)
awk -v s="$s" -v e="$e" 'BEGIN { printf "bgdraw --bode (end to end, 400 frequencies, SVG): %.2f s\n", e - s }'
