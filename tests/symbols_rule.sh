#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Every extern function of src/ and render/ is called from another file, and
# docs/architecture.md names every source file (tests/symbols_rule.py); the
# checker catches violations planted in a copy: a function nothing calls, a
# function only its own file calls, a source file the document does not name,
# and a path the document cites that does not exist.
# Usage: bash tests/symbols_rule.sh [PATH_TO_BGDRAW]   (from the project root)
set -u
. "$(dirname "$0")/lib/planted.sh" tests/symbols_rule.py src render include tests bench contrib docs
plant dead
printf '\nint bg_arena_unused(int x) {\n  return x + 1;\n}\n' >>"$tmp/dead/src/base/arena.c"
expect_violation dead 'src/base/arena.c: bg_arena_unused is used nowhere: delete it'
plant local
printf '\nint bg_arena_twice(int x) {\n  return 2 * x;\n}\nint bg_arena_four(int x) { return bg_arena_twice(bg_arena_twice(x)); }\n' \
  >>"$tmp/local/src/base/arena.c"
printf 'int bg_arena_four(int x);\n' >>"$tmp/local/src/base/arena.h"
printf 'static int use_four(void) { return bg_arena_four(1); }\n' >>"$tmp/local/src/base/strbuf.c"
expect_violation local 'bg_arena_twice is used only in its own file: make it static'
plant undocumented
echo 'int bg_extra_x;' >"$tmp/undocumented/src/base/extra.c"
expect_violation undocumented 'src/base/extra.c: not in docs/architecture.md'
plant stale
echo 'See `tests/nowhere/` for more.' >>"$tmp/stale/docs/architecture.md"
expect_violation stale 'cites `tests/nowhere/`, which does not exist'
echo "symbols rule: 4 planted violations tried, $fail failures"
[ "$fail" -eq 0 ]
