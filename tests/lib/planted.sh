# SPDX-License-Identifier: BSD-3-Clause
# Planted violations for the tree checkers (include_rule.sh, symbols_rule.sh),
# sourced after `set -u`:
#     . "$(dirname "$0")/lib/planted.sh" CHECKER.py DIR...
# Sets tmp (removed at exit) and fail (0); runs the checker on the project
# once (a failure counts); plant NAME copies the DIRs into $tmp/NAME for one
# planted violation, and expect_violation NAME TEXT counts a failure unless the
# checker fails on that copy with a line containing TEXT.
command -v python3 >/dev/null || { echo "python3 not found"; exit 1; }
checker=$1
shift
planted_dirs=("$@")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
python3 "$checker" . || fail=$((fail + 1))

plant() { # plant NAME
  rm -rf "${tmp:?}/$1"; mkdir -p "$tmp/$1"
  cp -r "${planted_dirs[@]}" "$tmp/$1/"
}
expect_violation() { # expect_violation NAME TEXT
  if python3 "$checker" "$tmp/$1" >"$tmp/$1.out"; then
    echo "FAIL planted $1: the checker passed"; fail=$((fail + 1))
  elif ! grep -q "$2" "$tmp/$1.out"; then
    echo "FAIL planted $1: no message '$2'"; cat "$tmp/$1.out"; fail=$((fail + 1))
  fi
}
