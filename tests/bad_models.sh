#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs bgdraw on every malformed model in tests/bad/ (and a few generated
# ones) and checks: exit status 1, each "# expect: LINE:COL: MESSAGE" line of
# the file appears in stderr as "FILE:LINE:COL: error: MESSAGE...", a caret
# line is shown, and no output file was written; "# absent: TEXT" must not
# appear (an error that is a consequence of another is suppressed).
# Usage: bash tests/bad_models.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: bad_models.sh PATH_TO_BGDRAW}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
pass=0
fail=0

# check FILE: one model against its expectations
check() {
  local file=$1 ok=1 err="$TMP/stderr" out="$TMP/x.svg"
  rm -f "$out"
  "$BGDRAW" "$file" -o "$out" 2>"$err" >/dev/null
  local rc=$?
  if [ "$rc" -ne 1 ]; then echo "FAIL $file: exit status $rc, expected 1"; ok=0; fi
  if [ -e "$out" ]; then echo "FAIL $file: an output file was written"; ok=0; fi
  if ! grep -q '^ *| .*\^$' "$err"; then echo "FAIL $file: no caret line"; ok=0; fi
  local n=0
  while IFS= read -r line; do
    line=${line%$'\r'}
    case $line in
      "# absent: "*) # a consequence of an earlier error that must not be reported
        if grep -qF -- "${line#"# absent: "}" "$err"; then
          echo "FAIL $file: reports '${line#"# absent: "}'"; ok=0
        fi
        continue ;;
      "# expect-at: "*) # a diagnostic in another file, or a note: given whole
        n=$((n + 1))
        if ! grep -qF -- "${line#"# expect-at: "}" "$err"; then
          echo "FAIL $file: missing '${line#"# expect-at: "}'"; ok=0
        fi
        continue ;;
      "# expect: "*) ;;
      *) continue ;;
    esac
    n=$((n + 1))
    local want=${line#"# expect: "}
    local pos=${want%%: *} msg=${want#*: }
    if ! grep -qF -- "$file:$pos: error: $msg" "$err"; then
      echo "FAIL $file: missing '$file:$pos: error: $msg'"; ok=0
    fi
  done <"$file"
  if [ "$n" -eq 0 ]; then echo "FAIL $file: no '# expect:' line"; ok=0; fi
  if [ $ok -eq 1 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); sed 's/^/    /' "$err"; fi
}

for f in tests/bad/*.bg; do check "$f"; done

# Generated: nesting deeper than the parser's limit (parentheses, unary minus, powers).
rep() { # rep TEXT COUNT: TEXT repeated COUNT times
  [ -n "$1" ] || return 0
  printf "%$2s" "" | sed "s/ /$1/g"
}
gen() { # gen NAME PREFIX ATOM SUFFIX COUNT COLUMN
  local s t
  s=$(rep "$2" "$5")
  t=$(rep "$4" "$5")
  { echo "# expect: 2:$6: expression nested too deeply"
    echo "param x = $s$3$t"
    printf 'Se U = x\n1 j\nR R1 = 1\nbond U -> j\nbond j -> R1\n'; } >"$TMP/$1.bg"
  check "$TMP/$1.bg"
}
gen deep_parens "(" 1 ")" 5000 211
gen deep_unary "-" 1 "" 100000 210
gen deep_power "2\\^" 1 "" 3000 411

# Generated: a flat sum of 20 000 terms is refused by length (not by a crash
# or quadratic memory), and its 40 000-character line is shown as a window
# around the caret.
{ echo "# expect: 2:4011: expression too long: more than 2000 nested operations"
  printf 'param x = 1'; rep "+1" 19999; echo
  printf 'Se U = x\n1 j\nR R1 = 1\nbond U -> j\nbond j -> R1\n'; } >"$TMP/long_sum.bg"
check "$TMP/long_sum.bg"
if ! awk 'length($0) > 200 { bad = 1 } END { exit bad }' "$TMP/stderr"; then
  echo "FAIL long_sum: a diagnostic line longer than 200 characters"; fail=$((fail + 1))
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
