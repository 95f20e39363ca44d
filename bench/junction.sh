#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# --check on N stores sharing one 0-junction (one integral store, N - 1
# dependent ones): the Jacobian pattern's colouring and the signal flow
# graph's parallel-edge test, both once quadratic in N (issue 28).
# usage: bench/junction.sh [BGDRAW] [N ...]   (default build/bgdraw; 20000 50000 100000)
set -eu
B=${1:-build/bgdraw}
shift || true
Ns=${*:-20000 50000 100000}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '| stores | --check CPU s | max RSS MB |\n|---:|---:|---:|\n'
for n in $Ns; do
  python3 - "$n" > "$tmp/j.bg" <<'P'
import sys
n = int(sys.argv[1])
print("\n".join(["model junction", "Sf F = 1", "0 j"] + [f"C C{i} = 1" for i in range(1, n + 1)]
                + ["bond F -> j"] + [f"bond j -> C{i}" for i in range(1, n + 1)]))
P
  /usr/bin/time -f "%U %S %M" -o "$tmp/t" "$B" "$tmp/j.bg" --check > /dev/null
  read -r u s m < "$tmp/t"
  printf '| %d | %.2f | %d |\n' "$n" "$(echo "$u + $s" | bc)" $((m / 1024))
done
