#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Every examples/*.bg must pass `bgdraw FILE --check` with status 0 and no error.
# Usage: bash tests/examples_check.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: examples_check.sh PATH_TO_BGDRAW}
pass=0
fail=0
err=$(mktemp)
trap 'rm -f "$err"' EXIT
for f in examples/*.bg; do
  if "$BGDRAW" "$f" --check >/dev/null 2>"$err" && ! grep -q 'error:' "$err"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL $f"
    sed 's/^/    /' "$err"
  fi
done

# The summary stays short on a large model: a 30-stage RC ladder lists ten
# states and counts the rest.
ladder=$(mktemp --suffix=.bg)
python3 bench/gen_ladder.py 30 "$ladder"
out=$("$BGDRAW" "$ladder" --check 2>/dev/null)
rm -f "$ladder"
if echo "$out" | grep -qx 'states (30): C1.q, C2.q, C3.q, C4.q, C5.q, C6.q, C7.q, C8.q, C9.q, C10.q, ... and 20 more'; then
  pass=$((pass + 1))
else
  fail=$((fail + 1)); echo "FAIL long state list not shortened:"; echo "$out" | head -3
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
