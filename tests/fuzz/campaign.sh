#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A long coverage-guided fuzz campaign with libFuzzer (clang, ASan + UBSan),
# one target after another, niced, each bounded in time and memory.
#
#   bash tests/fuzz/campaign.sh [SECONDS_PER_TARGET] [TARGET...]   (from the project root)
#
# TARGET: parse, equations, simulate, render, linear, import (default: all six),
# 600 s each. FORKS (default 1) worker processes per target: FORKS=2 uses both
# cores of a quiet machine.
# libFuzzer runs in fork mode (-fork=FORKS -ignore_timeouts=1 -ignore_ooms=1): a
# slow or memory-hungry input is saved and the campaign goes on, so one run
# collects every timeout instead of stopping at the first.
# Builds build-fuzz/ (clang, -DCMAKE_BUILD_TYPE=Fuzz -DBG_LIBFUZZER=ON), keeps a
# growing corpus per target in $BG_FUZZ_WORK (default /tmp/bgdraw-fuzz/<target>/),
# seeded with examples/, tests/bad/ and tests/fuzz/corpus/, and writes crashes,
# timeouts and leaks there as crash-*, timeout-*, leak-*. Each one found becomes
# a regression input in tests/fuzz/corpus/ (and a malformed model in tests/bad/
# when it is a diagnostics case). The summary line per target gives executions,
# corpus size and findings, from libFuzzer's own final statistics.
set -u
secs=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(parse equations simulate render linear import)
forks=${FORKS:-1}
total=0
root=$PWD
work=${BG_FUZZ_WORK:-/tmp/bgdraw-fuzz}
build=${BG_FUZZ_BUILD:-$root/build-fuzz}
command -v clang >/dev/null || { echo "campaign: clang is needed (apt-get install clang)"; exit 2; }
cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=Fuzz \
  -DBG_LIBFUZZER=ON >/dev/null || exit 2
nice cmake --build "$build" -j2 --target $(printf 'fuzz_%s ' "${targets[@]}") >/dev/null || exit 2
for t in "${targets[@]}"; do
  dir=$work/$t
  mkdir -p "$dir/corpus" "$dir/found"
  # Graphviz and pango keep caches for the life of the process: leaks are
  # checked on the engine targets only (valgrind covers the renderers).
  leaks=1
  [ "$t" = render ] || [ "$t" = linear ] && leaks=0 # linear draws its plots
  ASAN_OPTIONS=detect_leaks=$leaks:allocator_may_return_null=1 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  nice -n 19 "$build/fuzz_$t" "$dir/corpus" "$root/examples" "$root/tests/bad" \
    "$root/tests/fuzz/corpus" "$root/tests/data" -dict="$root/tests/fuzz/bg.dict" -max_len=8192 \
    -timeout=10 -rss_limit_mb=2048 -max_total_time="$secs" -print_final_stats=1 \
    -fork="$forks" -ignore_timeouts=1 -ignore_ooms=1 -ignore_crashes=0 \
    -artifact_prefix="$dir/found/" -close_fd_mask=3 >"$dir/log" 2>&1
  # fork mode: the parent's last status line "#N: cov: ... exec/s: S oom/timeout/crash: a/b/c"
  last=$(grep -E '^#[0-9]+: cov:' "$dir/log" | tail -1)
  execs=$(echo "$last" | sed -n 's/^#\([0-9]*\):.*/\1/p')
  speed=$(echo "$last" | sed -n 's/.*exec\/s:\{0,1\} *\([0-9]*\).*/\1/p')
  otc=$(echo "$last" | sed -n 's/.*oom\/timeout\/crash: *\([0-9\/]*\).*/\1/p')
  echo "fuzz_$t: ${execs:-?} executions in ${secs} s (${speed:-?}/s), corpus $(ls "$dir/corpus" | wc -l)," \
       "oom/timeout/crash ${otc:-?}, findings $(ls "$dir/found" | wc -l) (in $dir/found)"
  total=$((total + ${execs:-0}))
done
echo "all targets: $total executions"
