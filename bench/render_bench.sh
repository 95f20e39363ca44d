#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Times layout + rendering through the CLI for two generated models of about
# N elements (default 1000): a chain of alternating 0/1 junctions with a C, I
# or R on each, and an RC ladder (bench/gen_ladder.py, N/4 sections: one
# causal path and one flat loop per R-C pair, so `--show all` draws ~N
# polylines). Two tables per model: through the CLI (wall clock, best of 3;
# "check only" runs the same analysis, equations and numeric index as a
# diagram run, so the diagram costs roughly the difference), and in-process
# (bench/render_time.c, compiled against BGDRAW's build directory): the
# analysis, bg_diagram_build (pango, Graphviz layout, scene) and each format.
# Usage: bash bench/render_bench.sh BGDRAW [N]   (use a Release build)
set -eu
BGDRAW=${1:?usage: render_bench.sh PATH_TO_BGDRAW [N]}
N=${2:-1000}
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

chain() {
  echo "model chain \"generated chain of $N elements\""
  echo "Se U = 1"
  local nj=$((N / 2)) i e
  for ((i = 1; i <= nj; i++)); do
    if ((i % 2)); then echo "1 j$i"; else echo "0 j$i"; fi
    case $((i % 3)) in
      0) echo "R r$i = 1" ;;
      1) echo "I m$i = 1" ;;
      2) echo "C c$i = 1" ;;
    esac
  done
  echo "bond U -> j1"
  for ((i = 1; i <= nj; i++)); do
    case $((i % 3)) in 0) e=r$i ;; 1) e=m$i ;; 2) e=c$i ;; esac
    echo "bond j$i -> $e"
    if ((i < nj)); then echo "bond j$i -> j$((i + 1))"; fi
  done
}

best_of_3() { # ARGS... -> seconds (best of 3 runs)
  local best="" t0 t1 t k
  for k in 1 2 3; do
    t0=$(date +%s.%N)
    "$BGDRAW" "$@" >/dev/null
    t1=$(date +%s.%N)
    t=$(echo "$t1 - $t0" | bc)
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc)" = 1 ]; then best=$t; fi
  done
  echo "$best"
}

row() { # LABEL BASE ARGS...
  local label=$1 base=$2; shift 2
  local t; t=$(best_of_3 "$@")
  printf '  %-30s %6.2f s   (diagram %5.2f s)\n' "$label" "$t" "$(echo "$t - $base" | bc)"
}

bench() { # NAME MODEL
  local m=$2 base
  echo "$1: $(grep -c '^bond' "$m") bonds, $(grep -Evc '^(bond|model|param|simulate|plot|#)' "$m") elements and junctions"
  base=$(best_of_3 "$m" --check -q)
  printf '  %-30s %6.2f s\n' "check only (parse, analysis)" "$base"
  row "layout + svg" "$base" "$m" -o "$dir/b.svg"
  row "layout + pdf" "$base" "$m" -o "$dir/b.pdf"
  row "layout + png" "$base" "$m" -o "$dir/b.png"
  row "layout + dot" "$base" "$m" -o "$dir/b.dot"
  row "layout + svg,pdf,png,dot" "$base" "$m" -o "$dir/b.svg" -o "$dir/b.pdf" -o "$dir/b.png" -o "$dir/b.dot"
  row "--show all + svg" "$base" "$m" --show all -o "$dir/b.svg"
  row "--show all + png" "$base" "$m" --show all -o "$dir/b.png"
  ls -l "$dir"/b.* | awk '{print "    " $5 " bytes  " $NF}' | sed "s|$dir/||"
}

# The in-process timer, linked like tests/unit/test_render.c in BGDRAW's build.
build=$(cd "$(dirname "$BGDRAW")" && pwd)
timer=""
if [ -f "$build/CMakeFiles/test_render.dir/link.txt" ]; then
  libs=$(sed -e 's/.* -o test_render *//' "$build/CMakeFiles/test_render.dir/link.txt")
  (cd "$build" && cc -O2 -I"$here/../src" -I"$here/../render" "$here/render_time.c" $libs \
    -o "$dir/render_time") && timer="$dir/render_time"
fi

chain >"$dir/chain.bg"
python3 "$here/gen_ladder.py" $((N / 4)) "$dir/ladder.bg"
for model in chain ladder; do
  bench "$model" "$dir/$model.bg"
  if [ -n "$timer" ]; then
    echo "  in-process:"
    "$timer" "$dir/$model.bg" "$here/../styles"
  fi
done
