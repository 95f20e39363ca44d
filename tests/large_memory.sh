#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Memory of large outputs stays linear (issue 34): the mass-spring-damper
# chain of bench/gen_models.py at 400, 800 and 1 600 masses (2 000 to 8 000
# bonds), `-o x.svg` and `--report x.pdf`, each in a fresh process, peak
# resident memory from the kernel (getrusage of the child). What a bond adds
# between the sizes is held to a budget per bond (the fixed cost of fonts
# and libraries drops out), and the step from 800 to 1 600 masses may not
# cost more per bond than the step from 400 to 800 (plus a slack for
# malloc's rounding): a structure that grows faster than the model shows
# here long before it shows at 100 000 masses. Budgets: docs/report.md,
# "Cost", and bench/README.md, "large".
# Usage: bash tests/large_memory.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
for n in 10 500 2000; do
  python3 bench/gen_models.py chain $((5 * n)) 0.1 >"$tmp/c$n.bg"
done
peak() { # KB of the child's peak resident memory: peak ARGS...
  python3 -c 'import resource, subprocess, sys
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)' "$@"
}
# Under AddressSanitizer the peaks would carry the quarantine of freed blocks
# (256 MB by default: 310 MB for a 2 000-mass SVG); without it the sanitizer
# build's peaks are within the same budgets (measured 1.5 and 3.0 KB a bond).
grep -qa __asan_init "$BGDRAW" && # gcc links libasan.so, clang links it in
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}quarantine_size_mb=0"
for what in svg report; do
  declare -A kb=()
  for n in 10 500 2000; do
    if [ $what = svg ]; then kb[$n]=$(peak "$BGDRAW" "$tmp/c$n.bg" -q -o "$tmp/x.svg")
    else kb[$n]=$(peak "$BGDRAW" "$tmp/c$n.bg" -q --report "$tmp/x.pdf"); fi
  done
  # measured 2.4 and 6.9 KB a bond at 2 000 masses (2026-12-05, compact scene items
  # and path slots); the budgets are those plus a quarter
  budget=$([ $what = svg ] && echo 3.0 || echo 8.5)
  verdict=$(python3 -c 'import sys
tiny, a, b, budget = (float(x) for x in sys.argv[1:])
low, high = (a - tiny) / (5 * 500), (b - tiny) / (5 * 2000)  # KB a bond above the fixed cost
ok = high <= budget and high <= 1.25 * low + 0.5
print("ok" if ok else "FAIL", "%.2f %.2f" % (low, high))' "${kb[10]}" "${kb[500]}" "${kb[2000]}" "$budget")
  echo "large_memory: $what peaks ${kb[10]} ${kb[500]} ${kb[2000]} KB; KB a bond above the 10-mass run (500, 2 000 masses): ${verdict#* } (budget $budget)"
  [ "${verdict%% *}" = ok ]; check "$what: memory linear in the bonds, within $budget KB a bond" $?
  unset kb
done
echo "large_memory: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
