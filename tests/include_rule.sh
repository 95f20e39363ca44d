#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The stage dependency rule (tests/include_rule.py) holds on the tree, and the
# checker catches violations planted in a copy: an include of a higher stage, a
# bare include of another folder's header, another stage's internal header
# (*_int.h), an engine stage's header that is not its front door, an internal
# header not named *_int.h, a stage without its front door, and a folder that
# is not a stage.
# Usage: bash tests/include_rule.sh [PATH_TO_BGDRAW]   (from the project root)
set -u
. "$(dirname "$0")/lib/planted.sh" tests/include_rule.py CMakeLists.txt src render
plant upward
sed -i '1i #include "equations/eqsys.h"' "$tmp/upward/src/base/arena.c"
expect_violation upward 'stage base includes "equations/eqsys.h" of the higher stage equations'
plant render_in_engine
sed -i '1i #include "diagram/render.h"' "$tmp/render_in_engine/src/json/json.c"
expect_violation render_in_engine 'stage json includes "diagram/render.h"'
plant bare
sed -i '1i #include "model.h"' "$tmp/bare/src/analysis/paths.c"
expect_violation bare '"model.h" is not in analysis/'
plant internal
sed -i '1i #include "causality/causality_int.h"' "$tmp/internal/src/analysis/paths.c"
expect_violation internal '"causality/causality_int.h" is internal to stage causality'
plant side_door
sed -i '1i #include "equations/eqsys.h"' "$tmp/side_door/src/simulate/csv.c"
expect_violation side_door '"equations/eqsys.h" is not the front door of stage equations'
plant unnamed_internal
echo '/* x */' >"$tmp/unnamed_internal/src/linear/linear_helpers.h"
expect_violation unnamed_internal 'linear_helpers.h: not part of the front door linear/linear.h'
plant no_door
mv "$tmp/no_door/src/sym/sym.h" "$tmp/no_door/src/sym/sym_api.h"
expect_violation no_door 'src/sym/: no front door sym.h'
plant stray
mkdir "$tmp/stray/src/extra" && echo 'int x;' >"$tmp/stray/src/extra/x.c"
expect_violation stray 'src/extra/: not a stage'
echo "include rule: 8 planted violations tried, $fail failures"
[ "$fail" -eq 0 ]
