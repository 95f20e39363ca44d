#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Benchmark (not a test): parameter studies (docs/study.md, issue 37).
# - SMALL runs of a small model (examples/rlc.bg, a sweep of R0 collecting
#   the capacitor voltage's peak) on 1 thread and on every core: runs per
#   second and the speed-up;
# - LARGE runs of a 1 000-state RC ladder (bench/gen_ladder.py) on 1 thread
#   and on every core;
# - the study's cost per run against a single run: one `bgdraw m.bg -o m.csv`
#   process (what a shell loop over --set would pay a run) and the study's
#   wall time per run on 1 thread;
# - memory: the peak resident size of studies of 100, 1 000 and 10 000 runs
#   keeping only the summary (--study FILE.csv), which must not grow with the
#   number of runs (each run's trajectories are freed when its quantities are
#   taken).
# Every figure is the best of RUNS (default 3) wall-clock times: the machine
# may be shared, so run it niced and when it is quiet.
# Usage: bash bench/study_bench.sh PATH_TO_BGDRAW [SMALL] [LARGE]   (from the project root)
#   defaults SMALL=1000, LARGE=100
set -eu
BGDRAW=${1:?usage: study_bench.sh PATH_TO_BGDRAW [SMALL] [LARGE]}
SMALL=${2:-1000}
LARGE=${3:-100}
RUNS=${RUNS:-3}
case $BGDRAW in */*) BGDRAW=$(cd "$(dirname "$BGDRAW")" && pwd)/$(basename "$BGDRAW") ;; esac
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cores=$(nproc)

# best wall time (s), the peak RSS (KiB) and the CPU time (user + system,
# s) of its run: "SECONDS KIB CPU"
best() {
  local b="" m=0 c=0 i
  for ((i = 0; i < RUNS; i++)); do
    /usr/bin/time -f '%e %M %U %S' -o "$tmp/time" "$@" >/dev/null 2>"$tmp/err" ||
      { echo "failed: $*" >&2; sed 's/^/  /' "$tmp/err" >&2; exit 1; }
    read -r t k u s <"$tmp/time"
    if [ -z "$b" ] || awk -v a="$t" -v b="$b" 'BEGIN { exit !(a < b) }'; then
      b=$t m=$k c=$(awk -v u="$u" -v s="$s" 'BEGIN { print u + s }')
    fi
  done
  echo "$b $m $c"
}

python3 bench/gen_ladder.py 1000 "$tmp/ladder.bg"
small=(examples/rlc.bg --sweep "R0=5:125:$SMALL" --collect C1.e:max --collect C1.e:tmax)
large=("$tmp/ladder.bg" --sweep "R0=0.5:2:$LARGE" --collect C1000.q:final)

printf '%-28s %6s %8s %10s %9s %9s %12s\n' study runs threads "wall [s]" "runs/s" "speed-up" "CPU/run [ms]"
for which in small large; do
  if [ $which = small ]; then words=("${small[@]}") n=$SMALL; else words=("${large[@]}") n=$LARGE; fi
  read -r t1 _ c1 < <(best "$BGDRAW" "${words[@]}" -j 1 --study "$tmp/one.csv")
  read -r tn _ cn < <(best "$BGDRAW" "${words[@]}" -j "$cores" --study "$tmp/all.csv")
  cmp -s "$tmp/one.csv" "$tmp/all.csv" || { echo "the tables differ between 1 and $cores threads" >&2; exit 1; }
  label=$([ $which = small ] && echo "rlc.bg (2 states)" || echo "RC ladder (1000 states)")
  awk -v l="$label" -v n="$n" -v t="$t1" -v c="$c1" \
    'BEGIN { printf "%-28s %6d %8d %10.2f %9.1f %9s %12.2f\n", l, n, 1, t, n / t, "1", 1000 * c / n }'
  awk -v l="$label" -v n="$n" -v c="$cores" -v t="$tn" -v t1="$t1" -v cpu="$cn" \
    'BEGIN { printf "%-28s %6d %8d %10.2f %9.1f %9.2f %12.2f\n", l, n, c, t, n / t, t1 / t, 1000 * cpu / n }'
  if [ $which = small ]; then
    # one process takes a few ms, under time(1)'s 10 ms resolution: the mean of 100
    s0=$(date +%s.%N)
    for ((i = 0; i < 100; i++)); do "$BGDRAW" examples/rlc.bg -o "$tmp/single.csv" >/dev/null; done
    ts=$(awk -v a="$s0" -v b="$(date +%s.%N)" 'BEGIN { print (b - a) / 100 }')
    echo
    awk -v ts="$ts" -v t="$t1" -v n="$n" 'BEGIN {
      printf "one run of rlc.bg as its own process (bgdraw rlc.bg -o rlc.csv, mean of 100): %.4f s\n", ts
      printf "a run of the study on 1 thread: %.4f s (%.1f %% of a process per run)\n\n", t / n, 100 * t / n / ts }'
  else
    read -r ts _ < <(best "$BGDRAW" "$tmp/ladder.bg" -o "$tmp/single.csv")
    awk -v ts="$ts" -v t="$t1" -v n="$n" 'BEGIN {
      printf "\none run of the ladder as its own process: %.3f s; a run of the study on 1 thread: %.3f s (%.0f %%)\n",
        ts, t / n, 100 * t / n / ts }'
  fi
done

echo
printf '%-28s %6s %14s\n' "memory (summary only)" runs "peak RSS [MiB]"
for n in 100 1000 10000; do
  read -r _ kib < <(best "$BGDRAW" examples/rlc.bg --sweep "R0=5:125:$n" --collect C1.e:max -j "$cores" \
    --study "$tmp/m.csv")
  awk -v n="$n" -v k="$kib" 'BEGIN { printf "%-28s %6d %14.1f\n", "rlc.bg", n, k / 1024 }'
done
