#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Benchmark (not a test): the diagram SVG and the PDF report of the
# mass-spring-damper chain (bench/gen_models.py chain, 5 bonds a mass) at
# 100 000 masses and below, each in a fresh process under /usr/bin/time:
# CPU seconds (user + system) and peak resident memory. Issue 34's goal at
# 100 000 masses: the SVG under 20 s and 1 GB, the report under 60 s and 2 GB.
# Usage: nice -n 19 bash bench/large_outputs.sh PATH_TO_BGDRAW [MASSES...]
#   (default 25000 50000 100000; minutes of CPU and up to 5 GB at the top size:
#   run it alone)
set -eu
bgdraw=${1:?usage: large_outputs.sh PATH_TO_BGDRAW [MASSES...]}
shift
sizes=${*:-25000 50000 100000}
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf '%-8s %-7s %9s %9s\n' masses output "CPU s" "peak MB"
for n in $sizes; do
  python3 "$here/gen_models.py" chain $((5 * n)) 0.1 >"$dir/m.bg"
  for what in svg report; do
    if [ $what = svg ]; then set -- -o "$dir/x.svg"; else set -- --report "$dir/x.pdf"; fi
    /usr/bin/time -f '%U %S %M' -o "$dir/t" "$bgdraw" "$dir/m.bg" -q "$@"
    read -r u s kb <"$dir/t"
    awk -v n="$n" -v w="$what" -v u="$u" -v s="$s" -v kb="$kb" \
      'BEGIN { printf "%-8d %-7s %9.1f %9.0f\n", n, w, u + s, kb / 1024 }'
    rm -f "$dir/x.svg" "$dir/x.pdf"
  done
done
