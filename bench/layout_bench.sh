#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Layout stays linear (issue 31): the diagram's layout and scene
# (bg_diagram_build, default layers, default style) of a chain of 10 000
# bonds and of a reaction network with 1 000 modulating signals, each beside
# the same model at half the size; the exponent is log(t2/t1)/log 2 (1: linear).
# In-process (bench/render_time.c --build-only, compiled against BGDRAW's
# build directory), best of 3, with the layout a model of that size gets
# (above 2 000 nodes a forest is drawn as a tree on the grid, bg_grid_tree_ranks:
# both chains and both random trees, of 3 000 and 6 000 junctions, and the
# chains of 2 000 and 4 000 sections with a user state and a detector each; other graphs
# rows: the full reaction network) and, for
# the reaction networks, rows at both sizes too (the half network has 1 750
# nodes and would be laid out by dot, which is not linear); the same for a
# network whose signals join near neighbours ("nearby"); a junction of 6 000
# one-ports beside one of 3 000 (rows at both sizes, one-ports on a ring
# whose bonds grow with it: not linear, see bench/README.md), and the same
# junction of 4 000 (2 000) with every one-port modulated by one capacitor
# (a fan of signals, drawn as branches off one tree); then the length of
# the signal lines each network draws (below).
# Usage: bash bench/layout_bench.sh BGDRAW [BONDS SIGNALS]   (use a Release build)
set -eu
BGDRAW=${1:?usage: layout_bench.sh PATH_TO_BGDRAW [BONDS SIGNALS]}
NB=${2:-10000}
NS=${3:-1000}
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
build=$(cd "$(dirname "$BGDRAW")" && pwd)
libs=$(sed -e 's/.* -o test_render *//' "$build/CMakeFiles/test_render.dir/link.txt")
(cd "$build" && cc -O2 -I"$here/../src" -I"$here/../render" "$here/render_time.c" $libs -o "$dir/render_time")

time_of() { # KIND N [ENGINE] -> seconds of bg_diagram_build
  python3 "$here/gen_layout_models.py" "$1" "$2" "$dir/m.bg"
  "$dir/render_time" "$dir/m.bg" "$here/../styles" --build-only ${3:-} | awk '/layout/ {print $(NF-6)}'
}

row() { # LABEL KIND N [ENGINE]
  local t1 t2
  t1=$(time_of "$2" $(($3 / 2)) ${4:-})
  t2=$(time_of "$2" "$3" ${4:-})
  printf '%-34s %8.3f s %8.3f s   exponent %.2f\n' "$1" "$t1" "$t2" \
    "$(echo "l($t2 / $t1) / l(2)" | bc -l)"
}
printf '%-34s %10s %10s\n' "layout + scene (default layers)" "half" "full"
row "chain, $NB bonds" chain "$NB"
row "random tree, 6000 junctions" tree 6000
row "states, 4000 sections" states 4000
row "reactions, $NS signals (rows)" reactions "$NS" rows
row "nearby, $NS signals (rows)" nearby "$NS" rows
row "star, 6000 one-ports (rows)" star 6000
row "fan, 4000 signals of one source" fan 4000

# What the signals' routes draw: the total length of the signal lines in
# the SVG (bgdraw --layout rows), half and full size. The router's work per
# point of drawn route is about constant, so where the routes themselves
# grow faster than the model (signals joining far ends of the figure) the
# layout cannot be linear: its exponent is bounded below by this one.
length_of() { # KIND N -> points of signal line drawn
  python3 "$here/gen_layout_models.py" "$1" "$2" "$dir/m.bg"
  "$BGDRAW" "$dir/m.bg" --layout rows -o "$dir/m.svg"
  python3 - "$dir/m.svg" <<'PY'
import math, re, sys
total = 0.0
for m in re.finditer(r'<path class="signal(?:-branch)?" d="([^"]*)"', open(sys.argv[1]).read()):
    v = [float(x) for x in re.findall(r"-?[\d.]+(?:e-?\d+)?", m.group(1))]
    p = list(zip(v[0::2], v[1::2]))
    total += sum(math.dist(p[i], p[i + 1]) for i in range(len(p) - 1))
print(f"{total:.0f}")
PY
}
lrow() { # LABEL KIND N
  local l1 l2
  l1=$(length_of "$2" $(($3 / 2)))
  l2=$(length_of "$2" "$3")
  printf '%-34s %8s pt %8s pt   exponent %.2f\n' "$1" "$l1" "$l2" "$(echo "l($l2 / $l1) / l(2)" | bc -l)"
}
printf '%-34s %11s %11s\n' "signal lines drawn (rows)" "half" "full"
lrow "reactions, $NS signals" reactions "$NS"
lrow "nearby, $NS signals" nearby "$NS"
