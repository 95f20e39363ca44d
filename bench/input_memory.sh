#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Memory per input byte (issue 22): peak resident memory of bgdraw on RC
# ladders of growing size and on a file of comments, and the slope between
# the sizes (the fixed cost of the libraries cancels out).
#   bash bench/input_memory.sh [BGDRAW]     (from the project root; default build/bgdraw)
set -u
BGDRAW=${1:-build/bgdraw}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
peak() { # peak RSS in bytes of one run (python's view of the child)
  python3 - "$@" <<'PY'
import resource, subprocess, sys
subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024)
PY
}
row() { # LABEL FILE ARGS...
  local label=$1 f=$2
  shift 2
  local bytes rss
  bytes=$(stat -c %s "$f")
  rss=$(peak "$BGDRAW" "$f" "$@")
  echo "$label $bytes $rss"
}
printf '%-28s %12s %12s %10s\n' input bytes peak_rss B/B_slope
for what in "--check"; do
  prev=""
  for n in 2000 8000 32000; do
    python3 bench/gen_ladder.py $n > "$tmp/l$n.bg"
    set -- $(row "ladder$n $what" "$tmp/l$n.bg" $what)
    slope=""
    [ -n "$prev" ] && slope=$(python3 -c "print(f'{($4 - $prev_rss) / ($3 - $prev_bytes):.1f}')" 2>/dev/null)
    printf '%-28s %12s %12s %10s\n' "ladder $n, ${what%% *}" "$3" "$4" "$slope"
    prev=1 prev_bytes=$3 prev_rss=$4
  done
done
# A file of comments: the reading and lexing alone.
python3 - "$tmp/comments.bg" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("model c\nSe U = 1\nR R1 = 1\nbond U -> R1\n")
    f.write(("# " + "x" * 77 + "\n") * 400000)  # 32 MB
PY
set -- $(row comments "$tmp/comments.bg" --check)
printf '%-28s %12s %12s %10s\n' "32 MB of comments, --check" "$2" "$3" \
  "$(python3 -c "print(f'{$3 / $2:.2f}')")"
