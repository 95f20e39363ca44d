#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Benchmark (not a test): a doubling sweep over model size, per stage.
# For each shape (bench/gen_models.py: chain, ladder, grid) and each size in
# bonds (FROM, 2·FROM, ... up to TO), runs bench/stage_time.c in a fresh
# process and prints per stage the CPU time, the growth exponent against the
# previous size (log t2/t1 / log n2/n1: 1 is linear, 2 quadratic; n log n
# shows as about 1.1) and the peak resident memory of the run so far.
# Usage: bash bench/sweep.sh BGDRAW_BUILD_DIR [TO] [FROM]
#   defaults TO=4000, FROM=1000 (a short run); TO=100000 for the full sweep
#   (nice it: tens of minutes of CPU with the diagram and report).
#   SHAPES="chain ladder grid" and STAGES="eq,sim,diagram" (add ",report")
#   choose what runs; T_END (default 0.1) is the simulated span.
set -eu
build=$(cd "${1:?usage: sweep.sh BUILD_DIR [TO] [FROM]}" && pwd)
to=${2:-4000}
from=${3:-1000}
here=$(cd "$(dirname "$0")" && pwd)
shapes=${SHAPES:-chain ladder grid}
stages=${STAGES:-eq,sim,diagram}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

libs=$(sed -e 's/.* -o test_render *//' "$build/CMakeFiles/test_render.dir/link.txt")
(cd "$build" && cc -O2 -I"$here/../src" -I"$here/../render" "$here/stage_time.c" $libs \
  -o "$dir/stage_time")

for shape in $shapes; do
  echo "== $shape (stages: $stages)"
  prev=""
  for ((n = from; n <= to; n *= 2)); do
    python3 "$here/gen_models.py" "$shape" "$n" "${T_END:-0.1}" >"$dir/m.bg"
    bonds=$(grep -c '^bond' "$dir/m.bg")
    "$dir/stage_time" "$dir/m.bg" "$here/../styles" "$stages" >"$dir/t.$n" 2>"$dir/err" ||
      { echo "  $shape $n: failed"; sed 's/^/  /' "$dir/err" | head -5; continue; }
    echo "$bonds" >"$dir/b.$n"
    if [ -z "$prev" ]; then
      printf '  %-12s' stage; printf ' %8s' bonds; echo
    fi
    printf '  %-12s %8d bonds\n' "" "$bonds"
    awk -v pb="${prev:+$(cat "$dir/b.$prev")}" -v b="$bonds" -v pf="${prev:+$dir/t.$prev}" '
      BEGIN { if (pf != "") while ((getline l < pf) > 0) { split(l, f); pt[f[1]] = f[2] } }
      { ex = "-"
        if (pb != "" && ($1 in pt) && pt[$1] > 0.002 && $2 > 0.002) ex = sprintf("%.2f", log($2 / pt[$1]) / log(b / pb))
        printf "    %-12s %9.4f s  exp %5s  peak %7.1f MB\n", $1, $2, ex, $3 }' "$dir/t.$n"
    prev=$n
  done
done
