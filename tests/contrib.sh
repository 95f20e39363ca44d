#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The documentation-build integrations in contrib/ (docs/integrations.md), each
# run with its tool (tools/deps.sh installs python3-sphinx and pandoc): the
# Sphinx directive (file and inline models, options, a bad model is a warning),
# the pandoc Lua filter (```bgdraw blocks in HTML), the Makefile example
# (figures rebuilt when a table CSV changes).
# Usage: bash tests/contrib.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=$(cd "$(dirname "${1:?usage: contrib.sh PATH_TO_BGDRAW}")" && pwd)/$(basename "$1")
ROOT=$PWD
pass=0
fail=0
tmp=$(mktemp -d)
trap "rm -rf $tmp" EXIT; [ -n "${KEEP:-}" ] && trap - EXIT && echo "$tmp"
check() { # check NAME STATUS
  if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL $1"; fi
}
need() { command -v "$1" >/dev/null || { echo "FAIL $1 is not installed (bash tools/deps.sh)"; fail=$((fail + 1)); return 1; }; }
"$BGDRAW" examples/rlc.bg -q --show paths --style print -T svg >"$tmp/rlc_paths.svg"

# ---- Sphinx
if need sphinx-build; then
  mkdir -p "$tmp/sph/models"
  cp examples/rlc.bg "$tmp/sph/models/rlc.bg"
  cat >"$tmp/sph/conf.py" <<EOF
import sys
sys.path.insert(0, "$ROOT/contrib/sphinx")
extensions = ["bgdraw_sphinx"]
bgdraw_command = "$BGDRAW"
EOF
  cat >"$tmp/sph/index.rst" <<'EOF'
Figures
=======

.. bgdraw:: models/rlc.bg
   :show: paths
   :style: print

.. bgdraw::

   Se Usrc = 1
   1 j
   R Rload = 2
   bond U -> j
   bond j -> Rload
EOF
  sphinx-build -q -b html "$tmp/sph" "$tmp/sph/_build" 2>"$tmp/sph.err"; st=$?
  check "sphinx-build with the directive (got $st)" $st
  html="$tmp/sph/_build/index.html"
  python3 - "$html" "$tmp/rlc_paths.svg" <<'PY'; check "sphinx: the file model's SVG is inline, as bgdraw -T svg draws it" $?
import sys
html, svg = open(sys.argv[1]).read(), open(sys.argv[2]).read()
svg = svg[svg.index("<svg"):]
assert svg in html, "inline svg missing"
PY
  grep -q "undefined name 'U'" "$tmp/sph.err" && grep -q "<stdin>:4:6: error" "$tmp/sph.err"
  check "sphinx: a bad inline model is a warning with bgdraw's diagnostic" $?
  sphinx-build -q -W -b html "$tmp/sph" "$tmp/sph/_b2" 2>/dev/null
  check "sphinx -W: the bad model fails the build" $(($? == 0))
  sed -i 's/bond U -> j/bond Usrc -> j/' "$tmp/sph/index.rst"
  sphinx-build -q -W -b html "$tmp/sph" "$tmp/sph/_b3" 2>"$tmp/sph.err"; st=$?
  check "sphinx -W: fixed model builds (got $st)" $st
  grep -q 'class="bond b2"' "$tmp/sph/_b3/index.html" && grep -q '>R : Rload<' "$tmp/sph/_b3/index.html"
  check "sphinx: inline model drawn (bond 2, searchable names)" $?
fi

# ---- pandoc
if need pandoc; then
  cat >"$tmp/doc.md" <<'EOF'
# Figures

```{.bgdraw show=paths style=print}
EOF
  grep -v '^#' examples/rlc.bg >>"$tmp/doc.md"
  echo '```' >>"$tmp/doc.md"
  BGDRAW="$BGDRAW" pandoc "$tmp/doc.md" --lua-filter contrib/pandoc/bgdraw.lua -t html -o "$tmp/doc.html" 2>"$tmp/pd.err"; st=$?
  check "pandoc with the Lua filter (got $st)" $st
  grep -v '^#' examples/rlc.bg | "$BGDRAW" -q --show paths --style print -T svg >"$tmp/pd_want.svg"
  python3 - "$tmp/doc.html" "$tmp/pd_want.svg" <<'PY'; check "pandoc: the block became bgdraw's inline SVG" $?
import sys
html, svg = open(sys.argv[1]).read(), open(sys.argv[2]).read()
assert svg[svg.index("<svg"):].strip() in html
assert "```" not in html and "bond U" not in html
PY
  printf '```bgdraw\nSe U = 1\nbond U -> X\n```\n' >"$tmp/bad.md"
  BGDRAW="$BGDRAW" pandoc "$tmp/bad.md" --lua-filter contrib/pandoc/bgdraw.lua -t html -o "$tmp/bad.html" 2>"$tmp/pd.err"
  check "pandoc: a bad model stops the conversion" $(($? == 0))
  grep -q "undefined name 'X'" "$tmp/pd.err"; check "pandoc: bgdraw's diagnostic shown" $?
fi

# ---- Makefile example
if need make; then
  mkdir -p "$tmp/mk/models"
  cp contrib/Makefile.example "$tmp/mk/Makefile"
  printf '0, 1\n10, 1\n' >"$tmp/mk/models/u.csv"
  cat >"$tmp/mk/models/tab.bg" <<'EOF'
Se U = table(t, "u.csv")
1 j
R R1 = 1
C C1 = 1
bond U -> j
bond j -> R1
bond j -> C1
EOF
  cp examples/rlc.bg "$tmp/mk/models/rlc.bg"
  make -s -C "$tmp/mk" BGDRAW="$BGDRAW" >/dev/null 2>&1; st=$?
  check "make: the figures are built (got $st)" $st
  [ -s "$tmp/mk/figures/tab.svg" ] && [ -s "$tmp/mk/figures/rlc.svg" ]; check "make: both figures" $?
  make -s -q -C "$tmp/mk" BGDRAW="$BGDRAW"; check "make: up to date after the build" $?
  sleep 1; touch "$tmp/mk/models/u.csv"
  make -s -q -C "$tmp/mk" BGDRAW="$BGDRAW" figures/tab.svg; check "make: the table CSV makes tab.svg out of date" $(($? != 1))
  make -s -q -C "$tmp/mk" BGDRAW="$BGDRAW" figures/rlc.svg; check "make: rlc.svg stays up to date" $?
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
