#!/usr/bin/env bash
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
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
