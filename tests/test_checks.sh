#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The shell tests' own trap: in `check "NAME ($(cmd))" $?` the command
# substitution in NAME runs before `$?` is expanded, so `$?` is the
# substitution's status (0) and the check passes whatever was tested. 39 such
# checks were vacuous until 2026-12-05 (two hid real faults: a C export with
# a param named __FILE__ that did not compile, a dangling link not seen as
# its target). The status must be taken first: `cs_=$?; check "NAME ($(cmd))" $cs_`.
# Usage: bash tests/test_checks.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
finder() { # FILES...: lines of the trap, as file:line
  grep -nE '(^|[^[:alnum:]_-])check ".*\$\(.*" \$\?[[:space:]]*(#.*)?$' "$@"
}
printf 'false; check "x ($(true))" $?\n' >"$tmp/trap.sh"
printf 'false; cs_=$?; check "x ($(true))" $cs_\ncheck "plain" $?\n' >"$tmp/fine.sh"
finder "$tmp/trap.sh" >/dev/null; check "the finder finds the trap" $?
! finder "$tmp/fine.sh" >/dev/null; check "the finder passes the status taken first" $?
found=$(finder $(git ls-files 'tests/*.sh' 'tests/**/*.sh' 2>/dev/null || find tests -name '*.sh'))
[ -z "$found" ]; check "no test checks \$? after a command substitution in its name: $found" $?
finish
