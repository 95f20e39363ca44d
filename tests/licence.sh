#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The licence (issue 32): LICENSE is the BSD 3-Clause text, and every source
# file of the tree names it with an SPDX line in its first three lines (C,
# headers, Python, shell, CMake), so a file copied out keeps its terms.
# Usage: bash tests/licence.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
grep -q "^BSD 3-Clause License" LICENSE && grep -q "Neither the name of the copyright holder" LICENSE
check "LICENSE is the BSD 3-Clause licence" $?
missing=""
while IFS= read -r f; do
  case $f in tests/fuzz/corpus/*|tests/property/found/*) continue ;; esac
  case $f in
    *.c|*.h|*.py|*.sh|*.cmake|CMakeLists.txt|*/CMakeLists.txt|.ci/run) ;;
    *) continue ;;
  esac
  head -3 "$f" | grep -q "SPDX-License-Identifier: BSD-3-Clause" || missing="$missing $f"
done < <(git ls-files 2>/dev/null || find . -type f | sed 's|^\./||')
[ -z "$missing" ]; check "every source file has the SPDX line (missing:$missing)" $?
"$BGDRAW" --help >/dev/null; check "the program runs" $?
finish
