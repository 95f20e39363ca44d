# SPDX-License-Identifier: BSD-3-Clause
# The preamble the shell tests share (tests/*.sh), sourced right after `set -u`:
#     . "$(dirname "$0")/lib/preamble.sh" "$@"
# ctest runs every script from the project root with bgdraw's path as its
# argument. This sets BGDRAW (made absolute, so a test may cd), root (the
# project root), tmp (a private folder, removed at exit), the pass and fail
# counters, check NAME STATUS (counts STATUS 0 as a pass, prints FAIL NAME
# otherwise) and finish (prints the counts, exits 0 only if nothing failed).
BGDRAW=${1:?usage: bash $0 PATH_TO_BGDRAW   (from the project root)}
case $BGDRAW in /*) ;; *) BGDRAW=$PWD/$BGDRAW ;; esac
root=$PWD
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { # NAME STATUS
  if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL $1"; fi
}
finish() {
  echo "$pass passed, $fail failed"
  exit $((fail != 0))
}
