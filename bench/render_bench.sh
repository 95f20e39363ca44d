#!/bin/bash
# Times layout + rendering of a generated model of about N elements (default
# 1000): a chain of alternating 0/1 junctions with a C, I or R on each.
# Usage: bash bench/render_bench.sh BGDRAW [N]
set -eu
BGDRAW=${1:?usage: render_bench.sh PATH_TO_BGDRAW [N]}
N=${2:-1000}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
model="$dir/bench.bg"
{
  echo "model bench \"generated chain of $N elements\""
  echo "Se U = 1"
  nj=$((N / 2))
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
    ((i < nj)) && echo "bond j$i -> j$((i + 1))"
  done
} >"$model"
echo "model: $(grep -c '^bond' "$model") bonds, $((N + 1)) elements"
time_it() { # LABEL ARGS...
  local label=$1; shift
  local t0 t1; t0=$(date +%s.%N)
  "$BGDRAW" "$model" "$@" >/dev/null
  t1=$(date +%s.%N)
  printf '%-28s %6.2f s\n' "$label" "$(echo "$t1 - $t0" | bc)"
}
time_it "check only" --check
time_it "layout + svg" -o "$dir/b.svg"
time_it "layout + svg,pdf,png,dot" -o "$dir/b.svg" -o "$dir/b.pdf" -o "$dir/b.png" -o "$dir/b.dot"
time_it "layout + svg, show all" --show all -o "$dir/b.svg"
ls -l "$dir"/b.* | awk '{print "  " $5 " bytes  " $NF}'
