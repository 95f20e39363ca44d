#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The call rule inside render/diagram (tests/diagram_calls.py) holds on the
# tree, and the checker catches violations planted in a copy: a pass calling
# a sibling pass, a helper calling the driver, and a file with no level.
# Usage: bash tests/diagram_calls.sh [PATH_TO_BGDRAW]   (from the project root)
set -u
command -v python3 >/dev/null || { echo "python3 not found"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
python3 tests/diagram_calls.py . || fail=$((fail + 1))
plant() { rm -rf "$tmp/$1"; mkdir -p "$tmp/$1/render"; cp -r render/diagram "$tmp/$1/render/"; }
expect_violation() { # NAME TEXT
  if python3 tests/diagram_calls.py "$tmp/$1" >"$tmp/$1.out"; then
    echo "FAIL planted $1: the checker passed"; fail=$((fail + 1))
  elif ! grep -q "$2" "$tmp/$1.out"; then
    echo "FAIL planted $1: no message '$2'"; cat "$tmp/$1.out"; fail=$((fail + 1))
  fi
}
plant sibling
echo 'void planted(bg_diagram *d) { bg_draw_paths(d); }' >>"$tmp/sibling/render/diagram/diagram_signals.c"
expect_violation sibling 'diagram_signals.c calls bg_draw_paths of a sibling, diagram_layers.c'
plant upward
echo 'void planted(const bg_model *m) { bg_diagram_build(m, 0, 0, 0); }' >>"$tmp/upward/render/diagram/diagram_geom.c"
expect_violation upward 'diagram_geom.c calls bg_diagram_build of a higher file, diagram.c'
plant stray
echo 'int x;' >"$tmp/stray/render/diagram/diagram_extra.c"
expect_violation stray 'diagram_extra.c: not in the call rule'
echo "diagram calls: 3 planted violations tried, $fail failures"
[ "$fail" -eq 0 ]
