#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# The HTML report's size and time against the model's size (issue 36: a
# 10 000-bond model's report under 20 MB and under 10 s). Three generated
# shapes of about N bonds each (bench/gen_models.py: a mass-spring-damper
# chain, an RC ladder, a grid of junctions, each with a simulate block),
# at N/10 and N bonds: wall time of `bgdraw MODEL --report m.html` (best of
# 2), the page's bytes, its largest section, and the bytes per bond. Exits 1
# when a model of N bonds misses a target.
# Usage: bash bench/html_report.sh BGDRAW [N]   (N default 10000; a Release build)
set -eu
BGDRAW=${1:?usage: html_report.sh PATH_TO_BGDRAW [N]}
N=${2:-10000}
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
printf '%-7s %7s %8s %10s %9s %-24s\n' shape bonds seconds bytes B/bond "largest section"
for shape in chain ladder grid; do
  for n in $((N / 10)) "$N"; do
    python3 "$here/gen_models.py" "$shape" "$n" 1 >"$dir/m.bg"
    bonds=$(grep -c '^bond ' "$dir/m.bg")
    best=
    for _ in 1 2; do
      s=$(date +%s.%N)
      "$BGDRAW" "$dir/m.bg" --report "$dir/m.html" 2>/dev/null || true
      t=$(echo "$(date +%s.%N) - $s" | bc)
      if [ -z "$best" ] || [ "$(echo "$t < $best" | bc)" = 1 ]; then best=$t; fi
    done
    bytes=$(stat -c %s "$dir/m.html")
    largest=$(python3 - "$dir/m.html" <<'PY'
import re, sys
h = open(sys.argv[1], encoding="utf-8").read()
s = [(m.start(), m.group(1)) for m in re.finditer(r'<section id="([^"]+)"', h)] + [(len(h), "")]
print(max((s[i + 1][0] - s[i][0], s[i][1]) for i in range(len(s) - 1))[1])
PY
)
    printf '%-7s %7d %8.2f %10d %9d %-24s\n' "$shape" "$bonds" "$best" "$bytes" $((bytes / bonds)) "$largest"
    if [ "$n" = "$N" ] && { [ "$(echo "$best > 10" | bc)" = 1 ] || [ "$bytes" -gt 20000000 ]; }; then
      echo "  over the target (10 s, 20 MB)"
      status=1
    fi
  done
done
exit $status
